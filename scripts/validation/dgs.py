#!/usr/bin/python3
"""The DGS sedimentation (thesis §6.7.1): a bed of spheres that sinks
through the liquid of a closed box, and the liquid it displaces, which
rises through the bed and lifts particles again before they settle.

    scripts/validation/dgs.py OUTPUT [--times T1 T2 T3] [--doc DIR]
        [--min-lifted N] [--max-moving F] [--min-rising M]
    scripts/validation/dgs.py --redraw DIR

reads the run in OUTPUT (particle_set.csv, particles.dat or
particle_<i>.dat, flow.pvd with its flow_<step>.*.vtu) and prints

- per particle its largest lift, max over t of z(t) - min_{s<=t} z(s): how
  far the liquid carried it up again after it had sunk; the number lifted
  by more than a radius and by more than a diameter;
- per flow snapshot, in the mid-plane between the front and back walls:
  the fastest rising and the fastest sinking liquid, and the fastest rising
  liquid within the bed's height (between the 10th and 90th percentiles of
  the particles' heights), against the single sphere's Stokes velocity;
- the particles still moving at the end.

With --min-lifted, --max-moving or --min-rising it exits with an error
naming each bound the run misses: fewer than N particles lifted by more than
a diameter, more than the fraction F of them faster than a tenth of the
Stokes velocity at the end, or the liquid never rising through the bed at M
times the Stokes velocity.

With --doc it writes into DIR the series dgs.dat (the heights of the three
most lifted particles and the bed's mean height against time),
dgs-slice.dat and dgs-slice-particles.dat (the mid-plane's velocity on a
coarse grid, and the particles' x and z, at the three snapshots nearest
--times) and draws dgs.png and dgs-twirl.png from them; --redraw draws
the figures again from DIR's series.
"""
import argparse
import csv
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from particulate_output import (  # noqa: E402
    flow_snapshots,
    read_flow_snapshot,
    read_parameters,
    read_particle_series,
    read_table,
    write_table,
)


def particles(folder):
    """Ids, radii and time series of the run's particles."""
    with open(os.path.join(folder, "particle_set.csv")) as f:
        rows = list(csv.DictReader(f))
    radii = np.array([(3 * float(r["volume"]) / (4 * math.pi)) ** (1 / 3)
                      for r in rows])
    series = read_particle_series(folder, [r["id"] for r in rows])
    return radii, series


def largest_lift(z):
    """max over t of z(t) - min_{s<=t} z(s)."""
    return float(np.max(z - np.minimum.accumulate(z)))


def mid_plane(folder, step, y_mid):
    """The velocity in the plane y = y_mid of snapshot `step`: the points'
    x, z and velocity, each point once."""
    points, arrays = read_flow_snapshot(folder, step, ["velocity"])
    span = np.ptp(points, axis=0).max()
    on = np.abs(points[:, 1] - y_mid) < 1e-6 * span
    if not on.any():
        sys.exit(f"{folder}: snapshot {step} has no output points on y = {y_mid}")
    xz = np.round(points[on][:, [0, 2]] / (1e-7 * span)).astype(np.int64)
    _, first = np.unique(xz, axis=0, return_index=True)
    chosen = np.flatnonzero(on)[first]
    return points[chosen], arrays["velocity"][chosen]


def stokes_velocity(folder, radius):
    """The single sphere's Stokes settling speed 2 (rho_p - rho_f) g r^2 /
    (9 mu), from the run's parameters and the first shape's density."""
    values = read_parameters(folder)
    rho_f = float(values["Fluid/Density"])
    mu = float(values["Fluid/Dynamic viscosity"])
    g = np.linalg.norm([float(v) for v in values["Particles/Gravity"].split(",")])
    with open(os.path.join(folder, "particle_set.csv")) as f:
        rho_p = float(next(csv.DictReader(f))["density"])
    return 2 * (rho_p - rho_f) * g * radius ** 2 / (9 * mu)


