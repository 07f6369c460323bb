#!/usr/bin/env bash
# The table of doc/performance.md, "Preconditioners on a moving mesh": ten
# Cate E4 as shipped to t = 0.5 s (100 steps) on 2 ranks, once per policy
# for the preconditioners built from the mesh ('Multigrid on a moving mesh'),
# and once with the mesh fixed (the case's 'Mesh deformation' subsection
# left out). Prints one markdown row per run:
#   scripts/experiments/moving_mesh_preconditioners.sh [build/particulate]
# About 9 min; run it alone on the machine, the rows are wall times.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
exe="$(realpath "${1:-$root/build/particulate}")"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
case_file="$root/prm/ten-cate/ten-cate-e4.prm"

# name | sed script applied to the case file
variants=(
  "rebuild|s/^  set Velocity operator .*/&\n  set Multigrid on a moving mesh = rebuild/"
  "keep (default)|s/^x//"
  "mesh fixed|/^subsection Mesh deformation/,/^end/d"
)

timer() { # section name, log: calls and seconds of rank 0's timer
  awk -F'|' -v name="$1" '$2 ~ "^ "name" +$" {
    gsub(/ /, "", $3); split($4, t, "s"); gsub(/ /, "", t[1]);
    print $3, t[1]; found = 1 } END { if (!found) print 0, 0 }' "$2"
}

echo "| run | wall [s] | Schur builds (s) | V-cycle updates (s) | mesh motion [s] | Newton steps | FGMRES its | FGMRES [s] | w at t = 0.5 s [m/s] |"
echo "|---|---|---|---|---|---|---|---|---|"
for variant in "${variants[@]}"; do
  name="${variant%%|*}"
  edit="${variant#*|}"
  out="$work/run"
  rm -rf "$out"
  sed -e 's/^\( *set End time *=\).*/\1 0.5/' \
      -e "s|^\( *set Directory *=\).*|\1 $out|" -e "$edit" \
      "$case_file" > "$work/case.prm"
  mpirun -np 2 "$exe" "$work/case.prm" > "$work/log" 2>&1
  wall=$(timer "Total wallclock time elapsed" "$work/log" | cut -d' ' -f2)
  schur=$(timer "fluid: Schur approximation" "$work/log" | awk '{ print $1 " (" $2 ")" }')
  update=$(timer "fluid: velocity multigrid update" "$work/log" | awk '{ print $1 " (" $2 ")" }')
  motion=$(timer "fluid: mesh motion" "$work/log" | cut -d' ' -f2)
  solve=$(timer "fluid: linear solve" "$work/log" | cut -d' ' -f2)
  counts=$(awk '/^step/ { for (i = 1; i < NF; ++i) {
                  if ($i == "nonlinear") n += $(i + 1)
                  if ($i == "linear") l += $(i + 1) } }
                END { print n, l }' "$work/log")
  w=$(awk 'END { print $7 }' "$out/particle_0.dat")
  echo "| $name | $wall | $schur | $update | $motion | ${counts% *} | ${counts#* } | $solve | $w |"
done
