#!/bin/sh
# Two runs of the same case on the same number of ranks write bitwise
# identical time series: no choice of the solvers, the rigid engine or the
# output may depend on wall-clock time, machine load or the order in which
# messages arrive.
#   same_case_twice.sh PARTICULATE SOURCE_DIR
# On 2 ranks, each case twice with wall-time checkpoints: the first run
# with an interval of 1e-6 minutes (it saves at every step a wall-time
# checkpoint may fall on, steps 10, 20, ...), the second with 1000 minutes
# (it saves only at its end). Neither the clock nor writing a checkpoint may change
# the numbers:
#  - drafting, kissing and tumbling (prm/dkt, 2D), refinement 0, 20 steps;
#  - the mixed set (prm/mixed-set, 3D: spheres, spheroids and boxes),
#    4 steps (within the first ten: determinism of the general shapes).
# Every .dat file of the first run must equal the second's byte for byte.
set -u
exe=$1 source=$2
here=$(pwd)/same_case_twice
rm -rf "$here"
mkdir -p "$here"

fail() {
  echo "FAILED: $*"
  exit 1
}

# write_case NAME PRM REFINEMENTS END_TIME WALL_MINUTES
write_case() {
  sed -e "s|^\( *set Refinements *=\).*|\1 $3|" \
      -e "s|^\( *set End time *=\).*|\1 $4|" \
      -e "s|^\( *set Directory *=\).*|\1 $here/$1|" \
      -e '/^ *subsection Checkpoint/,/^ *end/d' \
      "$source/$2" > "$here/$1.prm"
  printf 'subsection Checkpoint\n  set Wall-time interval = %s\nend\n' "$5" \
    >> "$here/$1.prm"
}

# run_twice NAME PRM REFINEMENTS END_TIME
run_twice() {
  for run in a b; do
    minutes=1e-6
    [ $run = b ] && minutes=1000
    write_case "$1-$run" "$2" "$3" "$4" $minutes
    mpirun -np 2 "$exe" "$here/$1-$run.prm" > "$here/$1-$run.log" 2>&1 ||
      fail "$1, run $run: $(tail -5 "$here/$1-$run.log")"
  done
  n=0
  for file in "$here/$1-a"/*.dat; do
    other="$here/$1-b/$(basename "$file")"
    cmp -s "$file" "$other" ||
      fail "$1: $(basename "$file") differs between two runs: $(cmp "$file" "$other")"
    n=$((n + 1))
  done
  [ $n -gt 0 ] || fail "$1 wrote no time series"
  echo "$1: $n time series identical in two runs"
}

run_twice dkt prm/dkt/dkt.prm 0 0.1
run_twice mixed-set prm/mixed-set/mixed-set.prm 0 0.02
echo OK
