#!/usr/bin/python3
"""The macro-scallop (thesis §6.5): displacement per cycle and figures.

    python3 scripts/validation/macro_scallop.py series NEWTONIAN THICKENING DAT
    python3 scripts/validation/macro_scallop.py viscosity THICKENING DAT
    python3 scripts/validation/macro_scallop.py plot SERIES VISCOSITY PNG
    python3 scripts/validation/macro_scallop.py study DAT NAME=FOLDER ...

series: reads particle_0.dat (the head) of the two runs' output folders,
prints the displacement D of each completed 4 s cycle as D/l (l = 22 mm)
and the largest excursion within it, and writes DAT: t, then the head's
displacement y(t) - y(0) [m] of each run, every 0.05 s (empty where a run
has not got that far).

viscosity: samples the `viscosity` field of the shear-thickening run at
t = 0.5 s (closing) and t = 2.5 s (opening), where the shells stand at the
same angle (123.5 degrees), on a grid around the swimmer, into DAT.

study: the net displacement of every completed cycle of each named run
(e.g. newtonian-r4-dt2.5-C500=output/...) into DAT, one row per run and
cycle: name, cycle, D [mm], D/l, largest excursion [mm].

plot: draws PNG from the two files: the displacement over the cycles, and
the viscosity around the swimmer in the two frames.
"""
import argparse
import base64
import re
import struct
import zlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

LENGTH = 0.022  # the swimmer, head to shell tips [m]
PERIOD = 4.0  # s
FRAMES = (0.5, 2.5)  # same opening angle, closing and opening [s]


def head_track(folder):
    """t and y of the head (particle 0)."""
    data = np.loadtxt(folder + "/particle_0.dat", comments="#", ndmin=2)
    return data[:, 0], data[:, 2]


def cycles(t, y):
    """(cycle, D, largest |excursion|) for each completed cycle."""
    result = []
    k = 1
    while t[-1] >= k * PERIOD - 1e-9:
        start = np.argmin(abs(t - (k - 1) * PERIOD))
        end = np.argmin(abs(t - k * PERIOD))
        excursion = np.max(abs(y[start : end + 1] - y[start]))
        result.append((k, y[end] - y[start], excursion))
        k += 1
    return result


def write_series(args):
    tracks = [head_track(args.newtonian), head_track(args.thickening)]
    for name, (t, y) in zip(("Newtonian", "shear-thickening"), tracks):
        print(f"{name}: reached t = {t[-1]:.3f} s")
        for k, D, excursion in cycles(t, y):
            print(
                f"  cycle {k}: D = {D * 1e3:+.4f} mm, D/l = {D / LENGTH:+.5f},"
                f" largest excursion {excursion * 1e3:.4f} mm"
            )
    end = max(t[-1] for t, _ in tracks)
    times = np.arange(0.0, end + 1e-9, 0.05)
    with open(args.dat, "w") as out:
        out.write(
            "# macro-scallop: the head's displacement y(t) - y(0) [m]\n"
            "# t [s]  Newtonian  shear-thickening\n"
        )
        for s in times:
            row = [f"{s:.2f}"]
            for t, y in tracks:
                i = np.argmin(abs(t - s))
                row.append(f"{y[i] - y[0]:.9e}" if abs(t[i] - s) < 1e-6 else "nan")
            out.write("  ".join(row) + "\n")


