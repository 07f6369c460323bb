#!/usr/bin/python3
"""The ten Cate report (doc/validation/ten-cate.md) from its committed series.

    scripts/validation/ten_cate_report.py [--series doc/validation/ten-cate.dat]
        [--figure doc/validation/ten-cate.png] [--min-gap 1]
        [--collect BUILD/tests/validation [--commit HASH]]
    scripts/validation/ten_cate_report.py LABEL=RUN_SERIES ... --figure FIGURE

reads SERIES (one row per step of E1-E4: case, time [s], settling velocity
[m/s], gap h/d_p, kinetic energy of the particle and of the fluid [J]),
prints the report's table of u_max against the experiment (taken where the
gap is at least --min-gap, as the tests do), u_max/u_inf against the
experiment's (thesis Table 6.2) and the time the gap reaches one diameter,
and draws
FIGURE: the settling velocity against time and against the gap, with the
experiment's u_max, and the kinetic energies against time (thesis Figs 6.6
and 6.7).

Given LABEL=RUN_SERIES arguments instead, it reads one run from each file
as ten_cate.py --series wrote it (the case from its header), and the table
and the figure name each run by its LABEL.

--collect first writes SERIES from the files that `ctest -R
validation_ten_cate` leaves in the given folder,
ten-cate-<case>-series.dat (time, settling velocity, gap, kinetic energies;
written by ten_cate.py --series), with a header naming them and the commit
(--commit, default: the current HEAD) the runs were made on.
"""
import argparse
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# case: Re, experiment u_max [m/s] (ten Cate et al. 2002, Table II)
EXPERIMENT = {"e1": (1.5, 0.035986), "e2": (4.1, 0.05718),
              "e3": (11.6, 0.087269), "e4": (31.9, 0.12224)}
# case: u_inf [m/s], the settling velocity in an unbounded fluid, and the
# experiment's u_max / u_inf (thesis Tables 6.1 and 6.2)
UNBOUNDED = {"e1": (0.038, 0.947), "e2": (0.06, 0.953),
             "e3": (0.091, 0.959), "e4": (0.128, 0.955)}
# the End time each validation test runs its case to
# (tests/validation/CMakeLists.txt)
END_TIME = {"e1": "3.5", "e2": "2.1", "e3": "1.4", "e4": "1.1"}


def collect(folder, series, commit):
    """SERIES from FOLDER/ten-cate-<case>-series.dat, the numbers copied as
    they are."""
    if commit is None:
        try:
            commit = subprocess.run(
                ["git", "rev-parse", "--short", "HEAD"], check=True,
                capture_output=True, text=True).stdout.strip()
        except (OSError, subprocess.CalledProcessError):
            commit = "unknown"
    header, rows = [], []
    for case in EXPERIMENT:
        path = os.path.join(folder, f"ten-cate-{case}-series.dat")
        if not os.path.exists(path):
            continue
        with open(path) as f:
            for line in f:
                if line.startswith("#"):
                    header.append(f"#   {case}: {line[1:].strip()} "
                                  f"(to t = {END_TIME[case]} s)")
                elif line.strip():
                    rows.append(f"{case} {line.strip()}")
    with open(series, "w") as f:
        f.write("# ten Cate et al. (2002) E1-E4 as shipped: the runs of the tests "
                "validation_ten_cate_e1 ... e4\n"
                "# (prm/ten-cate/ten-cate-<case>.prm as shipped, 2 ranks, 'End time' "
                "shortened by tests/validation/CMakeLists.txt),\n"
                f"# code of commit {commit}; each case's series as "
                "scripts/validation/ten_cate.py --series wrote it:\n")
        f.write("\n".join(header) + "\n")
        f.write("# columns: case (e1-e4); time [s]; settling velocity -w [m/s]; "
                "gap h/d_p = (z - radius) / diameter;\n"
                "# kinetic energy of the particle and of the fluid in the whole box "
                "[J]\n"
                "# case time settling_velocity gap particle_kinetic_energy "
                "fluid_kinetic_energy\n")
        f.write("\n".join(rows) + "\n")
    print(f"wrote {series}")


def read_series(path):
    """{case: (t, w, gap, particle energy, fluid energy)} of SERIES."""
    columns = {}
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words or words[0].startswith("#"):
                continue
            columns.setdefault(words[0], []).append([float(x) for x in words[1:6]])
    return {case: tuple(np.array(rows).T) for case, rows in columns.items()}


