#!/usr/bin/env bash
# The virtual wind tunnel (thesis §6.6) at the given refinement levels, on 2
# MPI ranks into output/wind-tunnel-<case>-r<level>/; then the table of
# scripts/validation/wind_tunnel.py over every such folder present.
#   scripts/validation/wind_tunnel.sh elephant 0 1 2
#   scripts/validation/wind_tunnel.sh elephant-unadapted 0 1 2
# CASE is a file of prm/wind-tunnel/ (its name without .prm).
set -euo pipefail
cd "$(dirname "$0")/../.."
name="$1"; shift
case="prm/wind-tunnel/${name}.prm"
[[ -f "$case" ]] || { echo "no case file $case" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for level in "$@"; do
  out="output/wind-tunnel-${name}-r${level}"
  mkdir -p "$out"
  # the copy stays next to the original, so that its relative paths hold
  copy="$(dirname "$case")/_validation_${name}-r${level}.prm"
  sed -e "s/^\( *set Refinements *=\).*/\1 ${level}/" \
      -e "s#^\( *set Directory *=\).*#\1 ${out}#" "$case" > "$copy"
  mpirun -np 2 build/particulate "$copy" | tee "$out/run.log"
  mv "$copy" "$out/case.prm"
done
/usr/bin/python3 scripts/validation/wind_tunnel.py output/wind-tunnel-*-r*