def decode_array(text, header_type):
    """The values of a zlib-compressed base64 VTK DataArray."""
    size = 8 if header_type == "UInt64" else 4
    fmt = "<Q" if size == 8 else "<I"
    # the header (block count, block size, last block size, compressed
    # sizes) is encoded on its own, then the blocks
    first = base64.b64decode(text[: 4 * ((3 * size + 2) // 3)])
    n_blocks = struct.unpack(fmt, first[:size])[0]
    header_bytes = (3 + n_blocks) * size
    header_chars = 4 * ((header_bytes + 2) // 3)
    header = base64.b64decode(text[:header_chars])
    sizes = struct.unpack("<" + fmt[1] * (3 + n_blocks), header)
    data = base64.b64decode(text[header_chars:])
    raw = b""
    offset = 0
    for compressed in sizes[3:]:
        raw += zlib.decompress(data[offset : offset + compressed])
        offset += compressed
    return raw


def read_vtu(path, names):
    """Points and the named point fields of one deal.II .vtu piece."""
    text = open(path).read()
    header_type = "UInt64" if 'header_type="UInt64"' in text else "UInt32"
    arrays = {}
    for match in re.finditer(
        r'<DataArray type="(\w+)"(?: Name="(\w+)")?[^>]*format="binary"[^>]*>'
        r"\s*([^<]*)</DataArray>",
        text,
    ):
        kind, name, body = match.groups()
        dtype = {"Float32": "<f4", "Float64": "<f8"}.get(kind)
        if dtype is None:
            continue
        values = np.frombuffer(decode_array(body.strip(), header_type), dtype)
        arrays[name or "Points"] = values
    points = arrays["Points"].reshape(-1, 3)
    return points, {n: arrays[n] for n in names}


def frame_file(folder, time):
    """The .vtu piece of the output written at @p time, or None."""
    pvd = open(folder + "/flow.pvd").read()
    for t, file in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd):
        if abs(float(t) - time) < 1e-6:
            return folder + "/" + file.replace(".pvtu", ".0.vtu")
    return None


def write_viscosity(args):
    t, y = head_track(args.thickening)
    with open(args.dat, "w") as out:
        out.write(
            "# macro-scallop, shear-thickening: viscosity [Pa s] around the "
            "swimmer\n# t [s]  x - x_head [m]  y - y_head [m]  mu\n"
        )
        for time in FRAMES:
            piece = frame_file(args.thickening, time)
            if piece is None:
                print(f"{args.thickening}: no flow output at t = {time} s yet")
                continue
            points, fields = read_vtu(piece, ["viscosity"])
            head_y = y[np.argmin(abs(t - time))]
            centre = np.array([0.0225, head_y])
            xs = np.linspace(-0.018, 0.018, 73)
            ys = np.linspace(-0.024, 0.012, 73)
            near = np.linalg.norm(points[:, :2] - centre, axis=1) < 0.035
            p, mu = points[near, :2], fields["viscosity"][near]
            for dy in ys:
                for dx in xs:
                    # the nearest output point (the Q2 cells' nodes)
                    i = np.argmin(np.sum((p - centre - [dx, dy]) ** 2, axis=1))
                    out.write(f"{time:.2f} {dx:.5f} {dy:.5f} {mu[i]:.5g}\n")
    print(f"wrote {args.dat}")


def plot(args):
    data = np.loadtxt(args.series, comments="#", ndmin=2)
    field = np.loadtxt(args.viscosity, comments="#", ndmin=2)
    fig = plt.figure(figsize=(12, 4.2))
    ax = fig.add_subplot(1, 3, 1)
    for column, label in ((1, "Newtonian (12.19 Pa s)"), (2, "shear-thickening")):
        ax.plot(data[:, 0], data[:, column] / LENGTH, label=label)
    for k in range(1, int(data[-1, 0] // PERIOD) + 1):
        ax.axvline(k * PERIOD, color="0.8", lw=0.8)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("displacement / l")
    ax.legend()
    ax.set_title("head displacement, l = 22 mm")
    for n, time in enumerate(FRAMES):
        rows = field[abs(field[:, 0] - time) < 1e-6]
        if len(rows) == 0:
            continue
        ax = fig.add_subplot(1, 3, 2 + n)
        xs, ys = np.unique(rows[:, 1]), np.unique(rows[:, 2])
        mu = rows[:, 3].reshape(len(ys), len(xs))
        image = ax.pcolormesh(
            xs * 1e3, ys * 1e3, mu, vmin=0.9, vmax=22, cmap="viridis", shading="auto"
        )
        ax.set_aspect("equal")
        ax.set_xlabel("x - x_head [mm]")
        ax.set_title(f"t = {time} s ({'closing' if time < 1 else 'opening'})")
        fig.colorbar(image, ax=ax, label="viscosity [Pa s]")
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print(f"wrote {args.png}")


def write_study(args):
    with open(args.dat, "w") as out:
        out.write(
            "# macro-scallop: net displacement per cycle of each run\n"
            "# run  cycle  D [mm]  D/l  largest excursion [mm]\n"
        )
        for entry in args.runs:
            name, folder = entry.split("=", 1)
            for k, D, excursion in cycles(*head_track(folder)):
                row = f"{name} {k} {D * 1e3:+.4f} {D / LENGTH:+.5f} {excursion * 1e3:.2f}"
                print(row)
                out.write(row + "\n")
    print(f"wrote {args.dat}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="mode", required=True)
    s = sub.add_parser("series")
    s.add_argument("newtonian")
    s.add_argument("thickening")
    s.add_argument("dat")
    v = sub.add_parser("viscosity")
    v.add_argument("thickening")
    v.add_argument("dat")
    p = sub.add_parser("plot")
    p.add_argument("series")
    p.add_argument("viscosity")
    p.add_argument("png")
    st = sub.add_parser("study")
    st.add_argument("dat")
    st.add_argument("runs", nargs="+", metavar="NAME=FOLDER")
    args = parser.parse_args()
    {
        "series": write_series,
        "viscosity": write_viscosity,
        "plot": plot,
        "study": write_study,
    }[args.mode](args)


if __name__ == "__main__":
    main()
