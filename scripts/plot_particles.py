#!/usr/bin/python3
"""Plot the particles of a particulate-flow run: their paths in the vertical
plane (x-y in 2D, x-z in 3D) and their heights against time.

    scripts/plot_particles.py output/quickstart [--output FILE] [--title T]

reads OUTPUT/particle_<n>.dat and writes FILE (default
OUTPUT/particles.png).
"""
import argparse
import glob
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from particulate_output import read_series  # noqa: E402


def particle_files(folder):
    files = glob.glob(os.path.join(folder, "particle_*.dat"))
    number = lambda f: int(re.search(r"particle_(\d+)\.dat$", f).group(1))
    return sorted((f for f in files if re.search(r"_\d+\.dat$", f)), key=number)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder")
    parser.add_argument("--output", default=None)
    parser.add_argument("--title", default=None)
    args = parser.parse_args()
    files = particle_files(args.folder)
    if not files:
        sys.exit(f"{args.folder}: no particle_<n>.dat (is it a particulate-flow run?)")

    series = [(int(re.search(r"particle_(\d+)\.dat$", f).group(1)), read_series(f))
              for f in files]
    # 2D runs write z = 0: there y is up; in 3D z is, and the path is drawn
    # in the vertical x-z plane
    up = "z" if any((s["z"] != 0).any() for _, s in series) else "y"
    fig, (ax_path, ax_height) = plt.subplots(1, 2, figsize=(10, 5),
                                             gridspec_kw={"width_ratios": [1, 1.6]})
    for n, s in series:
        line, = ax_path.plot(s["x"], s[up], lw=1, label=f"particle {n}")
        ax_path.plot(s["x"][0], s[up][0], "o", mfc="none", color=line.get_color())
        ax_path.plot(s["x"][-1], s[up][-1], "o", color=line.get_color())
        ax_height.plot(s["time"], s[up], color=line.get_color(), label=f"particle {n}")
    ax_path.set_aspect("equal")
    ax_path.set_xlabel("x [m]")
    ax_path.set_ylabel(f"{up} [m]")
    ax_path.set_title("paths (open: start, filled: end)", fontsize=9)
    ax_height.set_xlabel("time [s]")
    ax_height.set_ylabel(f"height {up} [m]")
    ax_height.legend(fontsize=8)
    for ax in (ax_path, ax_height):
        ax.grid(alpha=0.3)
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    out = args.output or os.path.join(args.folder, "particles.png")
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
