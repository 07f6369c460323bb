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
for level in "$@"; do
  scripts/validation/run_case_at_level.sh "$case" "$level" \
    "output/wind-tunnel-${name}-r${level}"
done
/usr/bin/python3 scripts/validation/wind_tunnel.py output/wind-tunnel-*-r*
