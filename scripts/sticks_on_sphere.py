#!/usr/bin/python3
"""Where sticks settling onto a fixed sphere end up.

    scripts/sticks_on_sphere.py RUN_DIR --sphere X Y Z R --reach L
        [--series FILE] [--figure FILE] [--series-every N]
        [--check-end T --max-penetration D] [--label NAME]

reads the run's particle_set.csv, the free particles' particle_<i>.dat and
flow.dat, and prints per output row and at the end how many sticks lie on
the sphere (centre closer to the sphere's centre than R + L, L the stick's
half length plus its radius, and above the sphere's centre height minus R),
how many have fallen past it, the largest speed and the deepest overlap
(flow.dat's max_penetration). With --check-end and --max-penetration it
exits 1 unless the run reached t = T and no overlap was ever deeper than D.

    scripts/sticks_on_sphere.py --redraw SERIES FIGURE

draws the figure again from a committed series.
"""
import argparse
import csv
import os

import numpy as np

from particulate_output import (read_particle_series, read_series,
                                redraw_if_asked, write_table)


def free_bodies(folder):
    with open(os.path.join(folder, "particle_set.csv")) as f:
        ids = [int(row["id"]) for row in csv.DictReader(f)
               if row["motion"] == "free"]
    return read_particle_series(folder, ids)


def draw(path, header, table):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, (count, speed) = plt.subplots(1, 2, figsize=(10, 3.6))
    t = table[:, 0]
    count.plot(t, table[:, header.index("on_sphere")], label="on the sphere")
    count.plot(t, table[:, header.index("below")], label="fallen past it")
    count.set_xlabel("t [s]")
    count.set_ylabel("sticks")
    count.legend(fontsize=8)
    speed.semilogy(t, np.maximum(table[:, header.index("largest_speed")],
                                 1e-6))
    speed.set_xlabel("t [s]")
    speed.set_ylabel("largest stick speed [m/s]")
    figure.tight_layout()
    figure.savefig(path, dpi=120)


def main():
    if redraw_if_asked(draw):
        return
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run")
    parser.add_argument("--sphere", type=float, nargs=4, required=True)
    parser.add_argument("--reach", type=float, required=True)
    parser.add_argument("--series")
    parser.add_argument("--series-every", type=int, default=10)
    parser.add_argument("--figure")
    parser.add_argument("--label", default="",
                        help="the run's name (ignored; the test runner "
                        "passes it)")
    parser.add_argument("--check-end", type=float)
    parser.add_argument("--max-penetration", type=float)
    args = parser.parse_args()
    centre, radius = np.array(args.sphere[:3]), args.sphere[3]

    bodies = free_bodies(args.run)
    flow = read_series(os.path.join(args.run, "flow.dat"))
    n = min([len(b["time"]) for b in bodies] + [len(flow["time"])])
    rows = []
    for k in range(n):
        positions = np.array([[b["x"][k], b["y"][k], b["z"][k]]
                              for b in bodies])
        distance = np.linalg.norm(positions - centre, axis=1)
        on = np.sum((distance < radius + args.reach)
                    & (positions[:, 2] > centre[2] - radius))
        below = np.sum(positions[:, 2] < centre[2])
        speed = max(np.linalg.norm([b["u"][k], b["v"][k], b["w"][k]])
                    for b in bodies)
        rows.append([flow["time"][k], on, below, speed,
                     flow["max_penetration"][k]])
    table = np.array(rows)
    print("%d sticks, %d rows to t = %.3f s: at the end %d on the sphere, "
          "%d fallen past it, largest speed %.3g m/s; deepest overlap of "
          "the run %.3g mm"
          % (len(bodies), n, table[-1, 0], table[-1, 1], table[-1, 2],
             table[-1, 3], 1e3 * table[:, 4].max()))
    header = ["time", "on_sphere", "below", "largest_speed", "overlap"]
    if args.series:
        write_table(args.series, header, table, args.series_every)
    if args.figure:
        draw(args.figure, header, table)
    failed = []
    if args.check_end is not None and table[-1, 0] < args.check_end - 1e-9:
        failed.append("the run ends at t = %g s, before %g s"
                      % (table[-1, 0], args.check_end))
    if (args.max_penetration is not None
            and table[:, 4].max() > args.max_penetration):
        failed.append("an overlap of %.3g mm exceeds %.3g mm"
                      % (1e3 * table[:, 4].max(), 1e3 * args.max_penetration))
    for message in failed:
        print("FAIL: " + message)
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
