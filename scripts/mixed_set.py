#!/usr/bin/python3
"""Check a settling run of many bodies: the momentum balance during the free
fall, that every body comes to rest, and the deepest contact overlap.

    scripts/mixed_set.py OUTPUT_DIR [--label NAME] [--series FILE]
                         [--max-balance-error PERCENT]
                         [--max-final-speed M_PER_S]
                         [--max-penetration M]

reads OUTPUT_DIR/particle_set.csv (masses and volumes), particle_<i>.dat
(velocities, hydrodynamic and contact forces), flow.dat (max_penetration)
and used_parameters.prm (fluid density, gravity) and prints

- the momentum balance of the bodies over the free fall, from the start to
  the last step before any body has a contact force: the change of their
  total momentum sum m_i U_i against the impulse of the net weight
  sum (m_i - rho_f V_i) g and the hydrodynamic forces sum F_i, each step's
  force acting over that step (the coupling moves the bodies over a step
  with the loads computed at its end), as a percentage of the net weight's
  impulse; and the share of the net weight that the drag carries at the
  end of the free fall;
- the largest speed of a body at the end of the run, that body's speed at
  40 % of the run (with the doubling time when it grew), and the last time
  any other body moved faster than 1 mm/s;
- the deepest overlap of two bodies (shapes inflated by the contact
  distance) at the end of the run, and the deepest over the run with its
  time.

--series writes time, the total kinetic energy and the height of every
body (a small whitespace table for scripts/validation/mixed_set.py). The
--max-* options make it exit with 1 when a figure is beyond its bound.
"""
import argparse
import csv
import os
import sys

import numpy as np

from particulate_output import (read_parameters, read_particle_series,
                                read_series)


def vector(columns, names):
    return np.stack([columns[n] for n in names], axis=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output")
    parser.add_argument("--label", default="")
    parser.add_argument("--series")
    parser.add_argument("--max-balance-error", type=float)
    parser.add_argument("--max-final-speed", type=float)
    parser.add_argument("--max-penetration", type=float)
    args = parser.parse_args()

    prm = read_parameters(args.output)
    rho_f = float(prm["Fluid/Density"])
    g = np.array([float(x) for x in prm["Particles/Gravity"].split(",")])
    g = np.pad(g, (0, 3 - len(g)))
    with open(os.path.join(args.output, "particle_set.csv")) as f:
        particles = [row for row in csv.DictReader(f)
                     if row["motion"] == "free"]
    if not particles:
        sys.exit("mixed_set.py: no free particle in particle_set.csv")

    bodies = read_particle_series(args.output, [p["id"] for p in particles])
    t = bodies[0]["time"]
    mass = np.array([float(p["mass"]) for p in particles])
    volume = np.array([float(p["volume"]) for p in particles])
    velocity = [vector(b, ("u", "v", "w")) for b in bodies]
    force = [vector(b, ("F_x", "F_y", "F_z")) for b in bodies]
    contact = [vector(b, ("Fc_x", "Fc_y", "Fc_z")) for b in bodies]

    touching = np.any([np.linalg.norm(c, axis=1) > 0. for c in contact],
                      axis=0)
    first_contact = int(np.argmax(touching)) if touching.any() else len(t)
    if first_contact < 2:
        sys.exit("mixed_set.py: a body touches from the start; no free fall "
                 "to check")
    fall = slice(0, first_contact)  # the rows before the first contact
    momentum = sum(m * u for m, u in zip(mass, velocity))
    net_weight = np.sum(mass - rho_f * volume) * g
    loads = net_weight + sum(force)
    tf = t[fall]
    impulse = np.sum(loads[fall][1:] * np.diff(tf)[:, None], axis=0)
    weight_impulse = net_weight * (tf[-1] - tf[0])
    change = momentum[fall][-1] - momentum[fall][0]
    balance = 100. * np.linalg.norm(change - impulse) / np.linalg.norm(
        weight_impulse)
    drag_share = -np.dot(sum(force)[fall][-1], net_weight) / np.dot(
        net_weight, net_weight)

    speeds = np.array([np.linalg.norm(u[-1]) for u in velocity])
    flow = read_series(os.path.join(args.output, "flow.dat"))
    penetration = float(flow["max_penetration"][-1])
    deepest = float(np.max(flow["max_penetration"]))
    deepest_at = float(flow["time"][int(np.argmax(flow["max_penetration"]))])

    fastest = int(np.argmax(speeds))
    history = np.linalg.norm(velocity[fastest], axis=1)
    early = int(np.argmin(np.abs(t - 0.4 * t[-1])))
    growth = ""
    if 0. < history[early] < history[-1]:
        growth = ", doubling every %.2f s" % (
            (t[-1] - t[early]) * np.log(2.) / np.log(history[-1]
                                                     / history[early]))
    # (time, body) of the last row at which a body other than the fastest
    # moved faster than 1 mm/s
    last_fast = (float("nan"), fastest)
    for b in range(len(bodies)):
        fast = np.nonzero(np.linalg.norm(velocity[b], axis=1) > 1e-3)[0]
        if b != fastest and len(fast) and not t[fast[-1]] <= last_fast[0]:
            last_fast = (float(t[fast[-1]]), b)

    print("%s %d free bodies; free fall t = 0..%.4g s: momentum change %s "
          "N s against the impulse of net weight and fluid forces %s N s: "
          "balance error %.3f %% of the net weight's impulse; the drag "
          "carries %.1f %% of the net weight at the end of the free fall"
          % (args.label, len(particles), tf[-1],
             np.array2string(change, precision=5),
             np.array2string(impulse, precision=5), balance,
             100. * drag_share))
    print("%s at t = %.4g s: largest speed %.3e m/s (body %s), deepest "
          "overlap %.3e m (%.3e m over the run, at t = %.4g s)"
          % (args.label, t[-1], speeds.max(), particles[fastest]["id"],
             penetration, deepest, deepest_at))
    print("%s body %s at t = %.4g s: %.3e m/s%s; any other body faster than "
          "1 mm/s last at t = %.4g s (body %s)"
          % (args.label, particles[fastest]["id"], t[early], history[early],
             growth, last_fast[0], particles[last_fast[1]]["id"]))

    failed = []
    if args.max_balance_error is not None and not (
            balance <= args.max_balance_error):
        failed.append("momentum balance error %.3f %% > %g %%"
                      % (balance, args.max_balance_error))
    if args.max_final_speed is not None and not (
            speeds.max() <= args.max_final_speed):
        failed.append("a body still moves at %.3e m/s > %g m/s"
                      % (speeds.max(), args.max_final_speed))
    if args.max_penetration is not None and not (
            penetration <= args.max_penetration):
        failed.append("overlap %.3e m > %g m"
                      % (penetration, args.max_penetration))
    for f in failed:
        print("FAILED: " + f)

    if args.series:
        heights = np.stack([b["z"] for b in bodies], axis=1)
        energy = sum(b["kinetic_energy"] for b in bodies)
        with open(args.series, "w") as f:
            f.write("# time kinetic_energy %s  (%s; shapes: %s)\n"
                    % (" ".join("z_%s" % p["id"] for p in particles),
                       args.label,
                       " ".join(p["shape"] for p in particles)))
            stride = max(1, len(t) // 300)
            for i in range(0, len(t), stride):
                f.write("%.6g %.6g %s\n" % (
                    t[i], energy[i],
                    " ".join("%.6g" % z for z in heights[i])))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
