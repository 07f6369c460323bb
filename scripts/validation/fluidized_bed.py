#!/usr/bin/python3
"""The liquid-fluidized bed after Aguilar-Corona et al. (thesis §6.7.2):
spheres in a vertical column, lifted by a uniform upward flow, against the
Richardson-Zaki correlation.

    scripts/validation/fluidized_bed.py BED --bead BEAD [--held-bead HELD]
        [--after T] [--doc DIR] [--check-bracket]
    scripts/validation/fluidized_bed.py BEAD HELD BED [--after T] [--check-bracket]
    scripts/validation/fluidized_bed.py --redraw DIR

BEAD is the output of the single bead settling in the closed column
(prm/fluidized-bed/single-bead.prm), HELD that of the bead held in a stream
(prm/fluidized-bed/held-bead.prm), BED that of the bed
(prm/fluidized-bed/fluidized-bed.prm). It prints

- the bead's terminal velocity u_t: its mean settling speed from when it
  first reaches 98 % of its largest speed to 2 diameters above the floor,
  with the range over that stretch, its Reynolds number, and u_t against
  the thesis's 0.226 m/s;
- the held bead's drag F at the stream speed U (mean over the last half of
  its run) against its buoyant weight W, and the terminal velocity that
  follows, U (W/F)^(1/n), with n = 2 + dln C_D/dln Re of the standard drag
  curve (Schiller-Naumann) at U;
- the bed: the number of particles, its height h_b(t) = 2 mean(z - z_floor)
  (z_floor the distributor)
  (for a bed of uniform solid fraction the centroid lies at half its
  height) and its solid fraction alpha(t) = N V_p / (pi R_c^2 h_b)
  (thesis eq. 6.6), both averaged over t > T (default: the last half of the
  run), with their standard deviations, and alpha's trend there (the
  slope of its least-squares line: how far the bed still is from a
  settled state);
- the middle half of the bed (between a quarter and three quarters of h_b):
  its solid fraction and its beads' mean vertical velocity over t > T,
  against Richardson-Zaki's velocity of a suspension of that solid
  fraction, (u_0 - u_t (1 - alpha)^m) / (1 - alpha);
- the Richardson-Zaki prediction alpha_rz = 1 - (u_0 / u_t)^(1/m) (thesis
  eq. 6.8), m = 2.4 for Re_p >= 500 (Richardson and Zaki, 1954; thesis
  Table 6.7): the experiment's (u_0 = 0.12 m/s, u_t = 0.226 m/s), and with
  the run's u_0 and the terminal velocities measured here, each also with
  Richardson and Zaki's correction for the column's wall, u_t 10^(-d/D).

The second form takes the three runs in the order the validation test
makes them. --check-bracket exits with status 1 unless the bed's solid
fraction over t > T lies between the Richardson-Zaki predictions, with the
wall correction, of the settling and of the held bead (the report's
result: the bed's alpha is bracketed by the two ways of measuring u_t on
this mesh); it needs HELD.

With --doc it writes fluidized-bed.dat (t, h_b, alpha), fluidized-bed-bead.dat
(the bead's t, z, w), fluidized-bed-rz.dat (T and the predictions) and
fluidized-bed.png into DIR; --redraw draws the figure again from DIR's
series.
"""
import argparse
import csv
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from particulate_output import (  # noqa: E402
    read_parameters,
    read_particle_series,
    read_table,
    write_table,
)

THESIS_U_T = 0.226
THESIS_U_0 = 0.12
RZ_INDEX = 2.4


def run_set_up(folder):
    """The column's radius and floor, the liquid's density and dynamic
    viscosity, |g|, and the particles' ids, volumes and densities."""
    values = read_parameters(folder)
    lower = [float(v) for v in values["Mesh/Lower corner"].split(",")]
    upper = [float(v) for v in values["Mesh/Upper corner"].split(",")]
    with open(os.path.join(folder, "particle_set.csv")) as f:
        rows = list(csv.DictReader(f))
    return {
        "radius": 0.5 * min(upper[0] - lower[0], upper[1] - lower[1]),
        # the beads' floor: the distributor where there is one
        "floor": float(values.get("Particles/Distributor height") or lower[2]),
        "rho_f": float(values["Fluid/Density"]),
        "mu": float(values["Fluid/Dynamic viscosity"]),
        "g": np.linalg.norm([float(v) for v in values["Particles/Gravity"].split(",")]),
        "ids": [r["id"] for r in rows],
        "volume": np.array([float(r["volume"]) for r in rows]),
        "values": values,
    }


