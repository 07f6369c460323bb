#!/usr/bin/python3
"""Where the wall time of whole runs goes (doc/performance.md, "Time to
solution"), from the log of `ctest -V` or of a single run:

    cd build && ctest -R 'validation_ten_cate_e[1-4]$' -V > ten-cate.log
    scripts/validation/run_phases.py build/ten-cate.log

prints one markdown row per run (named by its ctest test, or by the log's
file name): its coupled steps and time step, the total wall time, and the
seconds of rank 0's timers grouped by phase:
- Schur solves and velocity V-cycles (the applications inside FGMRES);
- the velocity multigrid's geometry updates and set-ups;
- L_p, its AMG and M_p's ILU built ('fluid: Schur approximation');
- the carried mesh: deformation, ALE motion and the flow's transfers onto
  fresh adaptations (the timer 'mesh deformation', which holds the other
  two);
- the coupling: containment, constraints and forces.
"""
import argparse
import os
import re

TIMER = re.compile(r"^\|\s*(.+?)\s*\|\s*(\d+)\s*\|\s*([0-9.e+-]+)s")
TOTAL = re.compile(r"^\|\s*Total wallclock time elapsed\s*\|\s*([0-9.e+-]+)s")
STEP = re.compile(r"^step\s+\d+\s+t = \S+\s+dt = (\S+)")
START = re.compile(r"^\s*Start\s+(\d+):\s+(\S+)")
PREFIX = re.compile(r"^(\d+): ?(.*)$")

PHASES = [
    ("Schur solves", ["fluid: Schur complement solves"]),
    ("V-cycles", ["fluid: velocity preconditioner"]),
    ("multigrid update, set-up",
     ["fluid: velocity multigrid update", "fluid: velocity multigrid setup"]),
    ("L_p and its AMG built", ["fluid: Schur approximation"]),
    ("carried mesh: deformation, motion, transfers",
     ["mesh deformation"]),  # holds 'fluid: mesh motion' and '... transfer'
    ("coupling", ["fbm: containment", "fbm: constraints", "fbm: forces"]),
]


def runs_in(path):
    """{run name: [lines]} of the log: per ctest test, or the whole file."""
    names, lines = {}, {}
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            start = START.match(line)
            if start:
                names[start.group(1)] = start.group(2)
                continue
            prefixed = PREFIX.match(line)
            if prefixed:
                lines.setdefault(prefixed.group(1), []).append(prefixed.group(2))
            else:
                lines.setdefault(None, []).append(line)
    if len(lines) > 1 or None not in lines:
        return {names.get(k, k): v for k, v in lines.items() if k is not None}
    return {os.path.basename(path): lines[None]}


def row(name, lines):
    timers, dt, steps, wall = {}, None, 0, None
    for line in lines:
        step = STEP.match(line)
        if step:
            dt = float(step.group(1))
        total = TOTAL.match(line)
        if total and wall is None:
            wall = float(total.group(1))
        timer = TIMER.match(line)
        if timer:
            label = timer.group(1)
            if label not in timers:  # rank 0's table comes first
                timers[label] = (int(timer.group(2)), float(timer.group(3)))
    if wall is None:
        return None
    steps = timers.get("coupled step (total)", (0, 0.))[0]
    cells = ["%d (%g ms)" % (steps, 1e3 * dt) if dt else str(steps),
             "**%.1f**" % wall]
    for _, sections in PHASES:
        cells.append("%.1f" % sum(timers.get(s, (0, 0.))[1] for s in sections))
    prefix = "validation_ten_cate_"
    if name.startswith(prefix):
        name = name[len(prefix):].upper()
    return "| %s | %s |" % (name, " | ".join(cells))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("logs", nargs="+")
    args = parser.parse_args()
    print("| case | steps (dt) | **wall time** | "
          + " | ".join(p for p, _ in PHASES) + " |")
    print("|---" * (3 + len(PHASES)) + "|")
    for path in args.logs:
        for name, lines in runs_in(path).items():
            line = row(name, lines)
            if line:
                print(line)


if __name__ == "__main__":
    main()