def grid_sample(points, velocity, cells):
    """The points of a plane's regular output grid thinned to about
    `cells` arrows across its longer side."""
    x, z = points[:, 0], points[:, 2]
    step_x = np.min(np.diff(np.unique(np.round(x, 9))))
    stride = max(1, int(round(np.ptp(x) / step_x / cells)))
    ix = np.round((x - x.min()) / step_x).astype(int)
    iz = np.round((z - z.min()) / step_x).astype(int)
    keep = (ix % stride == 0) & (iz % stride == 0)
    return np.column_stack([x[keep], z[keep], velocity[keep][:, 0],
                            velocity[keep][:, 2]])


def analyse(folder, times, doc, bounds=None):
    radii, series = particles(folder)
    time = series[0]["time"]
    heights = np.array([s["z"] for s in series])
    lifts = np.array([largest_lift(z) for z in heights])
    order = np.argsort(-lifts, kind="stable")
    r = radii.mean()
    print(f"{len(series)} particles, radius {r:.4g}; t = 0 .. {time[-1]:.4g}")
    print(f"lifted by more than a radius:   {int(np.sum(lifts > r))}")
    print(f"lifted by more than a diameter: {int(np.sum(lifts > 2 * r))}")
    print("most lifted: " + ", ".join(
        f"particle {i} by {lifts[i]:.4g} ({lifts[i] / (2 * r):.2f} d)" for i in order[:3]))
    speed = np.array([math.sqrt(s["u"][-1] ** 2 + s["v"][-1] ** 2 + s["w"][-1] ** 2)
                      for s in series])
    u_stokes = stokes_velocity(folder, r)
    print(f"single sphere's Stokes velocity: {u_stokes:.4g}")
    print(f"at the end: {int(np.sum(speed > 0.1 * u_stokes))} particles move faster "
          f"than a tenth of it; mean height {heights[:, -1].mean():.4g}")

    values = read_parameters(folder)
    lower = [float(v) for v in values["Mesh/Lower corner"].split(",")]
    upper = [float(v) for v in values["Mesh/Upper corner"].split(",")]
    y_mid = 0.5 * (lower[1] + upper[1])
    print("# time w_up w_down w_up_in_bed bed_z10 bed_z90   (mid-plane y = %g)" % y_mid)
    snapshots = flow_snapshots(folder)
    rising_in_bed = 0.
    for t, step in snapshots:
        points, velocity = mid_plane(folder, step, y_mid)
        k = min(np.searchsorted(time, t - 1e-12), len(time) - 1)
        z10, z90 = np.percentile(heights[:, k], [10, 90])
        in_bed = (points[:, 2] >= z10) & (points[:, 2] <= z90)
        w = velocity[:, 2]
        print(f"{t:.4g} {w.max():.4g} {w.min():.4g} {w[in_bed].max():.4g} "
              f"{z10:.4g} {z90:.4g}")
        if in_bed.any():
            rising_in_bed = max(rising_in_bed, w[in_bed].max())
    print(f"fastest liquid rising in the bed: {rising_in_bed:.4g}, "
          f"{rising_in_bed / u_stokes:.3g} times the Stokes velocity")
    if bounds:
        failures = check(bounds, int(np.sum(lifts > 2 * r)),
                         int(np.sum(speed > 0.1 * u_stokes)), len(series),
                         rising_in_bed / u_stokes)
        if failures:
            sys.exit("FAILED: " + "; ".join(failures))
        print("all checks passed")

    if doc:
        table = np.column_stack([time] + [heights[i] for i in order[:3]]
                                + [heights.mean(axis=0)])
        write_table(os.path.join(doc, "dgs.dat"),
                    ["time"] + [f"z_{i}" for i in order[:3]] + ["z_mean"], table)
        chosen = [min(snapshots, key=lambda s: abs(s[0] - t)) for t in times]
        slices, dots = [], []
        for t, step in chosen:
            points, velocity = mid_plane(folder, step, y_mid)
            sample = grid_sample(points, velocity, 24)
            slices.append(np.column_stack([np.full(len(sample), t), sample]))
            k = min(np.searchsorted(time, t - 1e-12), len(time) - 1)
            dots.append(np.column_stack([np.full(len(series), t),
                                         [s["x"][k] for s in series], heights[:, k]]))
        write_table(os.path.join(doc, "dgs-slice.dat"), ["time", "x", "z", "u", "w"],
                    np.concatenate(slices))
        write_table(os.path.join(doc, "dgs-slice-particles.dat"), ["time", "x", "z"],
                    np.concatenate(dots))
        draw(doc)


