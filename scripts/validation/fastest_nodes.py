#!/usr/bin/python3
"""Where a run's flow is fastest: per flow snapshot, the fastest velocity
node, its speed, its distance from the column's axis, and the pressure range.

    scripts/validation/fastest_nodes.py OUTPUT [--axis X Y]

OUTPUT is a run's output folder (its flow.pvd and flow_*.vtu). --axis gives
the x and y of a vertical column's axis (the fluidized bed's: 0.02 0.02), so
that a node beside the mantle shows as a radius near the column's. Isolated
nodes far faster than the flow around them, with pressures of kPa, are the
sign of films the mesh does not resolve (doc/developer/fbm.md, "Near
contact").
"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from particulate_output import flow_snapshots, read_flow_snapshot  # noqa: E402


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output")
    parser.add_argument("--axis", nargs=2, type=float, default=[0.02, 0.02])
    args = parser.parse_args()
    print("# time step x y z [mm] radius [mm] speed [m/s] p_min p_max [Pa]")
    for time, step in flow_snapshots(args.output):
        if not glob.glob(os.path.join(args.output, "flow_%05d.*.vtu" % step)):
            continue  # listed by a run this one was restarted from
        points, data = read_flow_snapshot(args.output, step, ["velocity", "pressure"])
        speed = np.linalg.norm(data["velocity"].reshape(-1, 3), axis=1)
        k = int(np.argmax(speed))
        x = points[k]
        radius = np.hypot(x[0] - args.axis[0], x[1] - args.axis[1])
        print(f"{time:.4g} {step} {1e3 * x[0]:.1f} {1e3 * x[1]:.1f} {1e3 * x[2]:.1f} "
              f"{1e3 * radius:.2f} {speed[k]:.3g} {data['pressure'].min():.4g} "
              f"{data['pressure'].max():.4g}")


if __name__ == "__main__":
    main()
