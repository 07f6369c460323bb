#!/usr/bin/python3
"""Compare settling runs of one body given analytically and as surface meshes.

    scripts/mesh_body_equivalence.py ANALYTIC_DIR MESH_DIR [MESH_DIR ...]
        --map-spacing H [H ...] [--names NAME ...] [--label NAME] [--series FILE]
        [--figure FILE] [--max-speed-error PERCENT]
        [--max-tilt-difference DEGREES] [--max-rest-difference SPACINGS]

reads particle_0.dat of each run (the first the analytic body, the others
the same body as a surface mesh, with distance-map spacings H) and prints,
for each mesh run against the analytic one:

- the largest settling speed -w (the terminal velocity of the run), and
  its relative difference [%];
- the largest difference of the long axis's tilt from the horizontal over
  the whole run [degrees];
- the rest height of the centre at the end, its difference in map spacings.

--series writes time and, per run, settling speed and tilt (a small table);
--figure draws them. The --max-* options make it exit with 1 when the first
mesh run (the shipped one) is off by more.

    scripts/mesh_body_equivalence.py --redraw SERIES FIGURE

draws the figure again from a committed series.
"""
import argparse
import os
import sys

import numpy as np

from particulate_output import read_series, redraw_if_asked, write_table
from ten_cate_ellipsoid import long_axis_tilt


def load(folder):
    body = read_series(os.path.join(folder, "particle_0.dat"))
    if len(body["time"]) < 2:
        sys.exit("mesh_body_equivalence.py: %s holds no time steps" % folder)
    return body


def table_of(runs, names):
    """Time and, per run, settling speed and tilt, as columns over the
    steps all runs have."""
    n = min(len(b["time"]) for b in runs)
    columns = [runs[0]["time"][:n]]
    header = ["time"]
    for body, name in zip(runs, names):
        columns += [-body["w"][:n], long_axis_tilt(body)[:n]]
        header += ["speed_" + name, "tilt_" + name]
    return header, np.column_stack(columns)


def draw(path, header, table):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, (speed, tilt) = plt.subplots(1, 2, figsize=(10, 3.8))
    t = table[:, 0]
    for k in range(1, len(header), 2):
        name = header[k][len("speed_"):]
        style = "k-" if name == "analytic" else "--"
        speed.plot(t, table[:, k], style, label=name, lw=1)
        tilt.plot(t, table[:, k + 1], style, label=name, lw=1)
    speed.set_xlabel("t [s]")
    speed.set_ylabel("settling speed -w [m/s]")
    tilt.set_xlabel("t [s]")
    tilt.set_ylabel("long axis from horizontal [deg]")
    tilt.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=120)


def main():
    if redraw_if_asked(draw):
        return
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("analytic")
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--map-spacing", type=float, nargs="+", required=True)
    parser.add_argument("--names", nargs="+",
                        help="a short name per mesh run for the series and "
                        "the figure (default: its map spacing)")
    parser.add_argument("--label", default="")
    parser.add_argument("--series")
    parser.add_argument("--figure")
    parser.add_argument("--max-speed-error", type=float)
    parser.add_argument("--max-tilt-difference", type=float)
    parser.add_argument("--max-rest-difference", type=float)
    args = parser.parse_args()
    if len(args.map_spacing) != len(args.meshes):
        sys.exit("mesh_body_equivalence.py: give one --map-spacing per "
                 "mesh run")

    analytic = load(args.analytic)
    meshes = [load(folder) for folder in args.meshes]
    speed0 = (-analytic["w"]).max()
    tilt0 = long_axis_tilt(analytic)
    print("%s analytic: largest settling speed %.5f m/s, rest height "
          "%.4f mm at t = %.3f s"
          % (args.label, speed0, 1e3 * analytic["z"][-1],
             analytic["time"][-1]))
    failed = []
    for k, (body, h) in enumerate(zip(meshes, args.map_spacing)):
        n = min(len(body["time"]), len(analytic["time"]))
        speed_error = 100. * ((-body["w"]).max() / speed0 - 1.)
        tilt_difference = np.abs(long_axis_tilt(body)[:n] - tilt0[:n]).max()
        rest = (body["z"][n - 1] - analytic["z"][n - 1]) / h
        print("%s mesh, map spacing %.4g mm: settling speed %+.3f %%, "
              "tilt apart by at most %.2f deg, rest height %+.3f spacings "
              "(t = %.3f s)"
              % (args.label, 1e3 * h, speed_error, tilt_difference, rest,
                 body["time"][n - 1]))
        if k == 0:
            for value, bound, what in (
                    (abs(speed_error), args.max_speed_error,
                     "settling speed error [%]"),
                    (tilt_difference, args.max_tilt_difference,
                     "tilt difference [deg]"),
                    (abs(rest), args.max_rest_difference,
                     "rest height difference [map spacings]")):
                if bound is not None and not value <= bound:
                    failed.append("%s %.3g > %g" % (what, value, bound))

    names = ["analytic"] + (args.names or ["h=%.3gmm" % (1e3 * h)
                                          for h in args.map_spacing])
    header, table = table_of([analytic] + meshes, names)
    if args.series:
        write_table(args.series, header, table)
    if args.figure:
        draw(args.figure, header, table)
    for f in failed:
        print("FAILED: " + f)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