def velocity_constant(folder, values, name):
    """The constant `name` of the inflow's 'Velocity constants'."""
    for pair in values["Boundary conditions/Velocity constants"].split(","):
        key, _, value = pair.partition("=")
        if key.strip() == name:
            return float(value)
    sys.exit(f"{folder}: the 'Velocity constants' name no {name}")


def terminal_velocity(folder):
    """The bead's settling speed once steady, its Reynolds number, its
    series (t, z, w) and the time window used."""
    setup = run_set_up(folder)
    (bead,) = read_particle_series(folder, setup["ids"][:1])
    t, z, w = bead["time"], bead["z"], bead["w"]
    d = 2 * (3 * setup["volume"][0] / (4 * math.pi)) ** (1 / 3)
    above = np.flatnonzero(z - setup["floor"] > 2 * d)
    last = above[-1]
    speed = -w[:last + 1]
    start = int(np.argmax(speed >= 0.98 * speed.max()))
    if last - start < 5:
        sys.exit(f"{folder}: the bead never settles at a steady speed (within 2 % "
                 f"of its largest) before it nears the floor")
    u_t = float(np.mean(speed[start:]))
    reynolds = u_t * d * setup["rho_f"] / setup["mu"]
    return (u_t, reynolds, d, np.column_stack([t, z, w]), (t[start], t[last]),
            (speed[start:].min(), speed[start:].max()))


def held_terminal_velocity(folder):
    """The held bead's stream speed U, mean drag over the last half of the
    run, buoyant weight, and the terminal velocity they give."""
    setup = run_set_up(folder)
    (bead,) = read_particle_series(folder, setup["ids"][:1])
    values = setup["values"]
    speed = velocity_constant(folder, values, "U")
    late = bead["time"] > 0.5 * bead["time"][-1]
    drag = float(np.mean(bead["F_z"][late]))
    with open(os.path.join(folder, "particle_set.csv")) as f:
        rho_p = float(next(csv.DictReader(f))["density"])
    weight = (rho_p - setup["rho_f"]) * setup["volume"][0] * setup["g"]
    d = 2 * (3 * setup["volume"][0] / (4 * math.pi)) ** (1 / 3)
    reynolds = speed * d * setup["rho_f"] / setup["mu"]
    growth = 0.15 * reynolds ** 0.687
    exponent = 2 + (-1 + 0.687 * growth / (1 + growth))
    return speed, drag, weight, speed * (weight / drag) ** (1 / exponent), exponent


def richardson_zaki(u_0, u_t):
    """The solid fraction at which a bed of spheres with terminal velocity
    u_t is fluidized by the superficial velocity u_0 (thesis eq. 6.8)."""
    return 1 - (u_0 / u_t) ** (1 / RZ_INDEX)


def bed_history(setup, series):
    """t, h_b(t) and alpha(t) of the bed."""
    t = series[0]["time"]
    heights = np.array([s["z"] for s in series]) - setup["floor"]
    h_b = 2 * heights.mean(axis=0)
    alpha = setup["volume"].sum() / (math.pi * setup["radius"] ** 2 * h_b)
    return np.column_stack([t, h_b, alpha])


def middle_slab(setup, series, after):
    """The solid fraction of the middle half of the bed (the beads between
    a quarter and three quarters of h_b above the distributor) and their
    mean vertical velocity, each averaged over t > after."""
    t = series[0]["time"]
    heights = np.array([s["z"] for s in series]) - setup["floor"]
    w = np.array([s["w"] for s in series])
    h_b = 2 * heights.mean(axis=0)
    inside = (heights > 0.25 * h_b) & (heights < 0.75 * h_b)
    volume = setup["volume"][0]
    alpha = inside.sum(axis=0) * volume / (math.pi * setup["radius"] ** 2 * 0.5 * h_b)
    speed = np.where(inside, w, 0).sum(axis=0) / np.maximum(inside.sum(axis=0), 1)
    late = t > after
    return float(alpha[late].mean()), float(speed[late].mean())


