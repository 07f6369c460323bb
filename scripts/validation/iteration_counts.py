#!/usr/bin/python3
"""The solver iterations of every step of a particulate-flow run, checked.

    scripts/validation/iteration_counts.py OUTPUT [--label NAME]
        [--max-linear 100] [--max-displacement METRES] [--series FILE]

reads OUTPUT/flow.dat (Newton and FGMRES iterations per step),
OUTPUT/particle_set.csv with the particles' series, and the End time of
OUTPUT/used_parameters.prm; prints the iterations of every step and exits 1
unless

- the run reached its End time (no 'run stopped' line in flow.dat);
- no step took more than --max-linear FGMRES iterations;
- with --max-displacement, no free particle moved farther than that from
  where it started.

--series FILE writes the table (time, Newton, FGMRES per step) for the docs.
The prm/dense-bed case is checked this way (test fbm_dense_bed).
"""
import argparse
import csv
import os
import sys

import numpy as np
from used_parameters import used_value

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from particulate_output import (read_particle_series, read_series,  # noqa: E402
                                write_table)


def stop_note(path):
    with open(path) as f:
        for line in f:
            if line.startswith("# run stopped"):
                return line[2:].strip()
    return None


def largest_displacement(folder):
    with open(os.path.join(folder, "particle_set.csv")) as f:
        ids = [row["id"] for row in csv.DictReader(f)
               if row["motion"] == "free"]
    largest = 0.
    for s in read_particle_series(folder, ids):
        x = np.stack([s["x"], s["y"], s["z"]], axis=1)
        largest = max(largest, np.linalg.norm(x - x[0], axis=1).max())
    return largest, len(ids)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output")
    parser.add_argument("--label", default=None)
    parser.add_argument("--max-linear", type=float, default=100)
    parser.add_argument("--max-displacement", type=float, default=None)
    parser.add_argument("--series", default=None)
    args = parser.parse_args()
    label = args.label or os.path.basename(os.path.normpath(args.output))

    path = os.path.join(args.output, "flow.dat")
    flow = read_series(path)
    t, newton, fgmres = (flow["time"][1:], flow["nonlinear_iterations"][1:],
                         flow["linear_iterations"][1:])
    print(f"{label}: {len(t)} steps")
    print("| t [s] | Newton | FGMRES |\n|---|---|---|")
    for row in zip(t, newton, fgmres):
        print("| %.4g | %d | %d |" % row)
    print(f"FGMRES per step: mean {fgmres.mean():.1f}, largest "
          f"{fgmres.max():.0f} (t = {t[fgmres.argmax()]:.4g} s); Newton per "
          f"step: mean {newton.mean():.2f}, largest {newton.max():.0f}")
    if args.series:
        write_table(args.series, ["time", "newton", "fgmres"],
                    np.stack([t, newton, fgmres], axis=1))

    failed = []
    note = stop_note(path)
    end_time = float(used_value(args.output, "End time"))
    if note or len(t) == 0 or t[-1] < end_time * (1 - 1e-9):
        failed.append("the run did not reach its End time %g s%s"
                      % (end_time, ": " + note if note else ""))
    if fgmres.max() > args.max_linear:
        failed.append("a step took %d FGMRES iterations, more than %g"
                      % (fgmres.max(), args.max_linear))
    if args.max_displacement is not None:
        moved, n = largest_displacement(args.output)
        print(f"largest displacement of the {n} free particles: {moved:.3g} m")
        if moved > args.max_displacement:
            failed.append("a particle moved %.3g m, more than %g m"
                          % (moved, args.max_displacement))
    for f in failed:
        print(f"{label}: FAILED: {f}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
