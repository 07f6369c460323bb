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


def read_particle_series(folder, ids):
    """The time series of the particles `ids` of a run, each as {column
    name: array}: from their own particle_<i>.dat or, where the run shared
    its particle files ('Particle files'), from the rows of particles.dat
    with that id."""
    shared = os.path.join(folder, "particles.dat")
    if not os.path.exists(shared):
        return [read_series(os.path.join(folder, "particle_%d.dat" % int(i)))
                for i in ids]
    rows = read_series(shared)
    of = rows.pop("id").astype(int)
    return [{name: column[of == int(i)] for name, column in rows.items()}
            for i in ids]


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
