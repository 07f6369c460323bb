#!/usr/bin/env bash
# Runs one shipped case at another refinement level on 2 MPI ranks, for the
# level studies of scripts/validation/*.sh.
#   scripts/validation/run_case_at_level.sh CASE LEVEL OUT [EXTRA]
# CASE (a .prm path) is copied next to itself, so that its relative paths
# hold, with 'Refinements' set to LEVEL and 'Directory' to OUT; EXTRA, if
# given, is appended to the copy (printf %b: '\n' for new lines). The run's
# console goes to OUT/run.log as well, and the copy ends as OUT/case.prm.
# The exit status is the run's.
set -uo pipefail
case="$1" level="$2" out="$3" extra="${4:-}"
mkdir -p "$out"
copy="$(dirname "$case")/_validation_$(basename "$out").prm"
sed -e "s/^\( *set Refinements *=\).*/\1 ${level}/" \
    -e "s#^\( *set Directory *=\).*#\1 ${out}#" "$case" > "$copy"
[[ -z "$extra" ]] || printf '%b' "$extra" >> "$copy"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun -np 2 build/particulate "$copy" | tee "$out/run.log"
status=${PIPESTATUS[0]}
mv "$copy" "$out/case.prm"
exit "$status"
