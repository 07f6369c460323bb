#!/usr/bin/python3
"""DFG flow-around-a-cylinder benchmarks (Schaefer & Turek 1996): plots for
doc/validation/dfg.md from the validation tests' output.

    scripts/validation/dfg.py BUILD/tests/validation [--doc doc/validation]

reads, where present,
  dfg-2d-1_levels.dat, dfg-3d-1z_levels.dat  (validation_dfg_2d_1_levels,
                                             validation_dfg_3d_1z_levels)
  dfg_2d_2_output/flow.dat                   (validation_dfg_2d_2)
and writes dfg-steady-levels.png (relative errors of c_D, c_L and delta_p
against the DoFs) and dfg-2d-2.png (drag and lift over time with the
benchmark's intervals for the maxima).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_table(path):
    with open(path) as f:
        names = f.readline().lstrip("#").split()
    data = np.atleast_2d(np.loadtxt(path))
    return {name: data[:, i] for i, name in enumerate(names)}


def plot_levels(folder, doc):
    cases = [("dfg-2d-1", "2D-1"), ("dfg-3d-1z", "3D-1Z")]
    tables = [(label, read_table(os.path.join(folder, name + "_levels.dat")))
              for name, label in cases
              if os.path.exists(os.path.join(folder, name + "_levels.dat"))]
    if not tables:
        return
    fig, axes = plt.subplots(1, len(tables), figsize=(6 * len(tables), 4.2),
                             squeeze=False)
    for ax, (label, t) in zip(axes[0], tables):
        for key, name, marker in [("c_D_error", "$c_D$", "o"),
                                  ("c_L_error", "$c_L$", "s"),
                                  ("delta_p_error", r"$\Delta p$", "^")]:
            ax.loglog(t["dofs"], np.abs(t[key]), marker=marker, label=name)
        ax.set_xlabel("DoFs")
        ax.set_ylabel("relative error")
        ax.set_title(f"DFG {label}: errors against the reference values")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    out = os.path.join(doc, "dfg-steady-levels.png")
    fig.savefig(out, dpi=120)
    print("wrote", out)


def plot_2d_2(folder, doc):
    path = os.path.join(folder, "dfg_2d_2_output", "flow.dat")
    if not os.path.exists(path):
        return
    t = read_table(path)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    top.plot(t["time"], t["c_D"], lw=0.8)
    top.axhspan(3.22, 3.24, color="tab:green", alpha=0.3,
                label=r"benchmark interval of $c_{D,\max}$")
    top.set_ylabel("$c_D$")
    top.set_ylim(2.9, 3.3)
    top.legend(loc="lower right")
    bottom.plot(t["time"], t["c_L"], lw=0.8)
    bottom.axhspan(0.99, 1.01, color="tab:green", alpha=0.3,
                   label=r"benchmark interval of $c_{L,\max}$")
    bottom.set_ylabel("$c_L$")
    bottom.set_xlabel("t [s]")
    bottom.legend(loc="lower left")
    top.set_title("DFG 2D-2 (Re = 100)")
    fig.tight_layout()
    out = os.path.join(doc, "dfg-2d-2.png")
    fig.savefig(out, dpi=120)
    print("wrote", out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("folder", help="build/tests/validation")
    parser.add_argument("--doc", default="doc/validation")
    args = parser.parse_args()
    plot_levels(args.folder, args.doc)
    plot_2d_2(args.folder, args.doc)


if __name__ == "__main__":
    main()
