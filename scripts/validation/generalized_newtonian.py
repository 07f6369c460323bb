#!/usr/bin/python3
"""Figure of plane Poiseuille flow of generalized-Newtonian fluids.

    python3 scripts/validation/generalized_newtonian.py ERRORS PROFILES PNG

reads the two series that the test fluid_generalized_newtonian_poiseuille
writes (generalized-newtonian-errors.dat: law, cells across the channel,
velocity L2 error, Newton steps; generalized-newtonian-profiles.dat: y, then
u_x and its closed form for each law) and draws PNG: the profiles across
the channel, each scaled by its closed form's centre value, and the L2 error
against the cells across the channel with the slopes 3 (Q2, smooth
profile) and 13/6 (the thickening power law's |y|^(5/3) at the centre).
"""
import argparse
import re
import shlex

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_errors(path):
    """{law: (cells, errors)} in the file's order."""
    laws = {}
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        name, cells, error, _ = shlex.split(line)
        laws.setdefault(name, ([], []))
        laws[name][0].append(int(cells))
        laws[name][1].append(float(error))
    return laws


def read_profiles(path):
    """y, and per law (name, u_h, u) from the header's quoted names."""
    header = open(path).readline()
    names = re.findall(r'"([^"]*)"', header)
    data = np.loadtxt(path)
    return data[:, 0], [(name, data[:, 1 + 2 * i], data[:, 2 + 2 * i])
                        for i, name in enumerate(names)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("errors")
    parser.add_argument("profiles")
    parser.add_argument("figure")
    args = parser.parse_args()

    y, profiles = read_profiles(args.profiles)
    errors = read_errors(args.errors)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for index, (name, computed, exact) in enumerate(profiles):
        colour = "C%d" % index
        scale = exact.max()
        left.plot(exact / scale, y, color=colour, lw=1)
        left.plot(computed[::2] / scale, y[::2], "o", color=colour, ms=3,
                  label=name)
    left.set_xlabel("u_x / u_max")
    left.set_ylabel("y")
    left.set_title("x = 1, 16 cells across: closed form (lines)")
    left.legend(fontsize=8)

    for index, (name, (cells, error)) in enumerate(errors.items()):
        right.loglog(cells, error, "o-", color="C%d" % index, label=name)
    cells = np.array([4, 16])
    first = min(e[1][0] for e in errors.values())
    right.loglog(cells, 0.5 * first * (cells / 4.) ** -3, "k--", lw=0.8,
                 label="slope 3")
    right.loglog(cells, 0.5 * first * (cells / 4.) ** (-13. / 6.), "k:",
                 lw=0.8, label="slope 13/6")
    right.set_xticks([4, 8, 16])
    right.set_xticklabels(["4", "8", "16"])
    right.minorticks_off()
    right.set_xlabel("cells across the channel")
    right.set_ylabel("velocity L2 error")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.figure, dpi=120)


if __name__ == "__main__":
    main()