def read_run_series(arguments):
    """{label: (case, (t, w, gap, particle energy, fluid energy))} of
    LABEL=FILE arguments, each FILE a ten_cate.py --series file."""
    runs = {}
    for argument in arguments:
        label, path = argument.rsplit("=", 1)
        with open(path) as f:
            header = f.readline()
        words = header.split()
        if len(words) < 4 or words[1:3] != ["ten", "Cate"]:
            raise SystemExit(f"{path}: not a ten_cate.py --series file")
        case = words[3].rstrip(",").lower()
        runs[label] = (case, tuple(np.loadtxt(path, ndmin=2).T[:5]))
    return runs


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="*", metavar="LABEL=RUN_SERIES",
                        help="runs to report instead of SERIES")
    parser.add_argument("--series", default="doc/validation/ten-cate.dat")
    parser.add_argument("--figure", default="doc/validation/ten-cate.png")
    parser.add_argument("--min-gap", type=float, default=1.)
    parser.add_argument("--title", default="ten Cate E1-E4 as shipped",
                        help="the figure's title")
    parser.add_argument("--collect", metavar="FOLDER", default=None,
                        help="write SERIES from FOLDER/ten-cate-<case>-series.dat "
                        "first")
    parser.add_argument("--commit", default=None,
                        help="with --collect: the commit the runs were made on "
                        "(default: the current HEAD)")
    args = parser.parse_args()
    if args.collect:
        collect(args.collect, args.series, args.commit)
    if args.runs:
        runs = read_run_series(args.runs)
    else:
        runs = {case.upper(): (case, columns)
                for case, columns in read_series(args.series).items()}

    fig, (ax_t, ax_h, ax_e) = plt.subplots(1, 3, figsize=(15, 4))
    print(f"| {'run' if args.runs else 'case'} | Re | u_max [m/s] | at t [s] | gap h/d_p there | "
          "experiment [m/s] | error | u_max/u_inf (experiment) | "
          "h/d_p = 1 at t [s] |")
    print("|---|---|---|---|---|---|---|---|---|")
    for label, (case, (t, w, gap, energy_p, energy_f)) in runs.items():
        re, u_exp = EXPERIMENT[case]
        window = np.nonzero(gap >= args.min_gap)[0]
        i = int(window[np.argmax(w[window])])
        error = 100 * (w[i] - u_exp) / u_exp
        u_inf, ratio_exp = UNBOUNDED[case]
        below = np.nonzero(gap <= 1.)[0]
        reached = f"{t[below[0]]:.3f}" if below.size else "not reached"
        print(f"| {label} | {re} | {w[i]:.5f} | {t[i]:.3f} | "
              f"{gap[i]:.2f} | {u_exp} | {error:+.2f} % | "
              f"{w[i] / u_inf:.3f} ({ratio_exp}) | {reached} |")
        line, = ax_t.plot(t, w, label=f"{label}, Re = {re}")
        ax_h.plot(gap, w, color=line.get_color())
        ax_e.semilogy(t[1:], energy_p[1:], color=line.get_color())
        ax_e.semilogy(t[1:], energy_f[1:], color=line.get_color(), ls="--")
        for ax in (ax_t, ax_h):
            ax.axhline(u_exp, color=line.get_color(), ls=":", lw=1)
    ax_h.axvline(args.min_gap, color="grey", lw=0.8, ls="--")
    ax_h.invert_xaxis()
    ax_t.set_xlabel("time [s]")
    ax_e.set_xlabel("time [s]")
    ax_e.set_ylabel("kinetic energy [J] (solid: particle, dashed: fluid)")
    # four decades below the largest energy: a sphere at rest on the floor
    # keeps round-off energies of 1e-40 J
    ax_e.set_ylim(bottom=1e-4 * max(np.max(columns[4]) for _, columns in runs.values()))
    ax_e.grid(alpha=0.3)
    ax_h.set_xlabel("gap h / d_p (falling towards the floor)")
    for ax in (ax_t, ax_h):
        ax.set_ylabel("settling velocity [m/s]")
        ax.grid(alpha=0.3)
    fig.suptitle(f"{args.title} (dotted: the experiment's u_max; "
                 f"dashed: h/d_p = {args.min_gap:g})", fontsize=10)
    ax_t.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.figure, dpi=110)
    print(f"wrote {args.figure}")


if __name__ == "__main__":
    main()
