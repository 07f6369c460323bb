#!/usr/bin/env bash
# Drag of ten Cate E4's sphere at U = 0.128 m/s (Re = 31.8), held fixed in
# a uniform stream or translating through fluid at rest, at the given
# refinement levels, on 2 MPI ranks into output/<case>-r<level>/; then the
# table of scripts/validation/sphere_drag.py over every such folder present.
#   scripts/validation/sphere_drag.sh fixed-sphere 0 1 2
#   scripts/validation/sphere_drag.sh moving-sphere 0 1
#   scripts/validation/sphere_drag.sh moving-sphere-carried 0 1
#   scripts/validation/sphere_drag.sh path/to/fixed-sphere-halfway.prm 0
# CASE is a file of prm/sphere-drag/ or the path of a variant of one (a copy
# with an entry changed), whose name starts with fixed-sphere or
# moving-sphere; the rest of the name labels the variant in the table.
# From r = 1 on the runs use the geometric multigrid with the matrix-free
# operator (the case files' preconditioners are the fastest at r = 0).
set -euo pipefail
cd "$(dirname "$0")/../.."
case="$1"; shift
[[ "$case" == *.prm ]] || case="prm/sphere-drag/${case}.prm"
[[ -f "$case" ]] || { echo "no case file $case" >&2; exit 1; }
name=$(basename "$case" .prm)
[[ "$name" == fixed-sphere* || "$name" == moving-sphere* ]] \
  || { echo "$case: the name must start with fixed-sphere or moving-sphere" >&2; exit 1; }
gmg='subsection Linear solver\n  set Velocity preconditioner = geometric multigrid\n  set Velocity operator = matrix-free\nend\n'
for level in "$@"; do
  extra=
  (( level >= 1 )) && extra="$gmg"
  scripts/validation/run_case_at_level.sh "$case" "$level" \
    "output/${name}-r${level}" "$extra"
done
/usr/bin/python3 scripts/validation/sphere_drag.py output/fixed-sphere*-r* output/moving-sphere*-r*
