#!/usr/bin/python3
"""Check a settling spheroid run: how its long axis turns against time.

    scripts/ten_cate_ellipsoid.py OUTPUT_DIR [--label NAME] [--series FILE]
                                  [--max-final-tilt DEGREES]

reads OUTPUT_DIR/particle_0.dat and prints

- the tilt of the body's long axis (its x axis) against the horizontal
  plane (positive on the side it starts on): at the start, the times it
  falls below 10 and 5 degrees and passes the horizontal, the largest tilt
  past it, and the tilt at the end of the run;
- the largest settling speed and the lateral (x) drift of the centre.

--series writes time, tilt [degrees], settling speed -w, horizontal
velocity u, and the centre's x and z (a small whitespace table for
scripts/validation/ten_cate_ellipsoid.py). --max-final-tilt makes it exit
with 1 when the tilt at the end is larger in size.
"""
import argparse
import os
import sys

import numpy as np

from particulate_output import read_series


def long_axis_tilt(body):
    """Angle [degrees] between the body's x axis and the horizontal plane,
    from the orientation quaternion (w, x, y, z) of every row; positive on
    the side it starts on, negative past the horizontal."""
    w, x, y, z = (body[k] for k in ("q_w", "q_x", "q_y", "q_z"))
    # z component of R(q) e_x
    vertical = np.clip(2. * (x * z - w * y), -1., 1.)
    side = np.sign(vertical[0]) if vertical[0] != 0. else 1.
    return np.degrees(np.arcsin(side * vertical))


def first_time_below(t, values, bound):
    below = np.nonzero(values < bound)[0]
    return t[below[0]] if below.size else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output")
    parser.add_argument("--label", default="")
    parser.add_argument("--series")
    parser.add_argument("--max-final-tilt", type=float)
    args = parser.parse_args()

    body = read_series(os.path.join(args.output, "particle_0.dat"))
    t = body["time"]
    if len(t) < 2:
        sys.exit("ten_cate_ellipsoid.py: %s holds no time steps"
                 % args.output)
    tilt = long_axis_tilt(body)
    settling = -body["w"]
    print("%s tilt of the long axis: %.2f deg at t = 0, below 10 deg from "
          "t = %.3f s, below 5 deg from t = %.3f s, through the horizontal "
          "at t = %.3f s, %.2f deg at t = %.3f s (largest past the "
          "horizontal %.2f deg)"
          % (args.label, tilt[0], first_time_below(t, tilt, 10.),
             first_time_below(t, tilt, 5.), first_time_below(t, tilt, 0.),
             tilt[-1], t[-1], -min(0., tilt.min())))
    top = int(np.argmax(settling))
    print("%s largest settling speed %.5f m/s at t = %.3f s; centre moved "
          "%.2f mm in x, %.2f mm down; horizontal velocity at the end "
          "%.5f m/s"
          % (args.label, settling[top], t[top],
             1e3 * (body["x"][-1] - body["x"][0]),
             1e3 * (body["z"][0] - body["z"][-1]), body["u"][-1]))

    failed = args.max_final_tilt is not None and not (
        abs(tilt[-1]) <= args.max_final_tilt)
    if failed:
        print("FAILED: the long axis ends %.2f deg from the horizontal > %g"
              % (abs(tilt[-1]), args.max_final_tilt))

    if args.series:
        with open(args.series, "w") as f:
            f.write("# time tilt_deg settling_speed u x z  (%s)\n"
                    % args.label)
            for i in range(len(t)):
                f.write("%.6g %.6g %.6g %.6g %.6g %.6g\n"
                        % (t[i], tilt[i], settling[i], body["u"][i],
                           body["x"][i], body["z"][i]))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
