#!/usr/bin/python3
"""Compare the rotation of a free ellipse (2D) or spheroid (3D) in shear flow
with Jeffery's closed form.

    scripts/jeffery_orbit.py OUTPUT_DIR [--shear-rate G] [--aspect-ratio L]
                             [--label NAME] [--series FILE]
                             [--max-period-error PERCENT]
                             [--max-orbit-drift PERCENT]

reads OUTPUT_DIR/particle_0.dat (the orientation quaternion columns) and
prints the measured period, its error against T = 2 pi (L + 1/L) / G, and
the RMS of the angle against the closed form over the first two periods
(over the whole run if it is shorter). The period is
twice the mean time between successive half turns, counted from the first
half turn on, so that the start from rest does not enter it. The angle phi is
that of the body's long axis (body x) against the flow direction x, in the
plane of shear (x, y), unwrapped; in the shear u = G y it decreases,

    tan(phi) = -(1/L) tan(G t / (L + 1/L)).

In 3D the long axis p = (sin theta cos phi, sin theta sin phi, cos theta)
(theta from the vorticity axis z) keeps Jeffery's orbit constant
C = tan(theta) sqrt(L^2 sin^2 phi + cos^2 phi) / L, and phi follows the
same closed form whatever C is. The script prints C at the start and its
largest relative departure from it over the run.

--series writes time, phi and Jeffery's phi, and in 3D the orbit constant
C (a small whitespace table for the figures and the orbit-constant table of
doc/validation/jeffery-orbit.md).
"""
import argparse
import math
import sys

import numpy as np

from particulate_output import read_series


def long_axis(columns):
    """The body x axis in the world, R e_x (the first column of the
    rotation matrix of the orientation quaternion)."""
    w, x, y, z = (columns[k] for k in ("q_w", "q_x", "q_y", "q_z"))
    return (1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z),
            2.0 * (x * z - w * y))


def long_axis_angle(columns):
    """Angle of the body x axis projected on the (x, y) plane, unwrapped."""
    ex, ey, _ = long_axis(columns)
    return np.unwrap(np.arctan2(ey, ex), period=math.pi)


def orbit_constant(columns, aspect_ratio):
    """Jeffery's orbit constant C of the long axis (infinite in the plane of
    shear, as in 2D)."""
    ex, ey, ez = long_axis(columns)
    phi = np.arctan2(ey, ex)
    with np.errstate(divide="ignore"):
        tan_theta = np.hypot(ex, ey) / np.abs(ez)
    return tan_theta * np.sqrt(aspect_ratio ** 2 * np.sin(phi) ** 2
                               + np.cos(phi) ** 2) / aspect_ratio


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
    parser.add_argument("--max-orbit-drift", type=float,
                        help="exit with 1 if the orbit constant departs "
                             "from its start by more than this many percent")
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
    if len(half_turns) < 3:
        sys.exit("jeffery_orbit.py: the run covers less than one period "
                 "after the first half turn (%d half turns); run it longer."
                 % len(half_turns))
    n_periods = 0.5 * (len(half_turns) - 1)
    measured = (half_turns[-1] - half_turns[0]) / n_periods
    window = t <= 2.0 * period + 1e-9 * period
    rms = math.sqrt(float(np.mean((phi[window] - exact[window]) ** 2)))
    print("%s period %.5f s over %g period(s) (Jeffery %.5f s): error "
          "%+.3f %%; angle RMS against the closed form %.4f rad over "
          "t = 0..%.3f s" % (args.label, measured, n_periods, period,
                              100.0 * (measured / period - 1.0), rms,
                              t[window][-1]))
    failed = False
    orbit = orbit_constant(columns, lam)
    if np.all(np.isfinite(orbit)):
        drift = 100.0 * float(np.max(np.abs(orbit / orbit[0] - 1.0)))
        print("%s orbit constant C = %.5f at the start, largest departure "
              "%.3f %%, %.5f at the end" % (args.label, orbit[0], drift,
                                           orbit[-1]))
        if args.max_orbit_drift is not None and not (
                drift <= args.max_orbit_drift):
            print("FAILED: the orbit constant departs by %.3f %%, more than "
                  "%g %%" % (drift, args.max_orbit_drift))
            failed = True
    error = 100.0 * abs(measured / period - 1.0)
    if args.max_period_error is not None and not error <= args.max_period_error:
        print("FAILED: the period is off by %.3f %%, more than %g %%"
              % (error, args.max_period_error))
        failed = True
    if args.series:
        # in 3D a fourth column: the orbit constant C
        with_orbit = bool(np.all(np.isfinite(orbit)))
        with open(args.series, "w") as f:
            f.write("# time phi phi_jeffery%s  (%s)\n"
                    % (" C" if with_orbit else "", args.label))
            stride = max(1, len(t) // 400)
            for i in range(0, len(t), stride):
                f.write("%.6g %.8g %.8g" % (t[i], phi[i], exact[i]))
                f.write(" %.6g\n" % orbit[i] if with_orbit else "\n")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