def check(bounds, lifted, moving, count, rising):
    """The run's physics against @p bounds: which of them it misses."""
    failures = []
    if bounds.min_lifted is not None and lifted < bounds.min_lifted:
        failures.append(f"{lifted} particles lifted by more than a diameter, "
                        f"fewer than {bounds.min_lifted}")
    if bounds.max_moving is not None and moving > bounds.max_moving * count:
        failures.append(f"{moving} of {count} particles still move at the end, "
                        f"more than {bounds.max_moving:g} of them")
    if bounds.min_rising is not None and rising < bounds.min_rising:
        failures.append(f"the liquid rises through the bed at {rising:.3g} times the "
                        f"Stokes velocity, less than {bounds.min_rising:g}")
    return failures


def draw(doc):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    header, table = read_table(os.path.join(doc, "dgs.dat"))
    fig, ax = plt.subplots(figsize=(6.4, 4))
    for j, name in enumerate(header[1:4], start=1):
        ax.plot(table[:, 0], table[:, j], label=f"particle {name[2:]}")
    ax.plot(table[:, 0], table[:, 4], "k--", label="mean of all particles")
    ax.set_xlabel("t")
    ax.set_ylabel("z")
    ax.set_title("DGS: heights of the three most lifted particles")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(doc, "dgs.png"), dpi=120)

    _, slices = read_table(os.path.join(doc, "dgs-slice.dat"))
    _, dots = read_table(os.path.join(doc, "dgs-slice-particles.dat"))
    times = np.unique(slices[:, 0])
    fig, axes = plt.subplots(1, len(times), figsize=(4.2 * len(times), 4.6),
                             squeeze=False)
    scale = np.abs(slices[:, 4]).max()
    levels = np.linspace(-scale, scale, 17)
    for ax, t in zip(axes[0], times):
        s = slices[slices[:, 0] == t]
        d = dots[dots[:, 0] == t]
        shade = ax.tricontourf(s[:, 1], s[:, 2], s[:, 4], levels=levels,
                               cmap="coolwarm")
        ax.plot(d[:, 1], d[:, 2], ".", color="0.25", markersize=1.5)
        ax.quiver(s[:, 1], s[:, 2], s[:, 3], s[:, 4], scale=15 * scale,
                  width=0.003)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t:.3g}")
        ax.set_xlabel("x")
    axes[0][0].set_ylabel("z")
    fig.colorbar(shade, ax=axes[0].tolist(), label="w, rising > 0",
                 shrink=0.8)
    fig.suptitle("DGS: the liquid's velocity in the mid-plane y = 0.125 "
                 "(arrows, w shaded); dots: all particles' x and z")
    fig.savefig(os.path.join(doc, "dgs-twirl.png"), dpi=110, bbox_inches="tight")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder", nargs="?")
    parser.add_argument("--times", nargs=3, type=float, default=[2, 4, 6])
    parser.add_argument("--doc")
    parser.add_argument("--redraw", metavar="DIR")
    parser.add_argument("--min-lifted", type=int,
                        help="fail if fewer particles are lifted by more than a diameter")
    parser.add_argument("--max-moving", type=float,
                        help="fail if a larger fraction of the particles moves faster than a "
                             "tenth of the Stokes velocity at the end")
    parser.add_argument("--min-rising", type=float,
                        help="fail if the liquid never rises through the bed faster than this "
                             "multiple of the Stokes velocity")
    parser.add_argument("--label", help="the run's name (ignored; for the test driver)")
    args = parser.parse_args()
    if args.redraw:
        draw(args.redraw)
    elif args.folder:
        checks = [args.min_lifted, args.max_moving, args.min_rising]
        analyse(args.folder, args.times, args.doc,
                args if any(c is not None for c in checks) else None)
    else:
        parser.error("give OUTPUT or --redraw DIR")


if __name__ == "__main__":
    main()
