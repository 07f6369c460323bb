#!/usr/bin/python3
"""Write a closed, outward-oriented triangulation of an ellipsoid as an OFF
file: an icosahedron refined k times (20 * 4^k triangles), its vertices
projected onto the unit sphere and scaled by the semi-axes. The vertices lie
on the ellipsoid; the polyhedron is inscribed in it.

Usage: scripts/make_ellipsoid_mesh.py A B C --refinements K -o FILE.off
(semi-axes in the file's length unit)."""
import argparse

import numpy as np


def icosphere(refinements):
    t = (1.0 + 5.0 ** 0.5) / 2.0
    vertices = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0),
                (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
                (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    vertices = [np.array(v, float) / np.linalg.norm(v) for v in vertices]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11),
             (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
             (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
             (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(refinements):
        midpoint = {}

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint:
                m = vertices[a] + vertices[b]
                vertices.append(m / np.linalg.norm(m))
                midpoint[key] = len(vertices) - 1
            return midpoint[key]

        refined = []
        for a, b, c in faces:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            refined += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = refined
    return np.array(vertices), faces


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("semi_axes", type=float, nargs=3)
    parser.add_argument("--refinements", type=int, default=4)
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    vertices, faces = icosphere(args.refinements)
    vertices = vertices * np.array(args.semi_axes)
    with open(args.output, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        for v in vertices:
            out.write("%.9g %.9g %.9g\n" % tuple(v))
        for f in faces:
            out.write("3 %d %d %d\n" % f)


if __name__ == "__main__":
    main()
