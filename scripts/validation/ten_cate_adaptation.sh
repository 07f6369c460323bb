#!/usr/bin/env bash
# Sedimentation with mesh adaptation (thesis §6.4, doc/deformation.md
# "Sedimentation with Laplace-kappa"): a ten Cate case on the regular mesh
# against the same mesh adapted to the sphere by Laplace-kappa every step
# (Width = one diameter, the other entries at their defaults), at
# Refinements = 0 and 1 with the case file's covered nodes ('inside') and at
# Refinements = 0 with 'Covered nodes = nearest'.
# Runs on 2 MPI ranks through ten_cate_levels.sh, then draws each family
# into one set of figures:
#   scripts/validation/ten_cate_adaptation.sh e4           (about 2 h)
#   scripts/validation/ten_cate_adaptation.sh e3 --r0-only (about 30 min)
# Figures and tables: doc/validation/ten-cate-<case>-kappa{,-nearest}/.
# SWEEPS=16 runs Laplace-kappa with that many 'Sweeps per level' (default 4)
# into output/ten-cate-<case>-r<level>[-nearest]-kappa-s16/ and draws
# doc/validation/ten-cate-<case>-kappa-s16[-nearest]/.
# END_TIME=1.0 stops every run there (E4 peaks at t = 0.8-0.9 s). A run whose
# folder already holds a finished run.log is not repeated.
set -euo pipefail
cd "$(dirname "$0")/../.."
case_name="$1"
levels=(0 1)
[[ "${2:-}" == "--r0-only" ]] && levels=(0)
kappa='subsection Mesh deformation\n  set Method = laplace-kappa\n  set Width  = 0.015\n'
tag=kappa
if [[ -n "${SWEEPS:-}" ]]; then
  kappa+="  set Sweeps per level = ${SWEEPS}\n"
  tag+="-s${SWEEPS}"
fi
kappa+='end\n'
time_prm=''
[[ -n "${END_TIME:-}" ]] && time_prm="subsection Time\\n  set End time = ${END_TIME}\\nend\\n"
# run_level <folder> <level> [environment...]: one ten_cate_levels.sh run,
# unless <folder> holds a finished one
run_level() {
  local folder="$1" level="$2"; shift 2
  grep -qs "Results are in" "$folder/run.log" && return 0
  env "$@" FIGURES="output/fig-$(basename "$folder")" \
    scripts/validation/ten_cate_levels.sh "$case_name" "$level"
}
for covered in "" nearest; do
  suffix="${covered:+-$covered}"
  [[ -n "$covered" ]] && levels=(0)
  figures="doc/validation/ten-cate-${case_name}-${tag}${suffix}"
  folders=(); labels=()
  for level in "${levels[@]}"; do
    plain="output/ten-cate-${case_name}-r${level}${suffix}"
    run_level "$plain" "$level" COVERED_NODES="$covered" EXTRA_PRM="$time_prm"
    run_level "$plain-$tag" "$level" COVERED_NODES="$covered" TAG="$tag" \
      EXTRA_PRM="$kappa$time_prm"
    folders+=("$plain" "$plain-$tag")
    labels+=("r=${level}, $((3 << level)) cells/D${covered:+, $covered}"
             "r=${level} + Laplace-kappa${SWEEPS:+, $SWEEPS sweeps}${covered:+, $covered}")
  done
  /usr/bin/env python3 scripts/validation/ten_cate.py "${folders[@]}" \
    --label "${labels[@]}" --doc "$figures"
done
