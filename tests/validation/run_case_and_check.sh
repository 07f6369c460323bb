#!/bin/sh
# Run shipped cases on 2 ranks, optionally at another mesh level, and check
# their output with one of the analysis scripts in scripts/.
#   run_case_and_check.sh PARTICULATE SOURCE_DIR CASE[,CASE...] LEVEL SCRIPT [OPTIONS...]
# CASE is relative to SOURCE_DIR (e.g. prm/jeffery-orbit/jeffery-2d.prm);
# several, separated by commas, are run one after the other.
# LEVEL replaces each case's 'Refinements' and names its run
# ./<case>-r<LEVEL>; '-' keeps the case as shipped and names it ./<case>.
# SCRIPT (e.g. jeffery_orbit.py) reads those folders with --label <name of
# the last> and OPTIONS (its bounds, e.g. --max-period-error 2); its exit
# status is the test's. END_TIME in the environment, if set, replaces the
# cases' 'End time' (a run shortened to the part of the physics the check
# needs).
set -eu
exe=$1 source=$2 cases=$3 level=$4 script=$5
shift 5
folders=
copies=
trap 'rm -f $copies' EXIT
for case in $(echo "$cases" | tr ',' ' '); do
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
  copies="$copies $copy"
  set_end=
  if [ -n "${END_TIME:-}" ]; then
    set_end="s|^\( *set End time *=\).*|\1 $END_TIME|"
  fi
  sed -e "${set_level:-s|^||}" -e "${set_end:-s|^||}" \
      -e "s|^\( *set Directory *=\).*|\1 $out|" "$source/$case" > "$copy"
  mpirun -np 2 "$exe" "$copy"
  folders="$folders $out"
done
/usr/bin/python3 "$source/scripts/$script" $folders --label "$name" "$@"
