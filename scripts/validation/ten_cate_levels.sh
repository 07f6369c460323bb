#!/usr/bin/env bash
# Refinement study of a ten Cate case: run prm/ten-cate/ten-cate-<case>.prm
# at the given refinement levels (output/ten-cate-<case>-r<level>/) on 2 MPI
# ranks, then compare them with the experiment (scripts/validation/ten_cate.py,
# figures and table into output/fig-ten-cate-<case>/).
#   scripts/validation/ten_cate_levels.sh e4 0 1
# COVERED_NODES=nearest runs them with 'Covered nodes = nearest' (subsection
# Particles) into output/ten-cate-<case>-r<level>-nearest/. FIGURES=<dir>
# puts the figures and table there instead. EXTRA_PRM is
# appended to each case file (printf %b: '\n' for new lines), TAG to the
# folder names and labels, e.g.
#   EXTRA_PRM='subsection Time\n set Time step = 0.0025\nend\n' TAG=dt2.5ms
set -euo pipefail
cd "$(dirname "$0")/../.."
case_name="$1"; shift
base="prm/ten-cate/ten-cate-${case_name}.prm"
[[ -f "$base" ]] || { echo "no case file $base" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
folders=(); labels=()
for level in "$@"; do
  out="output/ten-cate-${case_name}-r${level}${COVERED_NODES:+-$COVERED_NODES}${TAG:+-$TAG}"
  mkdir -p "$out"
  # the case file with another 'Refinements' and output folder
  sed -e "s/^\( *set Refinements *=\).*/\1 ${level}/" \
      -e "s#^\( *set Directory *=\).*#\1 ${out}#" "$base" > "$out/case.prm"
  if [[ -n "${COVERED_NODES:-}" ]]; then
    printf 'subsection Particles\n  set Covered nodes = %s\nend\n' \
      "$COVERED_NODES" >> "$out/case.prm"
  fi
  if [[ -n "${EXTRA_PRM:-}" ]]; then
    printf '%b' "$EXTRA_PRM" >> "$out/case.prm"
  fi
  mpirun -np 2 build/particulate "$out/case.prm" | tee "$out/run.log" || true
  folders+=("$out"); labels+=("r=${level}, $((3 << level)) cells/D${COVERED_NODES:+, $COVERED_NODES}${TAG:+, $TAG}")
done
/usr/bin/env python3 scripts/validation/ten_cate.py "${folders[@]}" --label "${labels[@]}" \
  --doc "${FIGURES:-output/fig-ten-cate-${case_name}}"
