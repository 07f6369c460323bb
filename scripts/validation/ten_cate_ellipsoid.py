#!/usr/bin/python3
"""Plot a settling spheroid from the series that scripts/ten_cate_ellipsoid.py
--series writes (time, tilt, settling speed, horizontal velocity, x, z).

    scripts/validation/ten_cate_ellipsoid.py OUTPUT.png SERIES.dat [...]

Top: the tilt of the long axis against the horizontal. Bottom: the
settling speed (solid) and the horizontal velocity (dashed). One colour per
series; the label is the one in the series' header.
"""
import sys

import numpy as np

from time_figure import save, two_panels


def read(path):
    with open(path) as f:
        header = f.readline()
    label = header.rsplit("(", 1)[1].rsplit(")", 1)[0]
    return label, np.loadtxt(path, ndmin=2)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    fig, top, bottom = two_panels()
    for k, path in enumerate(sys.argv[2:]):
        label, d = read(path)
        colour = "C%d" % k
        top.plot(d[:, 0], d[:, 1], color=colour, lw=1.2, label=label)
        bottom.plot(d[:, 0], 1e3 * d[:, 2], color=colour, lw=1.2,
                    label=label + ": settling speed")
        bottom.plot(d[:, 0], 1e3 * d[:, 3], color=colour, lw=1, ls="--",
                    label=label + ": horizontal velocity")
    top.set_ylabel("tilt of the long axis [deg]")
    top.axhline(0., color="k", lw=0.5)
    top.legend(fontsize=8)
    bottom.set_ylabel("velocity [mm/s]")
    bottom.axhline(0., color="k", lw=0.5)
    bottom.legend(fontsize=8)
    save(fig, top, bottom, sys.argv[1])


if __name__ == "__main__":
    main()
