#!/usr/bin/python3
"""Tables and figures of the grid-deformation test problem (thesis §5.6).

Usage:
    deformation_test_problem.py FOLDER [--doc DOC_DIR]

FOLDER is what `validation_deformation_test_problem FOLDER LEVEL` wrote:
test-problem.dat and the level-5 grids (gnuplot format). Prints the table
of doc/validation/deformation-test-problem.md and, with --doc, writes
    DOC_DIR/deformation-grids.png            deformed level-5 grids
    DOC_DIR/deformation-equidistribution.png error against the cell count
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_rows(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            c = line.split()
            rows.append(dict(level=int(c[0]), cells=int(c[1]), method=c[2],
                             eps=float(c[3]), success=c[4] == "1",
                             steps=int(c[5]), l2_before=float(c[6]),
                             max_before=float(c[7]), l2=float(c[8]),
                             max=float(c[9]), sj=float(c[10]),
                             ar=float(c[11]), seconds=float(c[13])))
    return rows


def read_gnuplot(path):
    """Polylines of a gnuplot-style file (deal.II grids, slices): points
    "x y ...", a blank line between lines."""
    lines, current = [], []
    with open(path) as f:
        for line in f:
            c = line.split()
            if len(c) >= 2 and not line.startswith("#"):
                current.append((float(c[0]), float(c[1])))
            elif current:
                lines.append(current)
                current = []
    if current:
        lines.append(current)
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--doc", help="write the figures into this folder")
    args = parser.parse_args()
    rows = read_rows(os.path.join(args.folder, "test-problem.dat"))

    print("| level | cells | eps | method | steps | E_L2 before | E_L2 after "
          "| E_max after | min scaled Jacobian | max aspect ratio | time [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if r["success"]:
            print(f"| {r['level']} | {r['cells']} | {r['eps']} | {r['method']} "
                  f"| {r['steps']} | {r['l2_before']:.3f} | {r['l2']:.4g} "
                  f"| {r['max']:.4g} | {r['sj']:.3f} | {r['ar']:.1f} "
                  f"| {r['seconds']:.3g} |")
        else:
            print(f"| {r['level']} | {r['cells']} | {r['eps']} | {r['method']} "
                  f"| 1 | {r['l2_before']:.3f} | refused: would tangle | | | "
                  f"| {r['seconds']:.3g} |")

    if not args.doc:
        return
    os.makedirs(args.doc, exist_ok=True)

    panels = [("basic", "0.1"), ("robust", "0.1"), ("robust", "0.02")]
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.6))
    for ax, (method, eps) in zip(axes, panels):
        path = os.path.join(args.folder, f"grid-{method}-eps{eps}.gnuplot")
        for line in read_gnuplot(path):
            xs, ys = zip(*line)
            ax.plot(xs, ys, "k-", lw=0.4)
        circle = plt.Circle((0.5, 0.5), 0.25, fill=False, color="tab:red",
                            lw=0.8, ls="--")
        ax.add_patch(circle)
        ax.set_aspect("equal")
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.set_title(f"{method} method, eps = {eps} (32 x 32 cells)")
    fig.tight_layout()
    fig.savefig(os.path.join(args.doc, "deformation-grids.png"), dpi=130)

    fig, ax = plt.subplots(figsize=(6.5, 4.8))
    for (method, eps), style in zip(
            [("basic", 0.1), ("robust", 0.1), ("basic", 0.02),
             ("robust", 0.02)], ["o-", "s-", "o--", "s--"]):
        pts = [(r["cells"], r["l2"]) for r in rows
               if r["method"] == method and r["eps"] == eps and r["success"]]
        if pts:
            xs, ys = zip(*pts)
            ax.loglog(xs, ys, style, label=f"{method}, eps = {eps}")
    xs = sorted({r["cells"] for r in rows})
    ref = [0.5 * (xs[0] / x) ** 0.75 for x in xs]
    ax.loglog(xs, ref, "k:", label="O(h^1.5)")
    ax.set_xlabel("cells")
    ax.set_ylabel("equidistribution error E_L2 after deformation")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(args.doc, "deformation-equidistribution.png"),
                dpi=130)


if __name__ == "__main__":
    main()
