#!/usr/bin/python3
"""Write a closed, outward-oriented triangulation of a solid of revolution
about the z axis as an OFF file: a closed profile polygon in the (r, z)
half-plane turned through 360 degrees in N segments. Profile points with
r = 0 become one vertex on the axis (a pole). Two shapes for containers:

  funnel: a conical wall of thickness T from radius R_TOP at height H down
          to the outlet radius R_OUT at height 0 (a frustum shell, open at
          both ends: the solid is a ring, genus 1);
  basket: a cup of outer radius R, height H, wall and floor thickness T,
          standing on z = 0 (genus 0);
  capsule: a stick of radius R whose core segment of length L runs along z,
          with hemispherical caps, centred at the origin.

Usage: scripts/make_revolved_mesh.py funnel R_TOP R_OUT H T [-n N] -o FILE.off
       scripts/make_revolved_mesh.py basket R H T [-n N] -o FILE.off
       scripts/make_revolved_mesh.py capsule R L [-n N] -o FILE.off
(lengths in the file's unit)."""
import argparse
import math

import numpy as np


def funnel_profile(r_top, r_out, height, thickness):
    # the inner surface runs from (r_out, 0) up to (r_top, height) at the
    # angle theta to the horizontal; the outer one is parallel to it,
    # thickness T away, i.e. T / sin(theta) further out at every height; the
    # rims are flat
    theta = math.atan2(height, r_top - r_out)
    shift = thickness / math.sin(theta)
    return [(r_out, 0.0), (r_out + shift, 0.0), (r_top + shift, height),
            (r_top, height)]


def basket_profile(radius, height, thickness):
    return [(0.0, 0.0), (radius, 0.0), (radius, height),
            (radius - thickness, height), (radius - thickness, thickness),
            (0.0, thickness)]


def capsule_profile(radius, length, arc_points=6):
    """From the bottom pole up the cap, the side and over the top cap."""
    profile = []
    for k in range(arc_points + 1):
        phi = -0.5 * math.pi + 0.5 * math.pi * k / arc_points
        profile.append((radius * math.cos(phi),
                        -0.5 * length + radius * math.sin(phi)))
    for k in range(arc_points + 1):
        phi = 0.5 * math.pi * k / arc_points
        profile.append((radius * math.cos(phi),
                        0.5 * length + radius * math.sin(phi)))
    # the poles exactly on the axis
    profile[0] = (0.0, profile[0][1])
    profile[-1] = (0.0, profile[-1][1])
    return profile


def revolve(profile, segments):
    """Vertices and triangles of the profile (closed polygon, no point
    repeated) turned about z."""
    vertices, index = [], []
    for r, z in profile:
        if r == 0.0:
            index.append([len(vertices)] * segments)
            vertices.append((0.0, 0.0, z))
        else:
            ring = []
            for k in range(segments):
                phi = 2.0 * math.pi * k / segments
                ring.append(len(vertices))
                vertices.append((r * math.cos(phi), r * math.sin(phi), z))
            index.append(ring)
    faces = []
    n = len(profile)
    for i in range(n):
        a, b = index[i], index[(i + 1) % n]
        for k in range(segments):
            k1 = (k + 1) % segments
            quad = (a[k], b[k], b[k1], a[k1])
            # drop the degenerate triangle at a pole
            for tri in ((quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])):
                if len(set(tri)) == 3:
                    faces.append(tri)
    vertices = np.array(vertices)
    # orient outwards: positive signed volume
    volume = sum(np.dot(vertices[a], np.cross(vertices[b], vertices[c]))
                 for a, b, c in faces) / 6.0
    if volume < 0.0:
        faces = [(a, c, b) for a, b, c in faces]
    return vertices, faces, abs(volume)


def write_off(path, vertices, faces):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        for v in vertices:
            out.write("%.10g %.10g %.10g\n" % tuple(v))
        for f in faces:
            out.write("3 %d %d %d\n" % f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("shape", choices=["funnel", "basket", "capsule"])
    parser.add_argument("sizes", type=float, nargs="+")
    parser.add_argument("-n", "--segments", type=int, default=64)
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    expected = {"funnel": 4, "basket": 3, "capsule": 2}[args.shape]
    if len(args.sizes) != expected or min(args.sizes) <= 0.0:
        parser.error("%s takes %d positive sizes" % (args.shape, expected))
    profile = {"funnel": funnel_profile, "basket": basket_profile,
               "capsule": capsule_profile}[args.shape](*args.sizes)
    vertices, faces, volume = revolve(profile, args.segments)
    write_off(args.output, vertices, faces)
    print("%s: %d vertices, %d triangles, volume %.6g" %
          (args.output, len(vertices), len(faces), volume))


if __name__ == "__main__":
    main()
