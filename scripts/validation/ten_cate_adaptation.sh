#!/usr/bin/env bash
# Sedimentation with mesh adaptation (thesis §6.4,
# doc/validation/ten-cate-laplace-kappa.md): a ten Cate case on the regular mesh
# at Refinements = 0 and 1 against the mesh at Refinements = 0 adapted to the
# sphere by Laplace-kappa every step (Width = one diameter, the other entries
# at their defaults), with 'Covered nodes = inside', and all
# but Refinements = 1 again with 'Covered nodes = nearest'.
# Laplace-kappa runs twice: with the default 4 'Sweeps per level' (folder
# suffix -kappa) and with 16 (-kappa-s16; at Refinements = 0 there is a single
# level, and 4 sweeps move the vertices only part of the way).
# Runs on 2 MPI ranks through ten_cate_levels.sh, then draws each family
# into one set of figures, output/fig-ten-cate-<case>-kappa{,-nearest}/:
#   END_TIME=1.0 scripts/validation/ten_cate_adaptation.sh e4  (about 1 h 15 min)
#   scripts/validation/ten_cate_adaptation.sh e3 --r0-only     (about 30 min)
# END_TIME stops every run there (E4 peaks at t = 0.8-0.9 s). A run whose
# folder already holds a finished run.log is not repeated.
set -euo pipefail
cd "$(dirname "$0")/../.."
case_name="$1"
levels=(0 1)
[[ "${2:-}" == "--r0-only" ]] && levels=(0)
time_prm=''
[[ -n "${END_TIME:-}" ]] && time_prm="subsection Time\\n  set End time = ${END_TIME}\\nend\\n"
# pinned_prm <covered>: the settings of the study, which the case files no
# longer ship (they carry the mesh with the sphere): the mesh adapted afresh
# every step, 'Force integral = stress', the Chebyshev velocity
# preconditioner on the assembled operator, and 'Covered nodes = inside'
# unless <covered> names another marking
pinned_prm() {
  printf '%s' 'subsection Mesh deformation\n  set Moving bodies = re-adapt\nend\n'
  printf '%s' 'subsection Particles\n  set Force integral = stress\n'
  [[ -n "$1" ]] || printf '%s' '  set Covered nodes = inside\n'
  printf '%s' 'end\nsubsection Linear solver\n  set Velocity preconditioner = Chebyshev\n'
  printf '%s' '  set Velocity operator = assembled\nend\n'
}
# kappa_prm <sweeps>: the Laplace-kappa subsection
kappa_prm() {
  printf '%s' 'subsection Mesh deformation\n  set Method = laplace-kappa\n'
  printf '%s' '  set Width  = 0.015\n'
  [[ "$1" == 4 ]] || printf '  set Sweeps per level = %s\\n' "$1"
  printf '%s' 'end\n'
}
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
  folders=(); labels=()
  for level in "${levels[@]}"; do
    plain="output/ten-cate-${case_name}-r${level}${suffix}"
    run_level "$plain" "$level" COVERED_NODES="$covered" \
      EXTRA_PRM="$(pinned_prm "$covered")$time_prm"
    folders+=("$plain")
    labels+=("r=${level}, $((3 << level)) cells/D${covered:+, $covered}")
    [[ "$level" == 0 ]] || continue
    for sweeps in 4 16; do
      tag=kappa; [[ "$sweeps" == 4 ]] || tag+="-s${sweeps}"
      run_level "$plain-$tag" 0 COVERED_NODES="$covered" TAG="$tag" \
        EXTRA_PRM="$(pinned_prm "$covered")$(kappa_prm "$sweeps")$time_prm"
      folders+=("$plain-$tag")
      labels+=("r=0 + Laplace-kappa, $sweeps sweeps${covered:+, $covered}")
    done
  done
  /usr/bin/python3 scripts/validation/ten_cate.py "${folders[@]}" \
    --label "${labels[@]}" --doc "output/fig-ten-cate-${case_name}-kappa${suffix}"
done
