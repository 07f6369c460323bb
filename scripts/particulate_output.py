"""Readers of what a Particulate run writes into its output folder, for the
scripts next to this file."""
import base64
import glob
import os
import re
import struct
import sys
import zlib

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


def _decode_vtu_array(text):
    """The values of one zlib-compressed binary VTU DataArray (deal.II's
    output) as float32. The base64 text starts with a header of uint32:
    number of blocks, block size, last block size, then the compressed size
    of every block."""
    data = text.strip()
    n_blocks = struct.unpack("<I", base64.b64decode(data[:8])[:4])[0]
    header_bytes = 4 * (3 + n_blocks)
    header_chars = (header_bytes + 2) // 3 * 4
    header = struct.unpack(
        "<%dI" % (3 + n_blocks), base64.b64decode(data[:header_chars])[:header_bytes]
    )
    raw = base64.b64decode(data[header_chars:])
    values, offset = b"", 0
    for size in header[3:]:
        values += zlib.decompress(raw[offset : offset + size])
        offset += size
    return np.frombuffer(values, dtype="<f4")


def read_vtu(path, names=()):
    """The points of a flow snapshot's `.vtu` piece as an (n, 3) array and
    its point data arrays `names` as {name: (n, components) array}."""
    with open(path) as f:
        text = f.read()
    if 'compressor="vtkZLibDataCompressor"' not in text:
        sys.exit(f"{path}: not a zlib-compressed binary VTU file")
    match = re.search(r"<Points>\s*<DataArray[^>]*>([^<]*)</DataArray>", text)
    if not match:
        sys.exit(f"{path}: no points")
    points = _decode_vtu_array(match.group(1)).reshape(-1, 3)
    arrays = {}
    for name in names:
        match = re.search(
            r'<DataArray[^>]*Name="%s"[^>]*>([^<]*)</DataArray>' % re.escape(name),
            text)
        if not match:
            sys.exit(f"{path}: no point data '{name}'")
        values = _decode_vtu_array(match.group(1))
        arrays[name] = values.reshape(points.shape[0], -1)
    return points, arrays


def read_flow_snapshot(folder, step, names=()):
    """Snapshot `step` of a run (flow_<step>.<rank>.vtu of every rank)
    joined: its points and point data arrays, as read_vtu gives them. Points
    shared by cells appear once per cell."""
    files = sorted(glob.glob(os.path.join(folder, "flow_%05d.*.vtu" % step)))
    if not files:
        sys.exit(f"{folder}: no flow_{step:05d}.*.vtu")
    pieces = [read_vtu(f, names) for f in files]
    points = np.concatenate([p for p, _ in pieces])
    return points, {n: np.concatenate([a[n] for _, a in pieces]) for n in names}


def flow_snapshots(folder):
    """The flow snapshots of a run as (time, step), from flow.pvd."""
    with open(os.path.join(folder, "flow.pvd")) as f:
        text = f.read()
    return [(float(t), int(s)) for t, s in re.findall(
        r'timestep="([^"]+)"[^>]*file="flow_(\d+)\.pvtu"', text)]


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
