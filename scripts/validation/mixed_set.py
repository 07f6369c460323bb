#!/usr/bin/python3
"""Plot a settling run of many bodies from the small series that
scripts/mixed_set.py --series writes (time, total kinetic energy, height of
every body; the header names the bodies' shapes).

    scripts/validation/mixed_set.py OUTPUT.png SERIES.dat

Top: the height of every body against time, one colour per shape. Bottom:
the bodies' total kinetic energy (logarithmic).
"""
import sys

import numpy as np

from time_figure import save, two_panels


def read(path):
    with open(path) as f:
        header = f.readline()
    shapes = header.rsplit("shapes:", 1)[1].rsplit(")", 1)[0].split()
    data = np.loadtxt(path, ndmin=2)
    return shapes, data[:, 0], data[:, 1], data[:, 2:]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    shapes, t, energy, heights = read(sys.argv[2])
    fig, top, bottom = two_panels((2, 1))
    colours = {}
    for i, shape in enumerate(shapes):
        first = shape not in colours
        colours.setdefault(shape, "C%d" % len(colours))
        top.plot(t, 1e3 * heights[:, i], color=colours[shape], lw=1,
                 label=shape if first else None)
    top.set_ylabel("height of the centre [mm]")
    top.legend(loc="upper right", fontsize=8)
    moving = energy > 0.
    bottom.semilogy(t[moving], energy[moving], "k-", lw=1)
    bottom.set_ylabel("kinetic energy [J]")
    save(fig, top, bottom, sys.argv[1])


if __name__ == "__main__":
    main()
