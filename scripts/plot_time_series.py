#!/usr/bin/python3
"""Plot columns of a Particulate time series (.dat with a '# name name ...'
header) against time and save a PNG.

    plot_time_series.py output/cylinder-in-channel/flow.dat --columns c_D c_L
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_series(path):
    with open(path) as f:
        header = f.readline()
    if not header.startswith("#"):
        sys.exit(f"{path}: the first line must be a '# name ...' header")
    names = header[1:].split()
    data = np.loadtxt(path, ndmin=2)
    return names, data


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("file", help=".dat time series")
    parser.add_argument("--columns", nargs="+", default=["c_D", "c_L"],
                        help="columns to plot, one panel each")
    parser.add_argument("--output", help="PNG to write (default: FILE with .png for .dat)")
    parser.add_argument("--title", default=None)
    args = parser.parse_args()

    names, data = read_series(args.file)
    missing = [c for c in args.columns if c not in names]
    if missing:
        sys.exit(f"{args.file}: no column {missing}; columns are {names}")
    time = data[:, names.index("time")]
    fig, axes = plt.subplots(len(args.columns), 1, sharex=True,
                             figsize=(7, 2.4 * len(args.columns)),
                             squeeze=False)
    for ax, column in zip(axes[:, 0], args.columns):
        ax.plot(time, data[:, names.index(column)], lw=1.2)
        ax.set_ylabel(column)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    fig.suptitle(args.title or args.file)
    fig.tight_layout()
    output = args.output or args.file.rsplit(".", 1)[0] + ".png"
    fig.savefig(output, dpi=120)
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
