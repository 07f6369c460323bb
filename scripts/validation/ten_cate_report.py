#!/usr/bin/python3
"""The ten Cate report (doc/validation/ten-cate.md) from its committed series.

    scripts/validation/ten_cate_report.py [--dir doc/validation/ten-cate]
        [--min-gap 2]

reads DIR/e1.dat ... e4.dat (time [s], settling velocity [m/s], gap h/d_p:
the files that `ctest -R validation_ten_cate` writes as
build/tests/validation/ten-cate-<case>-series.dat), prints the report's
table of u_max against the experiment (taken where the gap is at least
--min-gap, as the tests do) and draws DIR/velocity.png: the settling
velocity against time and against the gap, with the experiment's u_max.
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# case: Re, experiment u_max [m/s] (ten Cate et al. 2002, Table II)
EXPERIMENT = {"e1": (1.5, 0.035986), "e2": (4.1, 0.05718),
              "e3": (11.6, 0.087269), "e4": (31.9, 0.12224)}


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--dir", default="doc/validation/ten-cate")
    parser.add_argument("--min-gap", type=float, default=2.)
    args = parser.parse_args()

    fig, (ax_t, ax_h) = plt.subplots(1, 2, figsize=(11, 4))
    print("| case | Re | u_max [m/s] | at t [s] | gap h/d_p there | "
          "experiment [m/s] | error |")
    print("|---|---|---|---|---|---|---|")
    for case, (re, u_exp) in EXPERIMENT.items():
        path = os.path.join(args.dir, f"{case}.dat")
        if not os.path.exists(path):
            continue
        t, w, gap = np.loadtxt(path, unpack=True, ndmin=2)
        window = np.nonzero(gap >= args.min_gap)[0]
        i = int(window[np.argmax(w[window])])
        error = 100 * (w[i] - u_exp) / u_exp
        print(f"| {case.upper()} | {re} | {w[i]:.5f} | {t[i]:.3f} | "
              f"{gap[i]:.2f} | {u_exp} | {error:+.2f} % |")
        line, = ax_t.plot(t, w, label=f"{case.upper()}, Re = {re}")
        ax_h.plot(gap, w, color=line.get_color())
        for ax in (ax_t, ax_h):
            ax.axhline(u_exp, color=line.get_color(), ls=":", lw=1)
    ax_h.axvline(args.min_gap, color="grey", lw=0.8, ls="--")
    ax_h.invert_xaxis()
    ax_t.set_xlabel("time [s]")
    ax_h.set_xlabel("gap h / d_p (falling towards the floor)")
    for ax in (ax_t, ax_h):
        ax.set_ylabel("settling velocity [m/s]")
        ax.grid(alpha=0.3)
    fig.suptitle("ten Cate E1-E4 as shipped (dotted: the experiment's u_max; "
                 "dashed: h/d_p = 2)", fontsize=10)
    ax_t.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.dir, "velocity.png"), dpi=110)


if __name__ == "__main__":
    main()
