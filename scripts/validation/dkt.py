#!/usr/bin/python3
"""Drafting, kissing and tumbling of two disks (prm/dkt/dkt.prm): find the
three events in a run's particle series and plot the run.

    scripts/validation/dkt.py output/dkt [--doc doc/validation]

Events (particle 0 starts on top, particle 1 below it):
  drafting  the trailing disk starts to catch up: the time of the largest
            centre distance before the disks touch (before it, the leading
            disk pulls away; after it, the trailing one falls faster in its
            wake);
  kissing   the first step with a contact force between the disks (their
            gap has closed to the contact distance);
  tumbling  the pair has turned over: the first time the disk that started
            on top is below the other one.
Also prints the smallest gap between the disks and between a disk and a wall
over the run (overlap would be negative) and writes dkt-paths.png,
dkt-gap.png, dkt-velocity.png and dkt.dat into --doc.

With --max-tumbling-time T it checks the sequence (exit status 1 if a check
fails): the three events happen, in the order drafting, kissing, tumbling,
tumbling by T, and no disk overlaps the other or a wall by more than
--max-overlap percent of the radius (default 1).
"""
import argparse
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_series(path):
    with open(path) as f:
        names = f.readline()[1:].split()
    data = np.loadtxt(path, ndmin=2)
    return {n: data[:, i] for i, n in enumerate(names)}