def suspension_velocity(u_0, u_t, alpha):
    """Richardson-Zaki's mean velocity of the beads in a suspension of solid
    fraction alpha through which the superficial velocity u_0 rises:
    (u_0 - u_t (1 - alpha)^m) / (1 - alpha)."""
    porosity = 1 - alpha
    return (u_0 - u_t * porosity ** RZ_INDEX) / porosity


def analyse(bed, bead, held, after, doc, check_bracket):
    u_t, reynolds, d, bead_table, window, spread = terminal_velocity(bead)
    print(f"single bead: d = {d:.4g} m, terminal velocity u_t = {u_t:.4g} m/s "
          f"(mean over t = {window[0]:.3g} .. {window[1]:.3g} s, range {spread[0]:.4g} .. "
          f"{spread[1]:.4g}), Re_p = {reynolds:.4g}")
    print(f"  against the thesis's {THESIS_U_T} m/s: {100 * (u_t / THESIS_U_T - 1):+.1f} %")
    speeds = [("settling bead", u_t)]
    if held:
        speed, drag, weight, u_held, exponent = held_terminal_velocity(held)
        print(f"held bead in a stream of {speed:.4g} m/s: drag {drag:.4g} N against its "
              f"buoyant weight {weight:.4g} N (F/W = {drag / weight:.3f}); terminal "
              f"velocity U (W/F)^(1/{exponent:.3f}) = {u_held:.4g} m/s "
              f"({100 * (u_held / THESIS_U_T - 1):+.1f} % against the thesis)")
        speeds.append(("held bead", u_held))

    setup = run_set_up(bed)
    series = read_particle_series(bed, setup["ids"])
    history = bed_history(setup, series)
    u_0 = velocity_constant(bed, setup["values"], "u0")
    t = history[:, 0]
    if after is None:
        after = 0.5 * t[-1]
    late = t > after
    if late.sum() < 2:
        sys.exit(f"{bed}: the run ends at t = {t[-1]:.4g}, before --after {after}")
    h_mean, h_std = history[late, 1].mean(), history[late, 1].std()
    a_mean, a_std = history[late, 2].mean(), history[late, 2].std()
    print(f"bed: {len(setup['ids'])} particles, column radius {setup['radius']:.4g} m "
          f"(D/d = {2 * setup['radius'] / d:.3g}), u_0 = {u_0:.4g} m/s, t = 0 .. {t[-1]:.4g} s")
    print(f"  at t = 0: h_b = {history[0, 1]:.4g} m, alpha = {history[0, 2]:.4g}")
    print(f"  over t > {after:.3g} s: h_b = {h_mean:.4g} +- {h_std:.2g} m, "
          f"alpha = {a_mean:.4g} +- {a_std:.2g}")
    trend = np.polyfit(t[late], history[late, 2], 1)[0]
    print(f"  alpha's trend over t > {after:.3g} s (least-squares line): {trend:+.3g} per s, "
          f"{trend * (t[-1] - after):+.3g} over the window")
    wall = 10 ** (-d / (2 * setup["radius"]))
    predictions = [("experiment", THESIS_U_0, THESIS_U_T)]
    for label, speed in speeds:
        predictions += [(label, u_0, speed), (label + ", wall", u_0, wall * speed)]
    for label, inflow, speed in predictions:
        alpha_rz = richardson_zaki(inflow, speed)
        print(f"  Richardson-Zaki, m = {RZ_INDEX}, u_0 = {inflow:.4g}, u_t = {speed:.4g} "
              f"({label}): alpha_rz = {alpha_rz:.4g}; simulated/rz - 1 = "
              f"{100 * (a_mean / alpha_rz - 1):+.1f} %")

    slab_alpha, slab_w = middle_slab(setup, series, after)
    print(f"  middle half of the bed over t > {after:.3g} s: alpha = {slab_alpha:.4g}, "
          f"beads' mean vertical velocity {slab_w:.4g} m/s")
    for label, inflow, speed in predictions[1:]:
        print(f"  Richardson-Zaki's velocity of a suspension of that alpha, u_t = "
              f"{speed:.4g} ({label}): {suspension_velocity(inflow, speed, slab_alpha):.4g} m/s")

    if check_bracket and not check_bracketed(a_mean, predictions):
        sys.exit(1)
    if doc:
        write_table(os.path.join(doc, "fluidized-bed.dat"), ["time", "h_b", "alpha"], history)
        write_table(os.path.join(doc, "fluidized-bed-bead.dat"), ["time", "z", "w"], bead_table)
        write_table(os.path.join(doc, "fluidized-bed-rz.dat"),
                    ["after"] + ["alpha_rz_" + label.replace(", ", "_").replace(" ", "_")
                                 for label, _, _ in predictions],
                    np.array([[after] + [richardson_zaki(i, v) for _, i, v in predictions]]))
        draw(doc)


