#!/usr/bin/python3
"""Drag and lift of the oscillating cylinder (thesis §6.3) from several runs.

Usage:
    oscillating_cylinder.py LABEL=PATH [LABEL=PATH ...] [--doc DOC_DIR]
                            [--name NAME] [--max-peak-error P]
                            [--max-tv-ratio R]

PATH is either the output folder of a `particulate` run of
prm/oscillating-cylinder/*.prm (its particle_0.dat holds the force F_x, F_y
per unit depth in 2D, on the whole cylinder of a 3D slab run, which is
divided by the cylinder's 'Length' read from the folder's
used_parameters.prm) or a series file with the columns time, c_d, c_l: the
forces.dat of validation_oscillating_cylinder_body_fitted, or a committed
series doc/validation/oscillating-cylinder-*.dat (the last comment line
before the numbers names the columns; a line '# method: fbm' marks the
series of an FBM run, any other file is body-fitted). The first
body-fitted run given is the reference of the total-variation ratio.

Prints, per run and per period of T = 4 s, the drag extrema beside the
published +3.24 / -3.26 (Wan & Turek), raw and of the curve averaged over
0.1 s (spikes of single steps do not count), the largest |c_l|, and the total
variation of c_d over the period (how oscillatory the curve is); then, per
period, c_d split by least squares into its parts against the cylinder's
velocity and against its acceleration (where the added mass shows). With
--doc writes DOC_DIR/NAME-drag.png and NAME-lift.png (NAME defaults to
oscillating-cylinder). --series FILE writes time, c_d and c_l of the last
run given, the series this script reads back (the committed
doc/validation/oscillating-cylinder-<run>.dat); --until T uses every run up
to time T only.

The checks (exit status 1 if one fails): with --max-peak-error, every
complete period of every run that is not body-fitted has the extrema of its
0.1 s average within P % of those of the body-fitted reference's same
period; with --max-tv-ratio, its TV at most R times the reference's.
"""
import argparse
import os
import sys

import matplotlib
import numpy

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from particulate_output import read_parameters  # noqa: E402

A, F, D, RHO = 0.25, 0.25, 0.1, 1.0
U = 2 * 3.141592653589793 * F * A
PERIOD = 1 / F
PUBLISHED_MAX, PUBLISHED_MIN = 3.24, -3.26


def read_table(path):
    """The columns of a series, by the names in the last comment line
    before the numbers."""
    header, rows = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if not rows:
                    header = line.lstrip("#").split()
            elif line.strip():
                rows.append(list(map(float, line.split())))
    return {name: [r[i] for r in rows] for i, name in enumerate(header)}


def is_fbm_series(path):
    """Whether a series file says it is that of an FBM run."""
    with open(path) as f:
        return any(line.split() == ["#", "method:", "fbm"] for line in f
                   if line.startswith("#"))


def span_of(folder):
    """The cylinder's length along z of a 3D run (the 'Length' of its
    shape: the force is per this span), 1 for a 2D run (the force is per
    unit depth already)."""
    values = read_parameters(folder)
    if values.get("Simulation/Dimension") != "3":
        return 1.0
    lengths = [float(value) for key, value in values.items()
               if key.startswith("Particles/Shape ") and key.endswith("/Length")
               and value and float(value) > 0]
    if len(lengths) != 1:
        sys.exit(f"{folder}: expected one shape with a 'Length' (the "
                 f"cylinder's span), found {len(lengths)}")
    return lengths[0]


def coefficients(path):
    """(t, c_d, c_l, body_fitted) of one run."""
    if os.path.isdir(path):
        table = read_table(os.path.join(path, "particle_0.dat"))
        scale = 2 / (RHO * U * U * D * span_of(path))
        return (table["time"], [scale * f for f in table["F_x"]],
                [scale * f for f in table["F_y"]], False)
    table = read_table(path)
    return table["time"], table["c_d"], table["c_l"], not is_fbm_series(path)


def smoothed(t, values, width=0.1):
    """Centred moving average over `width` seconds: the curve without its
    step-to-step oscillations, whose extrema are the peaks proper."""
    out = []
    j0 = j1 = 0
    for i, s in enumerate(t):
        while t[j0] < s - width / 2:
            j0 += 1
        while j1 + 1 < len(t) and t[j1 + 1] <= s + width / 2:
            j1 += 1
        window = values[j0:j1 + 1]
        out.append(sum(window) / len(window))
    return out


