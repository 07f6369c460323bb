#!/usr/bin/python3
"""Drag of ten Cate E4's sphere held fixed in a uniform stream
(prm/sphere-drag/fixed-sphere.prm) and translating through fluid at rest
(moving-sphere.prm, moving-sphere-carried.prm), from the output folders of
scripts/validation/sphere_drag.sh.

    scripts/validation/sphere_drag.py output/fixed-sphere-r* output/moving-sphere-r*
        [--doc doc/validation] [--plot-tags TAG ...]

Both flows start impulsively at t = 0, so at equal times they are the same
physical flow seen from two frames. For each folder it prints the drag
averaged over WINDOW (the moving sphere's covered nodes change every few
steps and its drag with them), the last drag, the error against the
standard drag curve at the case's U (of the fixed sphere's last, nearly
steady drag; of the moving sphere's window mean), and for a moving run the ratio of
its window mean to that of the fixed run of the same level and tag. With
--doc it writes sphere-drag.png (drag against time) and sphere-drag.dat
(the table) there.
"""
import argparse
import math
import os
import re
import sys

import numpy as np
from used_parameters import used_value

WINDOW = (0.3, 0.5)  # s: after the start-up, before the moving sphere's end


def standard_drag(folder, speed):
    """Clift, Grace & Weber (1978), 20 <= Re <= 260, whole sphere [N]."""
    rho = float(used_value(folder, "Density"))
    mu = float(used_value(folder, "Dynamic viscosity"))
    d = 2 * float(used_value(folder, "Radius"))
    re_ = rho * speed * d / mu
    if not 20 <= re_ <= 260:
        sys.exit(f"{folder}: Re = {re_:.1f} outside the correlation's 20-260")
    c_d = 24 / re_ * (1 + 0.1935 * re_**0.6305)
    return re_, c_d * rho * speed**2 * math.pi * d**2 / 8


