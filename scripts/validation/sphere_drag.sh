#!/usr/bin/env bash
# Drag of ten Cate E4's sphere at U = 0.128 m/s (Re = 31.8), held fixed in
# a uniform stream (prm/sphere-drag/fixed-sphere.prm) or translating through
# fluid at rest (moving-sphere.prm), at the given refinement levels, on
# 2 MPI ranks into output/<frame>-sphere-r<level>[-<TAG>]/; then the table
# of scripts/validation/sphere_drag.py over every such folder present.
#   scripts/validation/sphere_drag.sh fixed 0 1 2
#   scripts/validation/sphere_drag.sh moving 0 1
# EXTRA_PRM is appended to each case file (printf %b: '\n' for new lines),
# TAG to the folder names, e.g.
#   EXTRA_PRM='subsection Particles\n set Covered nodes = inside\nend\n' TAG=inside
# From r = 1 on the runs use the geometric multigrid with the matrix-free
# operator (the case files' preconditioners are the fastest at r = 0).
set -euo pipefail
cd "$(dirname "$0")/../.."
frame="$1"; shift
base="prm/sphere-drag/${frame}-sphere.prm"
[[ -f "$base" ]] || { echo "no case file $base (frame: fixed or moving)" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for level in "$@"; do
  out="output/${frame}-sphere-r${level}${TAG:+-$TAG}"
  mkdir -p "$out"
  sed -e "s/^\( *set Refinements *=\).*/\1 ${level}/" \
      -e "s#^\( *set Directory *=\).*#\1 ${out}#" "$base" > "$out/case.prm"
  if (( level >= 1 )); then
    printf 'subsection Linear solver\n  set Velocity preconditioner = geometric multigrid\n  set Velocity operator = matrix-free\nend\n' >> "$out/case.prm"
  fi
  if [[ -n "${EXTRA_PRM:-}" ]]; then
    printf '%b' "$EXTRA_PRM" >> "$out/case.prm"
  fi
  mpirun -np 2 build/particulate "$out/case.prm" | tee "$out/run.log"
done
/usr/bin/env python3 scripts/validation/sphere_drag.py output/fixed-sphere-r* output/moving-sphere-r*
