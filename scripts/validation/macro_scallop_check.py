#!/usr/bin/python3
"""The macro-scallop's check (ctest validation_macro_scallop).

    python3 scripts/validation/macro_scallop_check.py NEWTONIAN [THICKENING]
        [--label NAME] [--max-newtonian-drift PERCENT] [--min-advantage R]

Reads the head's track (particle_0.dat) of the runs' output folders and,
over each completed 4 s cycle, requires in the Newtonian oil a net
displacement D of at most PERCENT of the cycle's largest excursion
(Purcell's scallop theorem: zero). With a shear-thickening run as well, it
prints that run's D of the same cycles and, given --min-advantage R,
requires it forward and at least R times the Newtonian |D|. Prints D, D/l
and the excursion of each cycle; the exit status is the check's.
"""
import argparse
import sys

from macro_scallop import LENGTH, cycles, head_track


def describe(name, k, d, excursion):
    return (f"cycle {k}: {name} D = {1e3 * d:+.4f} mm (D/l = {d / LENGTH:+.5f}, "
            f"{100 * abs(d) / excursion:.2f} % of its {1e3 * excursion:.2f} mm excursion)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("newtonian")
    parser.add_argument("thickening", nargs="?")
    parser.add_argument("--label", default="macro-scallop")
    parser.add_argument("--max-newtonian-drift", type=float, default=1.0)
    parser.add_argument("--min-advantage", type=float)
    args = parser.parse_args()

    newtonian = cycles(*head_track(args.newtonian))
    thickening = cycles(*head_track(args.thickening)) if args.thickening else []
    failures = []
    if not newtonian:
        failures.append("the Newtonian run completed no cycle")
    for k, d, excursion in newtonian:
        print(describe("Newtonian", k, d, excursion))
        drift = 100 * abs(d) / excursion
        if drift > args.max_newtonian_drift:
            failures.append(f"cycle {k}: the Newtonian swimmer moved {drift:.2f} % "
                            f"of its excursion, more than {args.max_newtonian_drift} %")
    for (k, d_t, e_t), (_, d_n, _) in zip(thickening, newtonian):
        print(describe("shear-thickening", k, d_t, e_t))
        if args.min_advantage is not None and d_t <= args.min_advantage * abs(d_n):
            failures.append(f"cycle {k}: the shear-thickening D = {1e3 * d_t:+.4f} mm "
                            f"is not {args.min_advantage} times the Newtonian "
                            f"|D| = {1e3 * abs(d_n):.4f} mm")
    for f in failures:
        print(f"{args.label}: FAILED: {f}")
    if not failures:
        print(f"{args.label}: OK")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
