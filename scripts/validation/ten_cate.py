#!/usr/bin/python3
"""ten Cate et al. (2002) sedimentation benchmark: compare runs of
prm/ten-cate/ten-cate-e*.prm with the experiment and plot them.

    scripts/validation/ten_cate.py output/ten-cate-e4 [output/ten-cate-e3 ...]
        [--doc FOLDER] [--max-error PERCENT] [--min-gap G] [--series FILE]

For each output folder (the case is read from its used_parameters.prm) it
prints u_max, its time and its error against the experiment's maximum
settling velocity (ten Cate's Table II), and writes into --doc (default:
the first folder) ten-cate-velocity.png (settling velocity),
ten-cate-gap.png (gap height h/d_p), ten-cate-energy.png (particle and
fluid kinetic energy) and ten-cate.dat (the table). --min-gap takes u_max
over the part of each run where the gap h/d_p is at least G (the approach
to the floor left out). With --max-error it exits 1 unless every run has
passed its maximum in that part (the velocity falls after it) within
PERCENT of the experiment. --series writes the first run's time, settling
velocity, gap and the kinetic energies of particle and fluid, a few kB,
for the report (scripts/validation/
ten_cate_report.py).

Each run's line also gives the time the gap falls to one diameter, the
first fresh adaptation of the carried mesh (mesh.dat's column
'readapted') against the time of u_max, and the rebound: the largest rise
of the settling velocity above its lowest value between u_max and the
sphere's first stop (where the contact model halts it: the settling
velocity below 1 % of u_max), in % of u_max (a sphere approaching a wall
only slows down). After the first stop it gives the sphere's largest
settling velocity and its gap at the end. --max-rebound PERCENT fails a
run whose rebound exceeds it.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from used_parameters import used_value  # noqa: E402

# experiment: fluid density [kg/m^3], dynamic viscosity [Pa s], u_max [m/s]
EXPERIMENT = {
    "E1": (970.0, 0.373, 0.035986),
    "E2": (965.0, 0.212, 0.05718),
    "E3": (962.0, 0.113, 0.087269),
    "E4": (960.0, 0.058, 0.12224),
}


def read_series(path):
    with open(path) as f:
        names = f.readline()[1:].split()
    return names, np.loadtxt(path, ndmin=2)


def fresh_adaptations(folder):
    """The times of the carried mesh's fresh adaptations (none without a
    mesh.dat)."""
    path = os.path.join(folder, "mesh.dat")
    if not os.path.exists(path):
        return np.array([])
    names, m = read_series(path)
    if "readapted" not in names:
        return np.array([])
    return m[m[:, names.index("readapted")] > 0, 0]


def first_stop(w, peak):
    """The index at which w first falls below 1 % of w[peak] after peak,
    or None."""
    stopped = np.nonzero(w[peak:] < 0.01 * w[peak])[0]
    return peak + int(stopped[0]) if stopped.size else None


def rebound(w, peak):
    """The largest rise of w above its running minimum from index peak to
    the first stop."""
    stop = first_stop(w, peak)
    approach = w[peak:stop]
    return float(np.max(approach - np.minimum.accumulate(approach)))


def describe_approach(t, w, gap, peak, fresh):
    """The gap's h/d_p = 1 time, the fresh adaptations (times FRESH)
    against the peak, the rebound and the first stop, as one line's
    clauses."""
    below = np.nonzero(gap <= 1.)[0]
    reached = f"at {t[below[0]]:.3f} s" if below.size else "not reached"
    if fresh.size == 0:
        adaptation = "no fresh adaptation"
    else:
        adaptation = (f"first fresh adaptation at t = {fresh[0]:.3f} s, "
                      f"{np.count_nonzero(fresh <= t[peak])} of {fresh.size} "
                      "by u_max")
    stop = first_stop(w, peak)
    if stop is None:
        stopped = "no stop"
    else:
        stopped = (f"first stop at t = {t[stop]:.3f} s, h/d_p = {gap[stop]:.3f}, "
                   f"from {w[stop - 1]:.4f} m/s; then at most "
                   f"{np.max(w[stop:]):.4f} m/s, h/d_p = {gap[-1]:.3f} at the end")
    return (f"h/d_p = 1 {reached}; {adaptation}; rebound "
            f"{100 * rebound(w, peak) / w[peak]:.2f} % of u_max; {stopped}")


def identify(folder):
    """The experiment a run reproduces, from its fluid properties."""
    rho = float(used_value(folder, "Density"))
    mu = float(used_value(folder, "Dynamic viscosity"))
    for name, (rho_e, mu_e, _) in EXPERIMENT.items():
        if abs(rho - rho_e) < 0.5 and abs(mu - mu_e) < 1e-6:
            return name
    sys.exit(f"{folder}: fluid {rho} kg/m^3, {mu} Pa s is none of E1-E4")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--doc", default=None,
                        help="folder for the figures and the table "
                        "(default: the first run's folder)")
    parser.add_argument("--label", nargs="*", default=None,
                        help="legend label per folder (default: folder name)")
    parser.add_argument("--max-error", type=float, default=None,
                        help="bound on |u_max error| [%%]; exit 1 beyond it")
    parser.add_argument("--min-gap", type=float, default=0.,
                        help="take u_max where the gap h/d_p >= this")
    parser.add_argument("--max-rebound", type=float, default=None,
                        help="bound on the rebound after u_max [%% of u_max]; "
                        "exit 1 beyond it")
    parser.add_argument("--series", default=None,
                        help="write time, settling velocity, gap and the "
                        "kinetic energies of the first run to this file")
    args = parser.parse_args()
    args.doc = args.doc or args.folders[0]
    os.makedirs(args.doc, exist_ok=True)

    figs = {k: plt.subplots(figsize=(7, 4)) for k in ("velocity", "gap", "energy")}
    rows = []
    failures = []
    for k, folder in enumerate(args.folders):
        case = identify(folder)
        u_exp = EXPERIMENT[case][2]
        names, p = read_series(os.path.join(folder, "particle_0.dat"))
        flow_names, flow = read_series(os.path.join(folder, "flow.dat"))
        t = p[:, names.index("time")]
        w = -p[:, names.index("w")]
        z = p[:, names.index("z")]
        radius = float(used_value(folder, "Radius"))
        gap = (z - radius) / (2 * radius)
        window = np.nonzero(gap >= args.min_gap)[0]
        if len(window) == 0:
            sys.exit(f"{folder}: the gap is below {args.min_gap} from the start")
        i = int(window[np.argmax(w[window])])
        error = (w[i] - u_exp) / u_exp
        label = args.label[k] if args.label else os.path.basename(folder.rstrip("/"))
        rows.append((case, label, w[i], t[i], u_exp, error, t[-1]))
        if args.max_error is not None:
            if i == window[-1]:
                failures.append(f"{case} {label}: still accelerating at the "
                                f"end, t = {t[-1]:.3f} s (no maximum yet)")
            elif abs(100 * error) > args.max_error:
                failures.append(f"{case} {label}: u_max error "
                                f"{100 * error:+.2f} % beyond "
                                f"{args.max_error} %")
        approach = describe_approach(t, w, gap, i, fresh_adaptations(folder))
        rise = 100 * rebound(w, i) / w[i]
        if args.max_rebound is not None and rise > args.max_rebound:
            failures.append(f"{case} {label}: the velocity rises again by "
                            f"{rise:.2f} % of u_max after its maximum, "
                            f"beyond {args.max_rebound} %")
        if args.series and k == 0:
            # the kinetic energies of the particle and of the fluid (the
            # whole box's, the images of a symmetric domain included)
            particle_energy = p[:, names.index("kinetic_energy")]
            fluid_energy = np.interp(
                t, flow[:, 0], flow[:, flow_names.index("fluid_kinetic_energy")])
            np.savetxt(args.series,
                       np.column_stack((t, w, gap, particle_energy,
                                        fluid_energy)),
                       fmt="%.6g",
                       header=f"ten Cate {case}, {label}: time [s], settling "
                       "velocity [m/s], gap h/d_p, kinetic energy of the "
                       "particle and of the fluid [J]")
        print(f"{case} {label}: u_max = {w[i]:.5f} m/s at t = {t[i]:.3f} s, "
              f"experiment {u_exp:.5f} m/s, error {100 * error:+.2f} % "
              f"(run to t = {t[-1]:.3f} s); {approach}")
        line, = figs["velocity"][1].plot(t, w, label=f"{case} {label}")
        figs["velocity"][1].axhline(u_exp, color=line.get_color(), ls=":",
                                    lw=1)
        figs["gap"][1].plot(t, gap, label=f"{case} {label}")
        ax = figs["energy"][1]
        ax.semilogy(flow[:, 0], flow[:, 2], color=line.get_color(),
                    label=f"{case} {label}: particle")
        ax.semilogy(flow[:, 0], flow[:, 1], color=line.get_color(), ls="--",
                    label=f"{case} {label}: fluid")

    labels = {"velocity": "settling velocity [m/s] (dotted: experiment u_max)",
              "gap": "gap height h / d_p",
              "energy": "kinetic energy [J]"}
    for key, (fig, ax) in figs.items():
        ax.set_xlabel("time [s]")
        ax.set_ylabel(labels[key])
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(args.doc, f"ten-cate-{key}.png"), dpi=120)
    with open(os.path.join(args.doc, "ten-cate.dat"), "w") as f:
        f.write("# case run u_max time_of_u_max u_max_experiment "
                "relative_error end_time\n")
        for r in rows:
            f.write(f"{r[0]} {r[1]} {r[2]:.6g} {r[3]:.4g} {r[4]:.6g} "
                    f"{r[5]:.5g} {r[6]:.4g}\n")
    for failure in failures:
        print("FAILED:", failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
