#!/bin/sh
# Run a Jeffery-orbit case at a given mesh level and check it against
# Jeffery's closed form (scripts/jeffery_orbit.py and its bounds).
#   jeffery_orbit.sh PARTICULATE SOURCE_DIR CASE REFINEMENTS [OPTIONS...]
# CASE is relative to SOURCE_DIR (e.g. prm/jeffery-orbit/jeffery-2d.prm); the
# run goes to ./<case>-r<REFINEMENTS> on 2 ranks; OPTIONS go to the script
# (e.g. --max-period-error 2).
set -eu
exe=$1 source=$2 case=$3 level=$4
shift 4
name=$(basename "$case" .prm)-r$level
out=$(pwd)/$name
# the case with its level and output folder replaced, next to the original
# (its relative paths stay valid)
copy=$(dirname "$source/$case")/_validation_$name.prm
trap 'rm -f "$copy"' EXIT
sed -e "s|^\( *set Refinements *=\).*|\1 $level|" \
    -e "s|^\( *set Directory *=\).*|\1 $out|" "$source/$case" > "$copy"
mpirun -np 2 "$exe" "$copy"
/usr/bin/python3 "$source/scripts/jeffery_orbit.py" "$out" --label "$name" "$@"
