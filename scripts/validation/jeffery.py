#!/usr/bin/python3
"""Plot Jeffery-orbit runs against the closed form from the small series
that scripts/jeffery_orbit.py --series writes (time, phi, phi_jeffery).

    scripts/validation/jeffery.py OUTPUT.png SERIES.dat [SERIES.dat ...]

Top: the angle of the long axis against time, each run and Jeffery's
closed form. Bottom: each run's angle minus the closed form. Prints, for
each run, the lag of the closed form that fits its angle best after
t = 2 s (the start from rest excluded; scanned in steps of 1 ms up to
0.5 s) and the angle RMS with that lag.
"""
import sys

import numpy as np

from time_figure import save, two_panels


def read(path):
    with open(path) as f:
        header = f.readline()
    label = header.split("(", 1)[1].rsplit(")", 1)[0] if "(" in header else path
    data = np.loadtxt(path, ndmin=2)
    return label, data[:, 0], data[:, 1], data[:, 2]


def best_lag(t, phi, exact, after=2.0):
    """(lag [s], RMS [rad]) of the closed form delayed by the lag that
    fits phi best over t > after."""
    late = t > after
    fits = [(np.sqrt(np.mean((phi[late] - np.interp(t[late] - lag, t, exact)) ** 2)), lag)
            for lag in np.arange(0.0, 0.5, 0.001)]
    rms, lag = min(fits)
    return lag, rms


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    runs = [read(p) for p in sys.argv[2:]]
    fig, top, bottom = two_panels((2, 1))
    label, t, _, exact = runs[0]
    top.plot(t, exact, "k-", lw=2.5, alpha=0.35, label="Jeffery (closed form)")
    for label, t, phi, exact in runs:
        lag, rms = best_lag(t, phi, exact)
        print(f"{label}: the closed form delayed by {lag:.3f} s fits the angle after "
              f"t = 2 s with RMS {rms:.4f} rad")
        top.plot(t, phi, lw=1, label=label)
        bottom.plot(t, phi - exact, lw=1, label=label)
    top.set_ylabel("angle of the long axis [rad]")
    top.legend(loc="upper right", fontsize=8)
    bottom.set_ylabel("run - closed form [rad]")
    bottom.axhline(0.0, color="k", lw=0.5)
    save(fig, top, bottom, sys.argv[1])


if __name__ == "__main__":
    main()