def read_entry(folder, name):
    """The value of 'set <name> = ...' in the run's used_parameters.prm."""
    with open(os.path.join(folder, "used_parameters.prm")) as f:
        for line in f:
            m = re.match(r"\s*set\s+" + re.escape(name) + r"\s*=\s*(.*)", line)
            if m:
                return m.group(1).split("#")[0].strip()
    sys.exit(f"{folder}/used_parameters.prm has no entry '{name}'")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--doc", default=None, help="folder for plots and table")
    parser.add_argument("--label", default=None, help="name of the run (unused)")
    parser.add_argument("--max-tumbling-time", type=float, default=None,
                        help="check the events; tumbling by this time [s]")
    parser.add_argument("--max-overlap", type=float, default=1.0,
                        help="bound on overlaps [%% of the radius]")
    args = parser.parse_args()

    a = read_series(os.path.join(args.folder, "particle_0.dat"))
    b = read_series(os.path.join(args.folder, "particle_1.dat"))
    t = a["time"]
    r = float(read_entry(args.folder, "Radius"))
    upper = [float(v) for v in read_entry(args.folder, "Upper corner").split(",")]
    lower = [float(v) for v in read_entry(args.folder, "Lower corner").split(",")]

    dx, dy = a["x"] - b["x"], a["y"] - b["y"]
    gap = np.hypot(dx, dy) - 2 * r
    # contact between the disks (and no wall): equal and opposite contact
    # forces on both
    f0 = np.hypot(a["Fc_x"], a["Fc_y"])
    net = np.hypot(a["Fc_x"] + b["Fc_x"], a["Fc_y"] + b["Fc_y"])
    touching = (f0 > 0) & (net <= 1e-6 * f0)
    kiss = np.argmax(touching) if touching.any() else None
    before = slice(0, kiss if kiss is not None else len(t))
    draft = int(np.argmax(gap[before]))
    turned = dy < 0
    tumble = int(np.argmax(turned)) if turned.any() else None

    wall_gap = min(
        min(p["x"].min() - lower[0], upper[0] - p["x"].max(),
            p["y"].min() - lower[1], upper[1] - p["y"].max()) - r
        for p in (a, b))

    rows = [
        ("drafting", t[draft], f"centre distance {gap[draft] + 2 * r:.5g} m at its largest"),
        ("kissing", t[kiss] if kiss is not None else float("nan"),
         f"gap {gap[kiss]:.4g} m" if kiss is not None else "not reached"),
        ("tumbling", t[tumble] if tumble is not None else float("nan"),
         "the upper disk passes below the lower" if tumble is not None else "not reached"),
    ]
    print(f"{'event':<10} {'t [s]':>8}  note")
    for name, time, note in rows:
        print(f"{name:<10} {time:8.3f}  {note}")
    print(f"smallest gap between the disks {gap.min():.4g} m "
          f"({gap.min() / r * 100:.1f} % of the radius; negative = overlap), "
          f"disk-wall {wall_gap:.4g} m; end of run t = {t[-1]:.3f} s")

    if args.max_tumbling_time is not None:
        failures = check_sequence(t, draft, kiss, tumble, min(gap.min(), wall_gap),
                                  r, args)
        if failures:
            print("\n".join("FAILED: " + f for f in failures))
            sys.exit(1)
        print("drafting, kissing and tumbling in order, without overlap: ok")

    if args.doc is None:
        return
    os.makedirs(args.doc, exist_ok=True)
    with open(os.path.join(args.doc, "dkt.dat"), "w") as f:
        f.write("# event time_s\n")
        for name, time, _ in rows:
            f.write(f"{name} {time:.4f}\n")
        f.write(f"# smallest pair gap {gap.min():.6g} m, wall gap {wall_gap:.6g} m\n")

    marks = [(t[draft], "drafting")]
    if kiss is not None:
        marks.append((t[kiss], "kissing"))
    if tumble is not None:
        marks.append((t[tumble], "tumbling"))

    fig, ax = plt.subplots(figsize=(3.2, 7))
    for p, name in ((a, "disk 0 (starts on top)"), (b, "disk 1")):
        ax.plot(p["x"] * 1e3, p["y"] * 1e3, label=name)
    for time, label in marks:
        i = int(np.searchsorted(t, time))
        for p in (a, b):
            ax.add_patch(plt.Circle((p["x"][i] * 1e3, p["y"][i] * 1e3), r * 1e3,
                                    fill=False, lw=0.8))
        ax.annotate(label, (a["x"][i] * 1e3 + 1.5, a["y"][i] * 1e3), fontsize=8)
    ax.set_xlim(lower[0] * 1e3, upper[0] * 1e3)
    ax.set_ylim(lower[1] * 1e3, upper[1] * 1e3)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(os.path.join(args.doc, "dkt-paths.png"), dpi=120)

    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(t, gap / (2 * r), label="gap between the disks / d")
    ax.plot(t, -dy / (2 * r), label="(y_1 - y_0) / d")
    for time, label in marks:
        ax.axvline(time, color="gray", lw=0.8, ls=":")
        ax.text(time, ax.get_ylim()[1] * 0.9, label, rotation=90, fontsize=8)
    ax.set_xlabel("t [s]")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.doc, "dkt-gap.png"), dpi=120)

    fig, ax = plt.subplots(figsize=(6, 3.5))
    for p, name in ((a, "disk 0"), (b, "disk 1")):
        ax.plot(t, p["v"] * 1e2, label=name + ", vertical")
        ax.plot(t, p["u"] * 1e2, ls="--", label=name + ", horizontal")
    for time, label in marks:
        ax.axvline(time, color="gray", lw=0.8, ls=":")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("velocity [cm/s]")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.doc, "dkt-velocity.png"), dpi=120)


def check_sequence(t, draft, kiss, tumble, smallest_gap, r, args):
    """The failed checks of the event sequence, as lines."""
    failures = []
    if kiss is None:
        failures.append("the disks never touch (no kissing)")
    elif not t[draft] < t[kiss]:
        failures.append("drafting does not come before kissing")
    if tumble is None:
        failures.append("the pair never turns over (no tumbling)")
    else:
        if kiss is not None and not t[kiss] < t[tumble]:
            failures.append("kissing does not come before tumbling")
        if t[tumble] > args.max_tumbling_time:
            failures.append(f"tumbling at t = {t[tumble]:.3f} s, after "
                            f"{args.max_tumbling_time} s")
    if smallest_gap < -args.max_overlap / 100 * r:
        failures.append(f"an overlap of {-smallest_gap:.3g} m, more than "
                        f"{args.max_overlap} % of the radius")
    return failures


if __name__ == "__main__":
    main()
