#!/usr/bin/python3
"""Check that the disks or spheres of a particulate-flow run settled into a
pile at rest, without ever overlapping each other or the walls.

    scripts/validation/settled_pile.py OUTPUT [--label NAME]
        [--rest-speed 0.005] [--support-gap CELLS]

reads OUTPUT/particle_set.csv (shapes' volumes: the radius of a disk per
unit depth, r = sqrt(V/pi), or of a sphere), OUTPUT/particle_<n>.dat (or
the shared particles.dat) and the box of OUTPUT/used_parameters.prm, and
exits 1 unless

- at every step every body lies inside the box (a 'column' mesh: inside
  its mantle) and no two bodies overlap (centres at least r_i + r_j apart);
- at the end every body moves slower than --rest-speed [m/s] and lies lower
  than it started;
- at the end every body is supported: its lowest point is within
  --support-gap contact distances (default 2) of the floor, or it touches a
  body whose centre lies below its own within that gap.

The floor is the mesh's lowest face, or the distributor at 'Distributor
height' where the case has one (the bodies may not cross it either).

The prm/quickstart case is checked this way (test fbm_quickstart_settles).
"""
import argparse
import csv
import math
import os
import sys

import numpy as np
from used_parameters import used_value

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from particulate_output import read_parameters, read_particle_series  # noqa: E402


def bodies(folder):
    """Radius and series of every body, in id order."""
    with open(os.path.join(folder, "particle_set.csv")) as f:
        rows = list(csv.DictReader(f))
    dim = 3 if any(float(r["z"]) != 0 for r in rows) else 2
    result = []
    series = read_particle_series(folder, [r["id"] for r in rows])
    for r, s in zip(rows, series):
        volume = float(r["volume"])
        radius = (math.sqrt(volume / math.pi) if dim == 2 else
                  (3 * volume / (4 * math.pi)) ** (1 / 3))
        result.append((radius, s))
    return dim, result


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder")
    parser.add_argument("--label", default=None)
    parser.add_argument("--rest-speed", type=float, default=0.005)
    parser.add_argument("--support-gap", type=float, default=2.)
    args = parser.parse_args()
    label = args.label or os.path.basename(args.folder.rstrip("/"))

    dim, body = bodies(args.folder)
    axes = ["x", "y", "z"][:dim]
    up = axes[-1]
    lower = [float(v) for v in
             used_value(args.folder, "Lower corner").split(",")][:dim]
    upper = [float(v) for v in
             used_value(args.folder, "Upper corner").split(",")][:dim]
    steps = min(len(s["time"]) for _, s in body)
    position = np.stack([[s[a][:steps] for a in axes] for _, s in body])
    radius = np.array([r for r, _ in body])
    tolerance = 1e-9 * max(u - lo for u, lo in zip(upper, lower))
    failures = []
    distributor = read_parameters(args.folder).get("Particles/Distributor height", "")
    if distributor:
        lower[-1] = float(distributor)

    # inside the box (raised to the distributor) at every step; a column:
    # inside its mantle
    column = read_parameters(args.folder).get("Mesh/Type") == "column"
    if column:
        centre = [0.5 * (lower[d] + upper[d]) for d in range(2)]
        mantle = 0.5 * min(upper[0] - lower[0], upper[1] - lower[1])
        reach = np.hypot(position[:, 0, :] - centre[0],
                         position[:, 1, :] - centre[1]) + radius[:, None]
        if reach.max() > mantle + tolerance:
            failures.append(f"a body crosses the mantle "
                            f"(by {reach.max() - mantle:.3g} m)")
    for d, axis in enumerate(axes):
        if column and d < 2:
            continue
        low = position[:, d, :] - radius[:, None] - lower[d]
        high = upper[d] - position[:, d, :] - radius[:, None]
        if low.min() < -tolerance or high.min() < -tolerance:
            failures.append(f"a body crosses a wall normal to {axis} "
                            f"(by {-min(low.min(), high.min()):.3g} m)")
    # no two bodies overlap at any step
    n = len(body)
    closest = math.inf
    for i in range(n):
        for j in range(i + 1, n):
            distance = np.linalg.norm(position[i] - position[j], axis=0)
            closest = min(closest,
                          (distance - radius[i] - radius[j]).min())
    if closest < -tolerance:
        failures.append(f"two bodies overlap by {-closest:.3g} m")

    # at rest at the end, lower than at the start, supported
    gap = args.support_gap * float(
        used_value(args.folder, "Contact distance")
        if used_value(args.folder, "Contact distance") != "auto"
        else cell_size(args.folder, lower, upper))
    end = position[:, :, -1]
    for k, (_, s) in enumerate(body):
        speed = math.sqrt(sum(s[v][steps - 1] ** 2
                              for v in ["u", "v", "w"][:dim]))
        if speed > args.rest_speed:
            failures.append(f"body {k} still moves at {speed:.3g} m/s")
        if end[k, -1] >= position[k, -1, 0]:
            failures.append(f"body {k} did not settle (ended at {up} = "
                            f"{end[k, -1]:.4g} m, started at "
                            f"{position[k, -1, 0]:.4g} m)")
        on_floor = end[k, -1] - radius[k] - lower[-1] <= gap
        on_body = any(
            end[j, -1] < end[k, -1]
            and np.linalg.norm(end[k] - end[j]) - radius[k] - radius[j] <= gap
            for j in range(n) if j != k)
        if not (on_floor or on_body):
            failures.append(f"body {k} rests on nothing (lowest point "
                            f"{end[k, -1] - radius[k]:.4g} m above the "
                            f"floor's {lower[-1]:.4g} m)")

    print(f"{label}: {n} bodies, {steps} steps; closest approach "
          f"{closest:.3g} m; support gap {gap:.3g} m")
    for f in failures:
        print(f"FAIL {label}: {f}")
    sys.exit(1 if failures else 0)


def cell_size(folder, lower, upper):
    """The finest cell edge of a 'hyper rectangle' mesh: what 'Contact
    distance = auto' takes."""
    subdivisions = [int(v) for v in
                    used_value(folder, "Subdivisions").split(",")]
    refinements = int(used_value(folder, "Refinements"))
    return min((u - lo) / (s * 2 ** refinements)
               for u, lo, s in zip(upper, lower, subdivisions))


if __name__ == "__main__":
    main()
