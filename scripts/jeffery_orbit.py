#!/usr/bin/python3
"""Compare the rotation of a free ellipse (2D) or spheroid (3D) in shear flow
with Jeffery's closed form.

    scripts/jeffery_orbit.py OUTPUT_DIR [--shear-rate G] [--aspect-ratio L]
                             [--label NAME] [--series FILE]
                             [--max-period-error PERCENT]

reads OUTPUT_DIR/particle_0.dat (the orientation quaternion columns) and
prints the measured period, its error against T = 2 pi (L + 1/L) / G, and
the RMS of the angle against the closed form over the run. The angle phi is
that of the body's long axis (body x) against the flow direction x, in the
plane of shear (x, y), unwrapped; in the shear u = G y it decreases,

    tan(phi) = -(1/L) tan(G t / (L + 1/L)).

--series writes time, phi and Jeffery's phi (a small whitespace table for
the figures of doc/validation-jeffery.md).
"""
import argparse
import math
import sys

import numpy as np


def read_series(path):
    with open(path) as f:
        header = f.readline().lstrip("#").split()
    data = np.loadtxt(path, comments="#", ndmin=2)
    return {name: data[:, i] for i, name in enumerate(header)}


def long_axis_angle(columns):
    """Angle of the body x axis projected on the (x, y) plane, unwrapped."""
    w, x, y, z = (columns[k] for k in ("q_w", "q_x", "q_y", "q_z"))
    # first column of the rotation matrix: R e_x
    ex = 1.0 - 2.0 * (y * y + z * z)
    ey = 2.0 * (x * y + w * z)
    return np.unwrap(np.arctan2(ey, ex), period=math.pi)


def jeffery_angle(t, shear_rate, aspect_ratio):
    omega = shear_rate / (aspect_ratio + 1.0 / aspect_ratio)
    return -np.unwrap(np.arctan2(np.sin(omega * t) / aspect_ratio,
                                 np.cos(omega * t)))


def crossing_times(t, phi, step):
    """Times at which phi first passes -step, -2 step, ... (linear
    interpolation)."""
    times = []
    level = -step
    for i in range(1, len(t)):
        while phi[i] <= level < phi[i - 1]:
            s = (phi[i - 1] - level) / (phi[i - 1] - phi[i])
            times.append(t[i - 1] + s * (t[i] - t[i - 1]))
            level -= step
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output")
    parser.add_argument("--shear-rate", type=float, default=1.0)
    parser.add_argument("--aspect-ratio", type=float, default=2.0)
    parser.add_argument("--label", default="")
    parser.add_argument("--series")
    parser.add_argument("--max-period-error", type=float,
                        help="exit with 1 if the period is off by more "
                             "than this many percent")
    args = parser.parse_args()

    columns = read_series(args.output + "/particle_0.dat")
    t = columns["time"]
    phi = long_axis_angle(columns)
    phi -= phi[0]
    exact = jeffery_angle(t, args.shear_rate, args.aspect_ratio)
    lam = args.aspect_ratio
    period = 2.0 * math.pi * (lam + 1.0 / lam) / args.shear_rate

    # an ellipse looks the same after half a turn: periods from the
    # half-turn crossings
    half_turns = crossing_times(t, phi, math.pi)
    if len(half_turns) < 2:
        sys.exit("jeffery_orbit.py: the run covers less than one period "
                 "(%d half turns); run it longer." % len(half_turns))
    n_periods = len(half_turns) // 2
    measured = half_turns[2 * n_periods - 1] / n_periods
    rms = math.sqrt(float(np.mean((phi - exact) ** 2)))
    print("%s period %.5f s over %d period(s) (Jeffery %.5f s): error "
          "%+.3f %%; angle RMS against the closed form %.4f rad over "
          "t = 0..%.3f s" % (args.label, measured, n_periods, period,
                              100.0 * (measured / period - 1.0), rms, t[-1]))
    error = 100.0 * abs(measured / period - 1.0)
    if args.max_period_error is not None and not error <= args.max_period_error:
        print("FAILED: the period is off by %.3f %%, more than %g %%"
              % (error, args.max_period_error))
        sys.exit(1)
    if args.series:
        with open(args.series, "w") as f:
            f.write("# time phi phi_jeffery  (%s)\n" % args.label)
            stride = max(1, len(t) // 400)
            for i in range(0, len(t), stride):
                f.write("%.6g %.8g %.8g\n" % (t[i], phi[i], exact[i]))


if __name__ == "__main__":
    main()