def per_period(t, c_d, c_l):
    """Per complete (or the last, partial) period: extrema (raw and of the
    0.1 s moving average), |c_l|, TV."""
    out = []
    c_d_smooth = smoothed(t, c_d)
    k = 0
    while k * PERIOD < t[-1] - 1e-9:
        idx = [i for i, s in enumerate(t)
               if k * PERIOD < s <= (k + 1) * PERIOD + 1e-9]
        # the first steps of the impulsive start are not part of the curve
        if k == 0:
            idx = [i for i in idx if t[i] > 0.1]
        if len(idx) > 2:
            d = [c_d[i] for i in idx]
            m = [c_d_smooth[i] for i in idx]
            tv = sum(abs(d[j + 1] - d[j]) for j in range(len(d) - 1))
            out.append(dict(period=k + 1, end=t[idx[-1]], max=max(d),
                            min=min(d), smooth_max=max(m), smooth_min=min(m),
                            lift=max(abs(c_l[i]) for i in idx), tv=tv))
        k += 1
    return out


def until(end, t, c_d, c_l):
    """The series up to time `end`."""
    n = sum(1 for s in t if s <= end + 1e-9)
    return list(t[:n]), list(c_d[:n]), list(c_l[:n])


def phase_parts(t, c_d):
    """Per period, the least-squares fit c_d = -c_u cos(w t) + c_a sin(w t):
    c_u the part against the cylinder's velocity U cos(w t), c_a the part
    against its acceleration -A w^2 sin(w t) (the added mass and the
    history force), and the RMS of what the fit leaves. The first 0.5 s
    (the impulsive start) are left out."""
    w = 2 * 3.141592653589793 * F
    out = []
    k = 0
    while k * PERIOD < t[-1] - 1e-9:
        lo = max(k * PERIOD, 0.5)
        idx = [i for i, s in enumerate(t) if lo < s <= (k + 1) * PERIOD + 1e-9]
        if len(idx) > 10:
            ts = numpy.array([t[i] for i in idx])
            basis = numpy.c_[-numpy.cos(w * ts), numpy.sin(w * ts)]
            values = numpy.array([c_d[i] for i in idx])
            fit = numpy.linalg.lstsq(basis, values, rcond=None)[0]
            rest = values - basis @ fit
            out.append(dict(period=k + 1, velocity=fit[0], acceleration=fit[1],
                            rest=float(numpy.sqrt(numpy.mean(rest ** 2)))))
        k += 1
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="+", help="LABEL=PATH")
    parser.add_argument("--doc", help="folder for the figures")
    parser.add_argument("--name", default="oscillating-cylinder",
                        help="file name stem of the figures")
    parser.add_argument("--max-peak-error", type=float, default=None,
                        help="bound [%%] on the 0.1 s averaged extrema against "
                        "the body-fitted reference's")
    parser.add_argument("--max-tv-ratio", type=float, default=None,
                        help="bound on TV(c_d) / the body-fitted reference's")
    parser.add_argument("--reference", default=None,
                        help="the body-fitted reference's forces.dat (the same "
                        "as giving it first among the runs)")
    parser.add_argument("--label", default=None,
                        help="the label of a single run given as a folder "
                        "(as the validation tests pass it)")
    parser.add_argument("--until", type=float, default=None,
                        help="use each run up to this time [s] only")
    parser.add_argument("--series", default=None,
                        help="write time, c_d, c_l of the last run to this file")
    args = parser.parse_args()

    runs = []
    if args.reference:
        runs.append(("body-fitted", args.reference)
                    + coefficients(args.reference))
    for item in args.runs:
        label, path = (item.split("=", 1) if "=" in item
                       else (args.label or os.path.basename(item), item))
        runs.append((label, path) + coefficients(path))
    if args.until is not None:
        runs = [(label, path) + until(args.until, t, c_d, c_l) + (fitted,)
                for label, path, t, c_d, c_l, fitted in runs]
    reference = {}
    for label, _, t, c_d, c_l, fitted in runs:
        if fitted and not reference:
            reference = {p["period"]: p for p in per_period(t, c_d, c_l)}
    reference_tv = {k: p["tv"] for k, p in reference.items()}

    print("| run | period (until t) | max c_d (pub. +3.24) | min c_d "
          "(pub. -3.26) | 0.1 s average: max / min | max abs c_l | TV(c_d) "
          "| TV / body-fitted |")
    print("|---|---|---|---|---|---|---|---|")
    for label, _, t, c_d, c_l, _ in runs:
        for p in per_period(t, c_d, c_l):
            ratio = (p["tv"] / reference_tv[p["period"]]
                     if p["period"] in reference_tv else float("nan"))
            print(f"| {label} | {p['period']} ({p['end']:.2f} s) | "
                  f"{p['max']:+.3f} ({100 * (p['max'] / PUBLISHED_MAX - 1):+.1f} %) | "
                  f"{p['min']:+.3f} ({100 * (p['min'] / PUBLISHED_MIN - 1):+.1f} %) | "
                  f"{p['smooth_max']:+.3f} ({100 * (p['smooth_max'] / PUBLISHED_MAX - 1):+.1f} %) / "
                  f"{p['smooth_min']:+.3f} ({100 * (p['smooth_min'] / PUBLISHED_MIN - 1):+.1f} %) | "
                  f"{p['lift']:.3f} | {p['tv']:.2f} | {ratio:.2f} |")

    print()
    print("| run | period | c_d against the velocity | against the acceleration "
          "| RMS rest |")
    print("|---|---|---|---|---|")
    for label, _, t, c_d, _, _ in runs:
        for p in phase_parts(t, c_d):
            print(f"| {label} | {p['period']} | {p['velocity']:.3f} | "
                  f"{p['acceleration']:.3f} | {p['rest']:.3f} |")

    failures = check_against_reference(runs, reference, args)

    if args.series:
        label, path, t, c_d, c_l, fitted = runs[-1]
        with open(args.series, "w") as f:
            f.write(f"# oscillating cylinder, {label}: the forces of {path}\n"
                    "# columns: time [s]; c_d = 2 F_x / (rho U^2 D L), c_l = "
                    "2 F_y / (rho U^2 D L), L = 1 in 2D, the cylinder's "
                    "'Length' in 3D\n")
            if not fitted:
                f.write("# method: fbm\n")
            f.write("# time c_d c_l\n")
            for row in zip(t, c_d, c_l):
                f.write("%.12g %.12g %.12g\n" % row)
        print(f"wrote {args.series}")

    if args.doc:
        os.makedirs(args.doc, exist_ok=True)
        for name, column, ylabel in (("drag", 3, "c_d"), ("lift", 4, "c_l")):
            fig, ax = plt.subplots(figsize=(9, 4))
            for run in runs:
                ax.plot(run[2], run[column], lw=0.9, label=run[0])
            if name == "drag":
                for v in (PUBLISHED_MAX, PUBLISHED_MIN):
                    ax.axhline(v, color="k", ls=":", lw=0.8)
                ax.set_ylim(-5, 5)
            else:
                ax.set_ylim(-0.3, 0.3)
            ax.set_xlabel("t [s]")
            ax.set_ylabel(ylabel)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=8)
            ax.set_title(f"Oscillating cylinder: {ylabel} "
                         "(dotted: published extrema, Wan & Turek)")
            fig.tight_layout()
            fig.savefig(os.path.join(args.doc,
                                     f"{args.name}-{name}.png"),
                        dpi=120)
            plt.close(fig)
    if failures:
        print("\n".join(failures))
        sys.exit(1)


