#!/bin/sh
# Run a shipped case on 2 ranks, optionally at another mesh level, and check
# its output with one of the analysis scripts in scripts/.
#   run_case_and_check.sh PARTICULATE SOURCE_DIR CASE LEVEL SCRIPT [OPTIONS...]
# CASE is relative to SOURCE_DIR (e.g. prm/jeffery-orbit/jeffery-2d.prm).
# LEVEL replaces the case's 'Refinements' and names the run
# ./<case>-r<LEVEL>; '-' keeps the case as shipped and names it ./<case>.
# SCRIPT (e.g. jeffery_orbit.py) reads that folder with --label <name> and
# OPTIONS (its bounds, e.g. --max-period-error 2); its exit status is the
# test's. END_TIME in the environment, if set, replaces the case's 'End
# time' (a run shortened to the part of the physics the check needs).
set -eu
exe=$1 source=$2 case=$3 level=$4 script=$5
shift 5
name=$(basename "$case" .prm)
set_level=
if [ "$level" != - ]; then
  name=$name-r$level
  set_level="s|^\( *set Refinements *=\).*|\1 $level|"
fi
out=$(pwd)/$name
# the case with its level and output folder replaced, next to the original
# (its relative paths stay valid)
copy=$(dirname "$source/$case")/_validation_$name.prm
trap 'rm -f "$copy"' EXIT
set_end=
if [ -n "${END_TIME:-}" ]; then
  set_end="s|^\( *set End time *=\).*|\1 $END_TIME|"
fi
sed -e "${set_level:-s|^||}" -e "${set_end:-s|^||}" \
    -e "s|^\( *set Directory *=\).*|\1 $out|" "$source/$case" > "$copy"
mpirun -np 2 "$exe" "$copy"
/usr/bin/python3 "$source/scripts/$script" "$out" --label "$name" "$@"
