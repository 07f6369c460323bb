#!/usr/bin/python3
"""Vortex shedding behind the cylinder of the DFG channel at Re = 100
(prm/cylinder-in-channel): the Strouhal number of the lift's oscillation
against the DFG 2D-2 benchmark's (Schaefer & Turek 1996: St = 0.2950 ..
0.3050, we take its centre 0.300).

    scripts/validation/shedding.py RUN [--after T] [--max-error PERCENT]

reads RUN/flow.dat, finds the times at which c_L crosses its mean upwards
after t = T (default: the second half of the run; linear interpolation
between steps), and prints the lift's amplitude, the mean drag and the
Strouhal number St = D / (U_mean period) with D = 0.1 m and U_mean = 1 m/s
(the case's reference values). With --max-error it exits with status 1
unless the lift oscillates (at least two full periods after T) with St
within that many percent of 0.300.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from particulate_output import read_table  # noqa: E402

DFG_STROUHAL = 0.300
DIAMETER = 0.1
MEAN_VELOCITY = 1.0


def upward_crossings(t, signal):
    """Times at which signal crosses zero upwards, linearly interpolated."""
    below = signal[:-1] < 0
    above = signal[1:] >= 0
    k = np.flatnonzero(below & above)
    return t[k] - signal[k] * (t[k + 1] - t[k]) / (signal[k + 1] - signal[k])


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--after", type=float)
    parser.add_argument("--max-error", type=float, metavar="PERCENT")
    parser.add_argument("--label", help="the run's name (ignored; for the test driver)")
    args = parser.parse_args()

    names, data = read_table(os.path.join(args.run, "flow.dat"))
    t, c_d, c_l = (data[:, names.index(n)] for n in ("time", "c_D", "c_L"))
    after = 0.5 * t[-1] if args.after is None else args.after
    late = t >= after
    crossings = upward_crossings(t[late], c_l[late] - c_l[late].mean())
    print(f"{args.run}: t = {after:.3g} .. {t[-1]:.3g} s, mean c_D = {c_d[late].mean():.4f}, "
          f"c_L from {c_l[late].min():.4f} to {c_l[late].max():.4f}")
    if len(crossings) < 3:
        print(f"FAILED: the lift crosses its mean upwards {len(crossings)} times after "
              f"t = {after:.3g} s; no shedding to measure")
        sys.exit(1 if args.max_error is not None else 0)
    period = np.diff(crossings).mean()
    strouhal = DIAMETER / (MEAN_VELOCITY * period)
    error = 100 * (strouhal / DFG_STROUHAL - 1)
    print(f"  {len(crossings) - 1} periods of {period:.4f} s (from {np.diff(crossings).min():.4f} "
          f"to {np.diff(crossings).max():.4f}): St = {strouhal:.4f}, {error:+.1f} % against "
          f"the DFG 2D-2 {DFG_STROUHAL}")
    if args.max_error is not None and abs(error) > args.max_error:
        print(f"FAILED: St {strouhal:.4f} is more than {args.max_error} % from {DFG_STROUHAL}")
        sys.exit(1)


if __name__ == "__main__":
    main()
