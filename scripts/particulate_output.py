"""Readers of what a Particulate run writes into its output folder, for the
scripts next to this file."""
import os
import sys

import numpy as np


def read_series(path):
    """A `.dat` time series (a '# name ...' header line, then rows of
    numbers) as {column name: array}."""
    with open(path) as f:
        header = f.readline().lstrip("#").split()
    data = np.loadtxt(path, comments="#", ndmin=2)
    return {name: data[:, i] for i, name in enumerate(header)}


def read_parameters(folder):
    """The entries of <folder>/used_parameters.prm as
    {"Subsection/.../Entry": value text}."""
    values, sections = {}, []
    with open(os.path.join(folder, "used_parameters.prm")) as f:
        for line in f:
            words = line.split("#")[0].strip()
            if words.startswith("subsection "):
                sections.append(words[len("subsection "):].strip())
            elif words == "end":
                sections.pop()
            elif words.startswith("set "):
                name, _, value = words[4:].partition("=")
                values["/".join(sections + [name.strip()])] = value.strip()
    return values


def write_table(path, header, table, every=1):
    """A small series for the docs: a '# name ...' line, then every
    `every`-th row of the 2D array `table`."""
    with open(path, "w") as out:
        out.write("# " + " ".join(header) + "\n")
        np.savetxt(out, table[::every], fmt="%.6g")


def read_table(path):
    """What write_table wrote: the column names and the rows."""
    with open(path) as f:
        header = f.readline().lstrip("#").split()
    return header, np.loadtxt(path, ndmin=2)


def redraw_if_asked(draw):
    """`SCRIPT --redraw SERIES FIGURE`: draw FIGURE from the committed SERIES
    with `draw(path, header, table)`; True if that was asked."""
    if len(sys.argv) == 4 and sys.argv[1] == "--redraw":
        draw(sys.argv[3], *read_table(sys.argv[2]))
        return True
    return False
