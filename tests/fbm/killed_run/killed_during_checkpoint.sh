#!/bin/sh
# A run killed (SIGKILL) half-way through writing a checkpoint, restarted,
# ends with the same numbers as an uninterrupted run.
#   killed_during_checkpoint.sh PARTICULATE SOURCE_DIR
# The settling disk (prm/settling-disk) on a coarse mesh (refinement 4) for
# 30 steps with a checkpoint every 10, on 2 ranks:
#  A: uninterrupted;
#  B: rank 0 kills itself half-way through its file of the second
#     checkpoint (step 20; PARTICULATE_KILL_DURING_CHECKPOINT=2): the run
#     must fail, the checkpoint of step 10 must be intact; then
#     'particulate --restart' continues from step 10 to the end.
# B's particle_0.dat and flow.dat must equal A's byte for byte (the rows the
# killed run wrote after step 10 are dropped by the restart).
# Then a few bytes in the middle of B's last checkpoint are overwritten: a
# restart must be refused, naming the file and the checksum, and leave the
# series as they were.
set -u
exe=$1 source=$2
here=$(pwd)/killed_during_checkpoint
rm -rf "$here"
mkdir -p "$here"

case_for() {
  sed -e 's|^\( *set Refinements *=\).*|\1 4|' \
      -e 's|^\( *set End time *=\).*|\1 0.03|' \
      -e "s|^\( *set Directory *=\).*|\1 $here/$1|" \
      "$source/prm/settling-disk/settling-disk.prm" > "$here/$1.prm"
  printf 'subsection Checkpoint\n  set Step interval = 10\nend\n' \
    >> "$here/$1.prm"
}
fail() {
  echo "FAILED: $*"
  exit 1
}

case_for a
case_for b
mpirun -np 2 "$exe" "$here/a.prm" > "$here/a.log" 2>&1 ||
  fail "the uninterrupted run failed: $(tail -5 "$here/a.log")"

PARTICULATE_KILL_DURING_CHECKPOINT=2 mpirun -np 2 "$exe" "$here/b.prm" \
  > "$here/b.log" 2>&1 && fail "the run to be killed ran to its end"
grep -q '^step  *20 ' "$here/b.log" ||
  fail "the run was not killed at its second checkpoint: $(tail -5 "$here/b.log")"
grep -q '^step  *21 ' "$here/b.log" &&
  fail "the run went on after its second checkpoint"
grep -q '^step 10$' "$here/b/checkpoint/info.txt" ||
  fail "the checkpoint of step 10 is not the current one"
[ -d "$here/b/checkpoint.new" ] ||
  fail "the cut-off checkpoint of step 20 left no trace"

mpirun -np 2 "$exe" --restart "$here/b.prm" > "$here/b-restart.log" 2>&1 ||
  fail "the restart failed: $(tail -5 "$here/b-restart.log")"
grep -q 'Restarting from .* (step 10)' "$here/b-restart.log" ||
  fail "the restart did not start at step 10"
for f in particle_0.dat flow.dat; do
  cmp "$here/a/$f" "$here/b/$f" ||
    fail "$f of the killed and restarted run differs from the uninterrupted one"
done

file=$here/b/checkpoint/rank-0.bin
printf 'XYZ' | dd of="$file" bs=1 seek=$(($(wc -c < "$file") / 2)) \
  conv=notrunc 2> /dev/null
mpirun -np 2 "$exe" --restart "$here/b.prm" > "$here/corrupt.log" 2>&1 &&
  fail "a restart from a corrupted checkpoint ran"
grep -q "rank-0.bin: its data do not match their checksum" "$here/corrupt.log" ||
  fail "the corrupted checkpoint is not named: $(tail -5 "$here/corrupt.log")"
for f in particle_0.dat flow.dat; do
  cmp "$here/a/$f" "$here/b/$f" ||
    fail "the refused restart changed $f"
done
echo "OK: killed in the checkpoint of step 20, restarted from step 10, the" \
  "series equal the uninterrupted run's; a corrupted checkpoint is refused"
