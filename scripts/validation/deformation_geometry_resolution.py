#!/usr/bin/python3
"""Table and figure of the geometry-resolution study (thesis §6.6).

Usage:
    deformation_geometry_resolution.py FOLDER [--level L] [--doc DOC_DIR]

FOLDER is what `validation_deformation_geometry_resolution SURFACE FOLDER
LEVELS` wrote. Prints the table of doc/validation/geometry-resolution.md
and, with --doc, writes DOC_DIR/deformation-geometry-slice.png: the mesh cut
through the middle of the body at level L, not adapted and adapted with
Laplace-kappa, with the body's own section in red.
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

from deformation_test_problem import read_gnuplot as polylines  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--level", type=int, default=2)
    parser.add_argument("--doc")
    args = parser.parse_args()

    print("| level | cells | h / size | mesh | Hausdorff / size "
          "| mean face distance / size | volume error | min scaled Jacobian "
          "| time [s] |")
    print("|---|---|---|---|---|---|---|---|---|")
    with open(os.path.join(args.folder, "geometry-resolution.dat")) as f:
        for line in f:
            if line.startswith("#"):
                continue
            c = line.split()
            name = "Laplace-κ" if c[3] == "laplace-kappa" else "not adapted"
            print(f"| {c[0]} | {c[1]} | {float(c[2]):.3g} | {name} "
                  f"| {float(c[4]):.4f} | {float(c[5]):.5f} "
                  f"| {100 * float(c[6]):+.2f} % | {float(c[7]):.2f} "
                  f"| {float(c[9]):.2g} |")

    if not args.doc:
        return
    section = polylines(os.path.join(args.folder, "slice-surface.dat"))
    fig, axes = plt.subplots(1, 2, figsize=(12, 6))
    for ax, kind, title in zip(axes, ["plain", "kappa"],
                               ["not adapted", "Laplace-κ"]):
        cells = polylines(os.path.join(
            args.folder, f"slice-level{args.level}-{kind}.dat"))
        ax.add_collection(LineCollection(cells, colors="k", linewidths=0.3))
        ax.add_collection(LineCollection(section, colors="tab:red",
                                         linewidths=1.0))
        xs = [p[0] for s in section for p in s]
        ys = [p[1] for s in section for p in s]
        pad = 0.15 * (max(xs) - min(xs))
        ax.set_xlim(min(xs) - pad, max(xs) + pad)
        ax.set_ylim(min(ys) - pad, max(ys) + pad)
        ax.set_aspect("equal")
        ax.set_title(f"{title}, level {args.level} (section through the middle)")
    fig.tight_layout()
    os.makedirs(args.doc, exist_ok=True)
    fig.savefig(os.path.join(args.doc, "deformation-geometry-slice.png"),
                dpi=130)


if __name__ == "__main__":
    main()
