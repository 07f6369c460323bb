#!/usr/bin/python3
"""How finely a mesh resolves a sphere: the cells that its surface cuts.

Reads the first ParaView snapshot of each run folder (flow_00000.*.vtu, all
ranks; deal.II's zlib-compressed binary VTU with 27 points per cell, i.e.
one subdivision of each Q2 cell) and reports, for the cells with output
points (corners, edge and face midpoints, centre) on both sides of the
sphere |x - c| = R: how many there are and their mean edge length (cube
root of the corners' bounding-box volume). A mesh adapted to the sphere has
more, smaller cut cells than the regular mesh.

  scripts/validation/sphere_cut_cells.py output/ten-cate-e4-r0 \
      output/ten-cate-e4-r0-kappa --centre 0 0 0.1275 --radius 0.0075
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from particulate_output import read_flow_snapshot  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--centre", nargs=3, type=float, required=True)
    parser.add_argument("--radius", type=float, required=True)
    args = parser.parse_args()
    centre = np.array(args.centre)
    print("# run cut_cells mean_edge_of_cut_cells[m]")
    for folder in args.folders:
        points, _ = read_flow_snapshot(folder, 0)
        if points.shape[0] % 27:
            sys.exit(f"{folder}: expected 27 points per cell (3D, one subdivision)")
        cells = points.reshape(-1, 27, 3)
        corners = cells[:, [0, 2, 6, 8, 18, 20, 24, 26], :]
        # the sign test on all 27 points: a cut between corners counts too
        distance = np.linalg.norm(cells - centre, axis=2) - args.radius
        cut = (distance.min(axis=1) < 0) & (distance.max(axis=1) > 0)
        volume = np.prod(corners.max(axis=1) - corners.min(axis=1), axis=1)
        edge = np.cbrt(volume[cut]).mean() if cut.any() else float("nan")
        print(f"{folder} {int(cut.sum())} {edge:.4e}")


if __name__ == "__main__":
    main()
