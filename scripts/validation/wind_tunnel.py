#!/usr/bin/python3
"""The virtual wind tunnel (thesis §6.6): how the flow mesh sees CGAL's
elephant, adapted by Laplace-kappa or not, and the drag on it, per level.

    scripts/validation/wind_tunnel.py FOLDER ... [--doc doc/validation] [--check]
    scripts/validation/wind_tunnel.py --redraw SERIES FIGURE

reads the output folders of prm/wind-tunnel/ cases (those of
scripts/validation/wind_tunnel.sh, or of the cases as shipped) and prints a
Markdown table per case and level:
cells, unknowns, the fine cell size h, what the run's surface_resolution.dat
says (solid cells, Hausdorff distance, mean face distance, volume error), the
last drag F_x and how much it changed over the last quarter of the run, and
the wall time (a run stopped after its set-up gives the geometry alone). With --doc it writes wind-tunnel.dat (the table) and
wind-tunnel.png (the distances and the drag against h) there. --check
(ctest -R validation_wind_tunnel) fails unless on every level run both ways
the adapted mesh's faces lie nearer the surface on average (the Hausdorff
distance is printed: where features thinner than a cell set it, the
adaptation does not move it), and every run's drag changed by less than
MAX_DRAG_CHANGE over its last quarter (a steady state).
"""
import argparse
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from particulate_output import (read_parameters, read_series,  # noqa: E402
                                read_table, redraw_if_asked, write_table)

MAX_DRAG_CHANGE = 1e-3
HEADER = ["adapted", "level", "h", "cells", "dofs", "solid_cells",
          "hausdorff", "mean_face_distance", "volume_error", "drag",
          "drag_change", "wall_s"]


def from_log(folder):
    """Cells, unknowns and the wall time from the run's log (unknown
    without one: the validation runner keeps none)."""
    cells = dofs = wall = np.nan
    path = os.path.join(folder, "run.log")
    if not os.path.exists(path):
        return cells, dofs, wall
    with open(path) as f:
        for line in f:
            m = re.match(r"Mesh: (\d+) cells, (\d+) DoFs", line)
            if m:
                cells, dofs = int(m.group(1)), int(m.group(2))
            m = re.search(r"Total wallclock time elapsed\s*\|\s*([\d.]+)s", line)
            if m:
                wall = float(m.group(1))
    return cells, dofs, wall


def row(folder):
    """One row of the table from a run's folder."""
    prm = read_parameters(folder)
    level = int(prm["Mesh/Refinements"])
    h = float(prm["Mesh/Fine cell size"]) / 2**level
    adapted = prm["Mesh deformation/Method"] != "none"
    resolution = np.loadtxt(os.path.join(folder, "surface_resolution.dat"),
                            usecols=(2, 3, 4, 5), ndmin=2)[0]
    body = read_series(os.path.join(folder, "particle_0.dat"))
    t, drag = body["time"], body["F_x"]
    if t[-1] > 0:
        quarter = drag[t >= 0.75 * t[-1]]
        change = abs(quarter[-1] - quarter[0]) / abs(quarter[-1])
    else:  # stopped after the set-up: the geometry only
        drag, change = [np.nan], np.nan
    cells, dofs, wall = from_log(folder)
    return [int(adapted), level, h, cells, dofs, *resolution, drag[-1],
            change, wall]


def draw(figure, header, table):
    col = {name: i for i, name in enumerate(header)}
    fig, (geo, force) = plt.subplots(1, 2, figsize=(10, 4))
    for adapted, label, style in ((0, "not adapted", "o--"),
                                  (1, "Laplace-κ", "s-")):
        rows = table[table[:, col["adapted"]] == adapted]
        rows = rows[np.argsort(rows[:, col["h"]])]
        if not len(rows):
            continue
        h = rows[:, col["h"]]
        geo.loglog(h, rows[:, col["hausdorff"]], style, label=f"Hausdorff, {label}")
        geo.loglog(h, rows[:, col["mean_face_distance"]], style, mfc="none",
                   label=f"mean face distance, {label}")
        has_drag = ~np.isnan(rows[:, col["drag"]])
        force.plot(h[has_drag], rows[has_drag, col["drag"]], style, label=label)
    geo.set_xlabel("fine cell size h [m] (elephant height 1 m)")
    geo.set_ylabel("distance to the surface [m]")
    geo.legend(fontsize=8)
    force.set_xlabel("fine cell size h [m]")
    force.set_ylabel("drag F_x [N]")
    force.invert_xaxis()
    force.legend()
    fig.tight_layout()
    fig.savefig(figure, dpi=110)


def main():
    if redraw_if_asked(draw):
        return
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--doc", help="folder for wind-tunnel.dat and .png")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--label", help="(ignored; the validation runner's)")
    args = parser.parse_args()
    table = np.array(sorted((row(f) for f in args.folders),
                            key=lambda r: (r[0], r[1])))
    print("| mesh | level | h [m] | cells | unknowns | solid cells | Hausdorff [m] "
          "| mean face distance [m] | volume error | drag F_x [N] "
          "| change, last quarter | wall [s] |\n|" + "---|" * 12)
    def shown(value, form):
        return "—" if np.isnan(value) else format(value, form)

    for r in table:
        print(f"| {'Laplace-κ' if r[0] else 'not adapted'} | {int(r[1])} "
              f"| {r[2]:.4g} | {shown(r[3], '.0f')} | {shown(r[4], '.0f')} "
              f"| {int(r[5])} "
              f"| {r[6]:.4f} | {r[7]:.5f} | {100 * r[8]:+.2f} % "
              f"| {shown(r[9], '.5f')} | {shown(r[10], '.1e')} "
              f"| {shown(r[11], '.0f')} |")
    if args.doc:
        series = os.path.join(args.doc, "wind-tunnel.dat")
        write_table(series, HEADER, table)
        draw(os.path.join(args.doc, "wind-tunnel.png"), *read_table(series))
    if args.check:
        sys.exit(0 if check(table) else 1)


def check(table):
    """The checks of --check, printed."""
    col = {name: i for i, name in enumerate(HEADER)}
    ok = True
    for r in table[~np.isnan(table[:, col["drag"]])]:
        steady = r[col["drag_change"]] < MAX_DRAG_CHANGE
        print(f"{'ok' if steady else 'FAIL'}: level {int(r[1])}, "
              f"{'adapted' if r[0] else 'not adapted'}: drag changed by "
              f"{r[col['drag_change']]:.1e} over the last quarter "
              f"(bound {MAX_DRAG_CHANGE:g})")
        ok &= steady
    for level in sorted(set(table[:, col["level"]])):
        rows = {int(r[0]): r for r in table if r[col["level"]] == level}
        if len(rows) < 2:
            continue
        plain, adapted = rows[0], rows[1]
        closer = (adapted[col["mean_face_distance"]]
                  < plain[col["mean_face_distance"]])
        print(f"{'ok' if closer else 'FAIL'}: level {int(level)}: "
              f"mean face distance {adapted[col['mean_face_distance']]:.4f} m "
              f"adapted, {plain[col['mean_face_distance']]:.4f} m not "
              f"(Hausdorff distance {adapted[col['hausdorff']]:.4f} m against "
              f"{plain[col['hausdorff']]:.4f} m)")
        ok &= closer
    return ok


if __name__ == "__main__":
    main()