def check_bracketed(alpha, predictions):
    """Whether alpha lies between the wall-corrected Richardson-Zaki
    predictions of the settling and the held bead; says which way it
    fails."""
    walls = {label: richardson_zaki(inflow, speed)
             for label, inflow, speed in predictions if label.endswith(", wall")}
    low, high = sorted(walls[name] for name in ("settling bead, wall", "held bead, wall"))
    if low <= alpha <= high:
        print(f"check: the bed's alpha {alpha:.4g} lies between the wall-corrected "
              f"predictions {low:.4g} and {high:.4g}")
        return True
    print(f"FAILED: the bed's alpha {alpha:.4g} lies outside the wall-corrected "
          f"Richardson-Zaki predictions of the settling and the held bead, "
          f"{low:.4g} .. {high:.4g}")
    return False


def draw(doc):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    _, history = read_table(os.path.join(doc, "fluidized-bed.dat"))
    _, bead = read_table(os.path.join(doc, "fluidized-bed-bead.dat"))
    names, ((after, *predictions),) = read_table(os.path.join(doc, "fluidized-bed-rz.dat"))
    fig, (ax_bead, ax_h, ax_a) = plt.subplots(1, 3, figsize=(13, 3.8))
    ax_bead.plot(bead[:, 0], -bead[:, 2], "k")
    ax_bead.axhline(THESIS_U_T, color="C3", ls="--", label="experiment: u_t = 0.226 m/s")
    ax_bead.set_xlabel("t [s]")
    ax_bead.set_ylabel("settling speed -w [m/s]")
    ax_bead.set_title("single bead in the closed column")
    ax_bead.legend(loc="lower right")
    ax_h.plot(history[:, 0], 100 * history[:, 1], "k")
    ax_h.set_xlabel("t [s]")
    ax_h.set_ylabel("bed height h_b = 2 mean(z - z_distributor) [cm]")
    ax_h.set_title("bed height")
    ax_a.plot(history[:, 0], history[:, 2], "k", label="simulated")
    for k, (value, name) in enumerate(zip(predictions, names[1:])):
        source = name[len("alpha_rz_"):].replace("_wall", " (wall)").replace("_", " ")
        ax_a.axhline(value, color=f"C{k + 1}", ls="--" if "wall" in name else "-",
                     label=f"Richardson-Zaki: {source}")
    for ax in (ax_h, ax_a):
        ax.axvspan(after, history[-1, 0], color="0.9", zorder=0)
    ax_a.set_xlabel("t [s]")
    ax_a.set_ylabel("solid fraction alpha_p")
    ax_a.set_ylim(0, 0.3)
    ax_a.set_title("solid fraction (eq. 6.6)")
    ax_a.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(doc, "fluidized-bed.png"), dpi=120)


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="*", metavar="RUN")
    parser.add_argument("--bead")
    parser.add_argument("--held-bead")
    parser.add_argument("--after", type=float)
    parser.add_argument("--doc")
    parser.add_argument("--check-bracket", action="store_true")
    parser.add_argument("--redraw", metavar="DIR")
    parser.add_argument("--label", help="the run's name (ignored; for the test driver)")
    args = parser.parse_args()
    if args.redraw:
        draw(args.redraw)
        return
    if len(args.runs) == 1 and args.bead:
        bed, bead, held = args.runs[0], args.bead, args.held_bead
    elif len(args.runs) == 3 and not (args.bead or args.held_bead):
        bead, held, bed = args.runs
    else:
        parser.error("give BED --bead BEAD, or BEAD HELD BED, or --redraw DIR")
    if args.check_bracket and not held:
        parser.error("--check-bracket needs the held bead's run")
    analyse(bed, bead, held, args.after, args.doc, args.check_bracket)


if __name__ == "__main__":
    main()
