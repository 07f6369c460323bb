#!/usr/bin/python3
"""Check a run of bodies poured through a funnel into a basket.

    scripts/funnel_basket.py RUN_DIR [RUN_DIR ...] --basket-radius R
        --basket-floor Z0 --basket-rim Z1 [--label NAME] [--series FILE]
        [--figure FILE] [--names NAME ...] [--max-penetration M]
        [--max-final-energy FRACTION]

reads each run's particle_set.csv (which particles are free), the free
particles' particle_<i>.dat and flow.dat, and prints:

- the deepest overlap of any step (flow.dat's max_penetration: how far two
  surfaces came closer than the contact distance);
- at the end: how many free bodies have their centre inside the basket
  (within radius R of its axis x = y = 0, between heights Z0 and Z1), the
  largest speed among them, and their kinetic energy as a fraction of the
  potential energy they released on the way down (sum of m g (z_0 - z)).

--series writes time and, per run, the number of bodies in the basket, the
largest speed and the deepest overlap (a small table); --figure draws them.
The --max-* options make it exit with 1 when the last run has an overlap
deeper than M at some step, or, at the end, a free body that is not in the
basket or a kinetic energy above FRACTION of the released one.

    scripts/funnel_basket.py --redraw SERIES FIGURE

draws the figure again from a committed series.
"""
import argparse
import csv
import os
import sys

import numpy as np

from particulate_output import (read_parameters, read_particle_series,
                                read_series, redraw_if_asked, write_table)


def free_particles(folder):
    """The free particles' numbers and masses."""
    with open(os.path.join(folder, "particle_set.csv")) as f:
        rows = [row for row in csv.DictReader(f) if row["motion"] == "free"]
    return [int(row["id"]) for row in rows], [float(row["mass"])
                                              for row in rows]


def gravity(folder):
    values = read_parameters(folder)["Particles/Gravity"].split(",")
    return np.linalg.norm([float(g) for g in values])


def released_energy(bodies, masses, g, k):
    """Potential energy the bodies released from the start to row k."""
    return sum(m * g * (b["z"][0] - b["z"][k]) for b, m in zip(bodies, masses))


def load(folder):
    ids, masses = free_particles(folder)
    bodies = read_particle_series(folder, ids)
    if not bodies:
        sys.exit("funnel_basket.py: %s has no free particles" % folder)
    flow = read_series(os.path.join(folder, "flow.dat"))
    n = min([len(b["time"]) for b in bodies] + [len(flow["time"])])
    if n < 2:
        sys.exit("funnel_basket.py: %s holds no time steps" % folder)
    return bodies, masses, flow, n


def in_basket(bodies, k, radius, floor, rim):
    return sum(1 for b in bodies
               if np.hypot(b["x"][k], b["y"][k]) < radius
               and floor < b["z"][k] < rim)


def largest_speed(bodies, k):
    return max(np.linalg.norm([b["u"][k], b["v"][k], b["w"][k]])
               for b in bodies)


def columns_of(folder, args):
    """Time and the run's bodies in the basket, largest speed and deepest
    overlap at each row; the number of free bodies; their kinetic energy
    over the potential energy they released, at the end."""
    bodies, masses, flow, n = load(folder)
    counts = [in_basket(bodies, k, args.basket_radius, args.basket_floor,
                        args.basket_rim) for k in range(n)]
    speeds = [largest_speed(bodies, k) for k in range(n)]
    energy = sum(b["kinetic_energy"][n - 1] for b in bodies) / \
        released_energy(bodies, masses, gravity(folder), n - 1)
    return (flow["time"][:n], np.array(counts, float), np.array(speeds),
            flow["max_penetration"][:n], len(bodies), energy)


def table_of(runs, names):
    n = min(len(run[0]) for run in runs)
    header, columns = ["time"], [runs[0][0][:n]]
    for run, name in zip(runs, names):
        header += ["in_basket_" + name, "largest_speed_" + name,
                   "overlap_" + name]
        columns += [run[1][:n], run[2][:n], run[3][:n]]
    return header, np.column_stack(columns)


def draw(path, header, table):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, (count, speed, overlap) = plt.subplots(1, 3, figsize=(13, 3.6))
    t = table[:, 0]
    for k in range(1, len(header), 3):
        name = header[k][len("in_basket_"):]
        count.plot(t, table[:, k], label=name, lw=1)
        speed.semilogy(t, np.maximum(table[:, k + 1], 1e-6), label=name,
                       lw=1)
        overlap.plot(t, 1e3 * table[:, k + 2], label=name, lw=1)
    count.set_xlabel("t [s]")
    count.set_ylabel("bodies in the basket")
    speed.set_xlabel("t [s]")
    speed.set_ylabel("largest body speed [m/s]")
    overlap.set_xlabel("t [s]")
    overlap.set_ylabel("deepest overlap [mm]")
    count.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=120)


def main():
    if redraw_if_asked(draw):
        return
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--basket-radius", type=float, required=True)
    parser.add_argument("--basket-floor", type=float, required=True)
    parser.add_argument("--basket-rim", type=float, required=True)
    parser.add_argument("--names", nargs="+",
                        help="a short name per run (default: its folder)")
    parser.add_argument("--label", default="")
    parser.add_argument("--series")
    parser.add_argument("--series-every", type=int, default=10,
                        help="write every this many rows to --series")
    parser.add_argument("--figure")
    parser.add_argument("--max-penetration", type=float)
    parser.add_argument("--max-final-energy", type=float)
    args = parser.parse_args()
    names = args.names or [os.path.basename(os.path.normpath(r))
                           for r in args.runs]
    if len(names) != len(args.runs):
        sys.exit("funnel_basket.py: give one --names entry per run")

    runs = [columns_of(folder, args) for folder in args.runs]
    failed = []
    for k, (run, name) in enumerate(zip(runs, names)):
        time, counts, speeds, overlaps, n_free, energy = run
        print("%s %s: %d steps to t = %.3f s; deepest overlap %.3g mm "
              "(at t = %.3f s); at the end %d of %d free bodies in the "
              "basket, largest speed %.3g m/s, kinetic energy %.3g of the "
              "released potential energy"
              % (args.label, name, len(time) - 1, time[-1],
                 1e3 * overlaps.max(), time[overlaps.argmax()],
                 int(counts[-1]), n_free, speeds[-1], energy))
        if k == len(runs) - 1:
            if (args.max_penetration is not None
                    and not overlaps.max() <= args.max_penetration):
                failed.append("deepest overlap %.3g m > %g m"
                              % (overlaps.max(), args.max_penetration))
            if args.max_final_energy is not None:
                if counts[-1] != n_free:
                    failed.append("%d of %d free bodies are not in the "
                                  "basket at the end"
                                  % (n_free - counts[-1], n_free))
                if not energy <= args.max_final_energy:
                    failed.append("final kinetic energy %.3g of the released "
                                  "one > %g" % (energy, args.max_final_energy))
    if args.series or args.figure:
        header, table = table_of(runs, names)
        if args.series:
            write_table(args.series, header, table, args.series_every)
        if args.figure:
            draw(args.figure, header, table)
    if failed:
        print("FAILED: " + "; ".join(failed))
        sys.exit(1)


if __name__ == "__main__":
    main()
