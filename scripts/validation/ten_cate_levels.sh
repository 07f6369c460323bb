#!/usr/bin/env bash
# Refinement study of a ten Cate case: run prm/ten-cate/ten-cate-<case>.prm
# at the given refinement levels (output/ten-cate-<case>-r<level>/) on 2 MPI
# ranks, then compare them with the experiment (scripts/validation/ten_cate.py,
# figures and table into output/fig-ten-cate-<case>/).
#   scripts/validation/ten_cate_levels.sh e4 0 1
# COVERED_NODES=nearest runs them with 'Covered nodes = nearest' (subsection
# Particles) into output/ten-cate-<case>-r<level>-nearest/; TIME_STEP=<s> with
# that 'Time step' (subsection Time) into ...-dt<s>/. FIGURES=<dir>
# puts the figures and table there instead. EXTRA_PRM is
# appended to each case file (printf %b: '\n' for new lines), TAG to the
# folder names and labels, e.g.
#   EXTRA_PRM='subsection Particles\n set Force integral = stress\nend\n' TAG=stress
set -euo pipefail
cd "$(dirname "$0")/../.."
case_name="$1"; shift
base="prm/ten-cate/ten-cate-${case_name}.prm"
[[ -f "$base" ]] || { echo "no case file $base" >&2; exit 1; }
folders=(); labels=()
for level in "$@"; do
  out="output/ten-cate-${case_name}-r${level}${COVERED_NODES:+-$COVERED_NODES}${TIME_STEP:+-dt$TIME_STEP}${TAG:+-$TAG}"
  extra="${EXTRA_PRM:-}"
  if [[ -n "${TIME_STEP:-}" ]]; then
    extra="subsection Time\n  set Time step = ${TIME_STEP}\nend\n${extra}"
  fi
  if [[ -n "${COVERED_NODES:-}" ]]; then
    extra="subsection Particles\n  set Covered nodes = ${COVERED_NODES}\nend\n${extra}"
  fi
  scripts/validation/run_case_at_level.sh "$base" "$level" "$out" "$extra" || true
  folders+=("$out"); labels+=("r=${level}, $((3 << level)) cells/D${COVERED_NODES:+, $COVERED_NODES}${TIME_STEP:+, dt $TIME_STEP s}${TAG:+, $TAG}")
done
/usr/bin/python3 scripts/validation/ten_cate.py "${folders[@]}" --label "${labels[@]}" \
  --doc "${FIGURES:-output/fig-ten-cate-${case_name}}"