def mesh_size(folder):
    """Cells and DoFs from the run's log, if kept."""
    try:
        with open(os.path.join(folder, "run.log")) as f:
            for line in f:
                m = re.match(r"Mesh: (\d+) cells, (\d+) DoFs", line)
                if m:
                    return int(m.group(1)), int(m.group(2))
    except OSError:
        pass
    return None, None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--doc", help="folder for the figure and table")
    parser.add_argument("--plot-tags", nargs="*",
                        help="the tagged runs of the figure's second panel "
                             "(default: all; the table has every run)")
    parser.add_argument("--label", help="name of the last run (unused)")
    parser.add_argument("--check-ratio", nargs="*", default=[],
                        metavar="RUN=LOW:HIGH",
                        help="check that the moving/fixed ratio of the run "
                             "(its folder's name) lies in [LOW, HIGH]; exit "
                             "status 1 if not")
    args = parser.parse_args()

    runs = {}
    for folder in args.folders:
        name = os.path.basename(os.path.normpath(folder))
        # <frame>-sphere[-<variant>]-r<level>[-<tag>]: the variant names the
        # case file (moving-sphere-carried.prm, or a copy with an entry
        # changed); a tag follows the level in older folders
        m = re.match(r"(fixed|moving)-sphere(?:-(.+?))?-r(\d+)(?:-(.+))?$", name)
        if not m or not os.path.exists(os.path.join(folder, "particle_0.dat")):
            print(f"skipped {folder} (not a finished sphere_drag.sh run)")
            continue
        frame, level = m.group(1), int(m.group(3))
        tag = "-".join(x for x in (m.group(2), m.group(4)) if x)
        a = np.loadtxt(os.path.join(folder, "particle_0.dat"), ndmin=2)
        t, f_z = a[:, 0], a[:, 12]
        inside = (t > WINDOW[0] + 1e-9) & (t <= WINDOW[1] + 1e-9)
        if t[-1] < WINDOW[1] - 1e-9:
            print(f"skipped {folder} (ends at t = {t[-1]} s, before {WINDOW[1]} s)")
            continue
        # U from the case: the stream's 'Velocity constants' (fixed) or the
        # 'Prescribed displacement constants' (moving), both 'U = ...'
        entry = ("Velocity constants" if frame == "fixed"
                 else "Prescribed displacement constants")
        speed = float(re.search(r"\bU\s*=\s*([-+.\deE]+)",
                                used_value(folder, entry)).group(1))
        runs[(frame, level, tag)] = dict(
            folder=folder, t=t, f=f_z, mean=f_z[inside].mean(),
            spread=(f_z[inside].min(), f_z[inside].max()),
            last=(t[-1], f_z[-1]), reference=standard_drag(folder, speed),
            size=mesh_size(folder),
            marking=used_value(folder, "Covered nodes"),
            integral=used_value(folder, "Force integral"))

    header = ("| run | r | cells/D | cells (DoFs) | covered nodes | force integral "
              f"| mean drag {WINDOW[0]}-{WINDOW[1]} s [mN] | min-max [mN] "
              "| last drag [mN] (t [s]) | against the drag curve | moving/fixed |")
    lines = [header, "|" + "---|" * 11]
    for key in sorted(runs, key=lambda k: (k[2], k[1], k[0])):
        frame, level, tag = key
        r = runs[key]
        re_, f_ref = r["reference"]
        cells, dofs = r["size"]
        ratio = ""
        if frame == "moving" and ("fixed", level, tag) in runs:
            ratio = f"{r['mean'] / runs[('fixed', level, tag)]['mean']:.3f}"
        elif frame == "moving" and ("fixed", level, "") in runs:
            ratio = f"{r['mean'] / runs[('fixed', level, '')]['mean']:.3f} (untagged fixed)"
        size = f"{cells} ({dofs})" if cells else "-"
        # the fixed sphere's drag at its end is (nearly) steady; the moving
        # one's is compared by its window mean
        against = (f"{100 * (r['last'][1] / f_ref - 1):+.1f} % (last)"
                   if frame == "fixed" else
                   f"{100 * (r['mean'] / f_ref - 1):+.1f} % (mean)")
        lines.append(
            f"| {os.path.basename(os.path.normpath(r['folder']))} | {level} | {3 << level} | {size} | {r['marking']} "
            f"| {r['integral']} | {1e3 * r['mean']:.4f} "
            f"| {1e3 * r['spread'][0]:.3f}-{1e3 * r['spread'][1]:.3f} "
            f"| {1e3 * r['last'][1]:.4f} ({r['last'][0]:.3g}) "
            f"| {against} (Re {re_:.1f}, {1e3 * f_ref:.4f} mN) "
            f"| {ratio} |")
    table = "\n".join(lines)
    print(table)
    failures = check_ratios(runs, args.check_ratio)

    if args.doc and runs:
        import matplotlib  # only for the figure

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        os.makedirs(args.doc, exist_ok=True)
        with open(os.path.join(args.doc, "sphere-drag.dat"), "w") as f:
            f.write(table + "\n")
        # (a) the plain runs, r = 0, 1, 2; (b) the variants (tagged runs)
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.8), sharey=True)
        f_ref = next(iter(runs.values()))["reference"][1]
        shown_tags = {k[2] for k in runs if k[2]
                      and (args.plot_tags is None or k[2] in args.plot_tags)}
        tagged_levels = {k[1] for k in runs if k[2] in shown_tags}
        for ax, tagged in zip(axes, (False, True)):
            for key in sorted(runs):
                frame, level, tag = key
                # the variants' panel also shows the plain fixed sphere of
                # their levels, the reference of the moving/fixed column
                reference = (tagged and not tag and frame == "fixed"
                             and level in tagged_levels)
                if bool(tag) != tagged and not reference:
                    continue
                if tag and tag not in shown_tags:
                    continue
                r = runs[key]
                label = f"{frame}, r={level}{', ' + tag if tag else ''}"
                line, = ax.plot(r["t"], 1e3 * r["f"],
                                lw=1.5 if frame == "fixed" else 0.6,
                                alpha=1 if frame == "fixed" else 0.7, label=label)
                # the window mean the table compares, as a bar over the window
                ax.plot(WINDOW, [1e3 * r["mean"]] * 2, color=line.get_color(), lw=3)
            ax.axhline(1e3 * f_ref, color="k", ls="--",
                       label="standard drag curve (Clift et al.)")
            ax.axvspan(*WINDOW, color="0.9", zorder=0)
            ax.set_xlim(0, 1.25)
            ax.set_ylim(0, 1e3 * 2 * f_ref)
            ax.set_xlabel("t [s]")
            ax.legend(fontsize=8, loc="lower right")
        axes[0].set_ylabel("drag on the sphere [mN]")
        axes[0].set_title("nearest, fixed mesh: r = 0, 1, 2")
        axes[1].set_title("variants (" + ", ".join(sorted(shown_tags))
                          + ") and the fixed sphere")
        fig.tight_layout()
        fig.savefig(os.path.join(args.doc, "sphere-drag.png"), dpi=120)
        print(f"wrote {args.doc}/sphere-drag.png and sphere-drag.dat")
    if failures:
        print("\n".join("FAILED: " + f for f in failures))
        sys.exit(1)


def moving_fixed_ratio(runs, key):
    """The moving run's window mean over the fixed run's of its level and
    tag, or of its level without a tag; None without such a fixed run."""
    _, level, tag = key
    fixed = runs.get(("fixed", level, tag)) or runs.get(("fixed", level, ""))
    return runs[key]["mean"] / fixed["mean"] if fixed else None


def check_ratios(runs, bounds):
    """The failed --check-ratio bounds, as lines (each printed as checked)."""
    failures = []
    by_name = {os.path.basename(os.path.normpath(r["folder"])): key
               for key, r in runs.items()}
    for item in bounds:
        name, band = item.split("=", 1)
        low, high = map(float, band.split(":"))
        key = by_name.get(name)
        ratio = moving_fixed_ratio(runs, key) if key and key[0] == "moving" else None
        if ratio is None:
            failures.append(f"{name}: no moving run with a fixed run of its level")
            continue
        ok = low <= ratio <= high
        print(f"{name}: moving/fixed {ratio:.3f} in [{low}, {high}]: "
              f"{'ok' if ok else 'FAILED'}")
        if not ok:
            failures.append(f"{name}: moving/fixed {ratio:.3f} outside [{low}, {high}]")
    return failures


if __name__ == "__main__":
    main()