def check_against_reference(runs, reference, args):
    """The failed checks of --max-peak-error and --max-tv-ratio, as lines."""
    if args.max_peak_error is None and args.max_tv_ratio is None:
        return []
    if not reference:
        sys.exit("the checks need a body-fitted reference run (its forces.dat)")
    failures, checked = [], 0
    for label, _, t, c_d, c_l, fitted in runs:
        if fitted:
            continue
        for p in per_period(t, c_d, c_l):
            ref = reference.get(p["period"])
            if ref is None or p["end"] < p["period"] * PERIOD - 1e-6:
                continue  # an incomplete period, or one the reference lacks
            checked += 1
            for key in ("smooth_max", "smooth_min"):
                error = 100 * abs(p[key] / ref[key] - 1)
                ok = args.max_peak_error is None or error <= args.max_peak_error
                print(f"{label}, period {p['period']}: {key} {p[key]:+.3f} against "
                      f"{ref[key]:+.3f}, {error:.1f} % {'ok' if ok else 'FAILED'}")
                if not ok:
                    failures.append(f"{label}: {key} of period {p['period']} "
                                    f"{error:.1f} % off the body-fitted one")
            ratio = p["tv"] / ref["tv"]
            ok = args.max_tv_ratio is None or ratio <= args.max_tv_ratio
            print(f"{label}, period {p['period']}: TV ratio {ratio:.2f} "
                  f"{'ok' if ok else 'FAILED'}")
            if not ok:
                failures.append(f"{label}: TV of period {p['period']} is "
                                f"{ratio:.2f} times the body-fitted one")
    if checked == 0:
        failures.append("no complete period to check")
    return failures


if __name__ == "__main__":
    main()
