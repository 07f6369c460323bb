#!/usr/bin/python3
"""Soak run: a coupled 3D case for 2 000 steps, with a checkpoint every 100
steps and ParaView output every 50, and the resident memory of the largest
rank recorded every 100 steps from the progress lines. The memory must stay
flat: after step 100 it may not grow by more than 2 %.

    scripts/validation/soak.py [--binary build/particulate] [--ranks 2]
                               [--case CASE] [--refinements 1]
                               [--steps 2000] [--output output/soak]
                               [--series doc/validation/soak.dat]
                               [--figure doc/validation/soak.png]
                               [--replot]

The case is by default prm/oscillating-cylinder/slab-3d-laplace-alpha.prm (a
cylinder moved back and forth through a 3D channel, the mesh around it
carried along by Laplace-alpha, geometric multigrid rebuilt as the mesh
moves); prm/ten-cate/ten-cate-e4.prm with --refinements 0 is a free sphere
coupled both ways (it settles, lands and rests on the floor). The case runs
at --refinements with a checkpoint every 100 steps and 'Interval = 50'; the
file actually run is written to the output folder. --replot only redraws
the figure from the series. Exits with 1 when the growth exceeds 2 %.
The default case runs on coarse cubes of 0.1 m (Subdivisions = 22, 4, 1)
with only its surface vertices carried: that mesh is adapted afresh, and the
multigrid rebuilt, whenever the carried one runs out of room (as shipped,
the slab's mesh is adapted once and carried for good).
"""
import argparse
import os
import re
import subprocess
import sys

DEFAULT_CASE = "prm/oscillating-cylinder/slab-3d-laplace-alpha.prm"
# the default case's mesh and mode for the soak, under which the mesh is
# adapted afresh as the cylinder moves
FRESH_ADAPTATIONS = [
    (r"(set Subdivisions\s*=\s*).*", r"\g<1>22, 4, 1"),
    (r"(set Moving bodies\s*=\s*).*", r"\g<1>carry surface vertices"),
]
PROGRESS = re.compile(r"^step\s+(\d+)\s.*\smemory (\d+) MiB")


def soak_case(case, text, steps, refinements, output):
    """The shipped case with the soak's resolution, length and intervals."""
    time_step = float(re.search(r"set Time step\s*=\s*(\S+)", text).group(1))
    text = re.sub(r"\nsubsection Checkpoint\n(?:.*\n)*?end\n", "\n", text)
    text += "subsection Checkpoint\n  set Step interval = 100\nend\n"
    replacements = [
        (r"(set Refinements\s*=\s*)\S+", r"\g<1>%d" % refinements),
        (r"(set End time\s*=\s*)\S+", r"\g<1>%g" % (steps * time_step)),
        (r"(subsection Output\n(?:.*\n)*?\s*set Interval\s*=\s*)\S+",
         r"\g<1>50"),
        (r"(set Directory\s*=\s*)\S+", r"\g<1>" + output),
    ]
    if os.path.exists(DEFAULT_CASE) and os.path.samefile(case, DEFAULT_CASE):
        replacements += FRESH_ADAPTATIONS
    for pattern, replacement in replacements:
        text, n = re.subn(pattern, replacement, text, count=1)
        if n != 1:
            sys.exit("soak: '%s' not found in %s" % (pattern, case))
    return text


def run(args):
    os.makedirs(args.output, exist_ok=True)
    case = os.path.join(args.output, "soak.prm")
    with open(args.case) as f:
        text = soak_case(args.case, f.read(), args.steps, args.refinements,
                         os.path.abspath(args.output))
    with open(case, "w") as f:
        f.write(text)
    command = ["mpirun", "-np", str(args.ranks), args.binary, case]
    memory = []
    with open(os.path.join(args.output, "soak.log"), "w") as log:
        process = subprocess.Popen(command, stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, text=True)
        for line in process.stdout:
            log.write(line)
            m = PROGRESS.match(line)
            if m and int(m.group(1)) % 100 == 0:
                memory.append((int(m.group(1)), int(m.group(2))))
                print("step %5d  memory %d MiB" % memory[-1], flush=True)
        if process.wait() != 0:
            sys.exit("soak: the run failed; see %s" % log.name)
    os.makedirs(os.path.dirname(args.series), exist_ok=True)
    with open(args.series, "w") as f:
        f.write("# soak run: %s at Refinements = %d, %d ranks; resident "
                "memory of the largest rank\n# step memory_MiB\n"
                % (args.case, args.refinements, args.ranks))
        for step, mib in memory:
            f.write("%d %d\n" % (step, mib))


def read_series(path):
    rows = [line.split() for line in open(path) if not line.startswith("#")]
    return [(int(s), int(m)) for s, m in rows]


def plot(series, figure):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    steps, mib = zip(*series)
    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.plot(steps, mib, "o-", ms=3)
    ax.set_xlabel("time step")
    ax.set_ylabel("resident memory, largest rank [MiB]")
    ax.set_ylim(0, 1.15 * max(mib))
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figure, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--binary", default="build/particulate")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--case", default=DEFAULT_CASE)
    parser.add_argument("--refinements", type=int, default=1)
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--output", default="output/soak")
    parser.add_argument("--series", default="doc/validation/soak.dat")
    parser.add_argument("--figure", default="doc/validation/soak.png")
    parser.add_argument("--replot", action="store_true")
    args = parser.parse_args()
    if not args.replot:
        run(args)
    series = read_series(args.series)
    plot(series, args.figure)
    after = [mib for step, mib in series if step >= 100]
    growth = (max(after) - after[0]) / after[0]
    print("soak: %d MiB at step %d, at most %d MiB after it: growth %.2f %%"
          % (after[0], 100, max(after), 100 * growth))
    return 0 if growth <= 0.02 else 1


if __name__ == "__main__":
    sys.exit(main())
