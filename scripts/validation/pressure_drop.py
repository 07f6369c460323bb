#!/usr/bin/python3
"""Check the steady pressure drop of runs against a closed form.

    scripts/validation/pressure_drop.py FOLDER... --expect G --max-error P

reads each FOLDER's flow.dat (the `delta_p` column, last row) and fails,
naming the run, when it differs from G by more than P percent. For the plane
Poiseuille flow of prm/generalized-newtonian the pressure drop over the
channel's length 1 equals the gradient G = 0.5 that the closed-form profile
at the inflow and the outflow carries (doc/validation/generalized-newtonian.md).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from particulate_output import read_table  # noqa: E402


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--expect", type=float, required=True)
    parser.add_argument("--max-error", type=float, required=True, help="percent")
    parser.add_argument("--label", help="the last run's name (ignored; for the test driver)")
    args = parser.parse_args()
    failures = []
    for folder in args.folders:
        names, rows = read_table(os.path.join(folder, "flow.dat"))
        delta_p = rows[-1, names.index("delta_p")]
        error = 100 * (delta_p / args.expect - 1)
        print(f"{folder}: delta_p = {delta_p:.6g} against {args.expect:g}: {error:+.3f} %")
        if abs(error) > args.max_error:
            failures.append(f"{folder}: {error:+.3f} %, beyond {args.max_error:g} %")
    if failures:
        sys.exit("FAILED: " + "; ".join(failures))


if __name__ == "__main__":
    main()
