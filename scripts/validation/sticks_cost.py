#!/usr/bin/python3
"""Cost of the sticks-on-sphere case against the number of sticks.

    python3 scripts/validation/sticks_cost.py [--end-time T] [LAYERS ...]

runs prm/sticks-on-sphere/sticks.prm on 2 MPI ranks with its first 1, 2 and
4 layers of 25 sticks (or the LAYERS given) up to T (default 0.1 s), each
into output/sticks-cost-<n>/ with its log run.log, and prints a Markdown
table: sticks, time steps, wall seconds of the coupled steps (the timer
"coupled step (total)") and per step, per step and stick, and the share of
the rigid engine and of the containment. A run whose folder holds a finished
run.log is not repeated.
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
CASE = os.path.join(ROOT, "prm", "sticks-on-sphere", "sticks.prm")


def variant(layers, end_time, output):
    """The case text with only its first `layers` lattices, stopping at
    `end_time`, writing into `output`."""
    text = open(CASE).read()
    for k in range(layers, 4):
        text = re.sub(r"  subsection Lattice layer%d\n.*?\n  end\n" % k, "",
                      text, flags=re.S)
    text = re.sub(r"(set End time *=).*", r"\g<1> %g" % end_time, text)
    text = re.sub(r"(set Directory *=).*", r"\g<1> %s" % output, text)
    return text


def timer(log, section):
    """Wall seconds of a timer section in the run's summary table."""
    m = re.search(r"\| %s\s*\|\s*(\d+)\s*\|\s*([0-9.e+-]+)s" %
                  re.escape(section), log)
    return (int(m.group(1)), float(m.group(2))) if m else (0, 0.)


def run(layers, end_time):
    name = "sticks-cost-%d" % (25 * layers)
    output = os.path.join(ROOT, "output", name)
    log_path = os.path.join(output, "run.log")
    if os.path.exists(log_path) and "Total wallclock" in open(log_path).read():
        return open(log_path).read()
    os.makedirs(output, exist_ok=True)
    copy = os.path.join(os.path.dirname(CASE), "_validation_%s.prm" % name)
    with open(copy, "w") as f:
        f.write(variant(layers, end_time, output))
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    try:
        result = subprocess.run(
            ["mpirun", "-np", "2", os.path.join(ROOT, "build", "particulate"),
             copy], capture_output=True, text=True, env=env)
    finally:
        os.remove(copy)
    with open(log_path, "w") as f:
        f.write(result.stdout + result.stderr)
    if result.returncode != 0:
        sys.exit("sticks_cost.py: the run with %d sticks failed; see %s"
                 % (25 * layers, log_path))
    return result.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("layers", type=int, nargs="*", default=[1, 2, 4])
    parser.add_argument("--end-time", type=float, default=0.1)
    args = parser.parse_args()
    print("| sticks | steps | coupled steps [s] | per step [s] | per step "
          "and stick [ms] | rigid bodies | containment |")
    print("|---:|---:|---:|---:|---:|---:|---:|")
    for layers in args.layers:
        log = run(layers, args.end_time)
        steps, total = timer(log, "coupled step (total)")
        _, rigid = timer(log, "rigid bodies")
        _, containment = timer(log, "fbm: containment")
        _, constraints = timer(log, "fbm: constraints")
        containment += constraints
        n = 25 * layers
        print("| %d | %d | %.1f | %.2f | %.1f | %.1f %% | %.1f %% |"
              % (n, steps, total, total / steps, 1e3 * total / steps / n,
                 100. * rigid / total, 100. * containment / total))


if __name__ == "__main__":
    main()
