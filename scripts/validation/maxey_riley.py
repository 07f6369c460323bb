#!/usr/bin/python3
"""The settling velocity of a sphere released from rest in an unbounded
fluid at rest, by the Maxey-Riley equation with Schiller-Naumann drag: the
reference for the first instants of a settling run, before walls and floor
matter.

    scripts/validation/maxey_riley.py RHO_P RHO_F MU D [--times T ...]
        [--run SERIES]

(m + C_a m_f) dv/dt = (m - m_f) g - 3 pi mu d v (1 + 0.15 Re^0.687)
                      - 3/2 d^2 sqrt(pi rho_f mu) int_0^t v'(s) / sqrt(t - s) ds

with C_a = 1/2 (the sphere's added mass) and the Basset history term. It
prints v(t) at the given times with both terms, without the history term,
and without the added mass (C_a = 0). The Basset kernel holds at Re << 1
and early times; at finite Re the history decays faster (Mei & Adrian
1992), so once the sphere is near its terminal speed the truth lies between
the first two rows. --run SERIES adds the row of a ten_cate.py --series
file (time, settling velocity, gap) and its differences to the first row.
"""
import argparse

import numpy as np

G = 9.81


def settling_velocity(rho_p, rho_f, mu, d, added_mass, history, end, dt=2e-4):
    """v at the times k dt, k = 0 .. end / dt (explicit in the drag, the
    newest history increment taken with the inertia)."""
    volume = np.pi * d ** 3 / 6
    m, m_f = rho_p * volume, rho_f * volume
    basset = 1.5 * d * d * np.sqrt(np.pi * rho_f * mu) if history else 0.
    n = int(round(end / dt))
    v, a = np.zeros(n + 1), np.zeros(n)
    for k in range(n):
        t = (k + 1) * dt
        reynolds = rho_f * abs(v[k]) * d / mu
        drag = 3 * np.pi * mu * d * v[k] * (1 + 0.15 * reynolds ** 0.687)
        # the exact integral of a piecewise constant acceleration
        start = np.arange(k) * dt
        weights = 2 * (np.sqrt(t - start) - np.sqrt(np.maximum(t - start - dt, 0.)))
        memory = basset * np.dot(a[:k], weights[:k])
        a[k] = ((m - m_f) * G - drag - memory) / (m + added_mass * m_f
                                                   + basset * 2 * np.sqrt(dt))
        v[k + 1] = v[k] + dt * a[k]
    return np.arange(n + 1) * dt, v


def read_series(path):
    """time and settling velocity of a ten_cate.py --series file."""
    table = np.loadtxt(path, ndmin=2)
    return table[:, 0], table[:, 1]


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    for name in ("rho_p", "rho_f", "mu", "d"):
        parser.add_argument(name, type=float)
    parser.add_argument("--times", type=float, nargs="+",
                        default=[0.01, 0.02, 0.05, 0.1, 0.2])
    parser.add_argument("--run", metavar="SERIES")
    args = parser.parse_args()
    end = max(args.times)
    rows = [("added mass and history", 0.5, True), ("added mass, no history", 0.5, False),
            ("no added mass, history", 0., True)]
    print("| model | " + " | ".join(f"v({t:g} s)" for t in args.times) + " |")
    print("|---" * (len(args.times) + 1) + "|")
    reference = None
    for label, added, history in rows:
        t, v = settling_velocity(args.rho_p, args.rho_f, args.mu, args.d, added, history, end)
        values = np.interp(args.times, t, v)
        reference = values if reference is None else reference
        print(f"| {label} | " + " | ".join(f"{x:.4f}" for x in values) + " |")
    if args.run:
        t, v = read_series(args.run)
        values = np.interp(args.times, t, v)
        print(f"| {args.run} | " + " | ".join(
            f"{x:.4f} ({100 * (x / r - 1):+.0f} %)" for x, r in zip(values, reference)) + " |")


if __name__ == "__main__":
    main()
