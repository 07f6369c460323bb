#!/usr/bin/env python3
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
import base64
import glob
import os
import re
import struct
import sys
import zlib

import numpy as np


def read_points(path):
    """The Points array of a VTU file as an (n, 3) array."""
    with open(path) as f:
        text = f.read()
    match = re.search(r"<Points>\s*<DataArray[^>]*>\s*([^<]*)</DataArray>", text)
    if not match or 'compressor="vtkZLibDataCompressor"' not in text:
        sys.exit(f"{path}: not a zlib-compressed binary VTU file with points")
    data = match.group(1).strip()
    # header: number of blocks, block size, last block size, then the
    # compressed size of every block, as uint32, base64-encoded on its own
    n_blocks = struct.unpack("<I", base64.b64decode(data[:8])[:4])[0]
    header_bytes = 4 * (3 + n_blocks)
    header_chars = (header_bytes + 2) // 3 * 4
    header = struct.unpack(
        "<%dI" % (3 + n_blocks), base64.b64decode(data[:header_chars])[:header_bytes]
    )
    raw = base64.b64decode(data[header_chars:])
    values, offset = b"", 0
    for size in header[3:]:
        values += zlib.decompress(raw[offset : offset + size])
        offset += size
    return np.frombuffer(values, dtype="<f4").reshape(-1, 3)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--centre", nargs=3, type=float, required=True)
    parser.add_argument("--radius", type=float, required=True)
    args = parser.parse_args()
    centre = np.array(args.centre)
    print("# run cut_cells mean_edge_of_cut_cells[m]")
    for folder in args.folders:
        files = sorted(glob.glob(os.path.join(folder, "flow_00000.*.vtu")))
        if not files:
            sys.exit(f"{folder}: no flow_00000.*.vtu (the first snapshot)")
        points = np.concatenate([read_points(f) for f in files])
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
