#!/usr/bin/env bash
# The table of doc/performance.md, "Velocity preconditioner": shipped cases
# that leave the velocity solver to the default, shortened, run on 2 ranks
# once as shipped ('automatic') and once with 'Velocity preconditioner =
# AMG'. Prints one markdown row per case: the wall times of the two runs and
# the last row of each run's particle_0.dat (flow.dat for a fluid run):
#   scripts/experiments/velocity_solver_defaults.sh [build/particulate]
# About 14 min; run it alone on the machine, the rows are wall times.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
exe="$(realpath "${1:-$root/build/particulate}")"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work="$(mktemp -d)"
trap 'rm -f "$root"/prm/*/_solver_defaults_*.prm; rm -rf "$work"' EXIT

# case file | end time ('' for the shipped one)
cases=(
  "quickstart/quickstart|"
  "oscillating-cylinder/oscillating-cylinder|0.5"
  "settling-disk/settling-disk|0.02"
  "dkt/dkt|0.1"
  "macro-scallop/newtonian|0.1"
  "jeffery-orbit/jeffery-2d|2.5"
  "cylinder-in-channel/cylinder-in-channel|1"
  "sphere-drag/fixed-sphere|"
)

# run CASE END PRECONDITIONER: prints the wall time; the output goes to
# $work/<case>-<preconditioner>
run() {
  local name="$1" end="$2" choice="$3" tag
  tag="$(basename "$name")-${choice}"
  # next to the original, so that its relative paths hold
  local copy="$root/prm/$(dirname "$name")/_solver_defaults_${tag}.prm"
  cp "$root/prm/$name.prm" "$copy"
  printf '\nsubsection Linear solver\n  set Velocity preconditioner = %s\nend\n' "$choice" >>"$copy"
  printf 'subsection Output\n  set Directory = %s\nend\n' "$work/$tag" >>"$copy"
  [[ -z "$end" ]] || printf 'subsection Time\n  set End time = %s\nend\n' "$end" >>"$copy"
  local start
  start=$(date +%s.%N)
  mpirun -np 2 "$exe" "$copy" >"$work/$tag.log" 2>&1
  awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }'
  rm -f "$copy"
}

last_row() { # output folder: the last data row of its time series
  local f="$1/particle_0.dat"
  [[ -f "$f" ]] || f="$1/flow.dat"
  grep -v '^#' "$f" | tail -1 | cut -d' ' -f1-7
}

echo "| case | automatic [s] | AMG [s] | last row, automatic | last row, AMG |"
echo "|---|---|---|---|---|"
for entry in "${cases[@]}"; do
  name="${entry%%|*}" end="${entry#*|}"
  a=$(run "$name" "$end" automatic)
  b=$(run "$name" "$end" AMG)
  printf '| %s | %.1f | %.1f | %s | %s |\n' "$name" "$a" "$b" \
    "$(last_row "$work/$(basename "$name")-automatic")" \
    "$(last_row "$work/$(basename "$name")-AMG")"
done
