#!/bin/sh
# Run prm/mixed-set/mixed-set.prm as shipped (2 ranks) and check it with
# scripts/mixed_set.py:
#   mixed_set.sh PARTICULATE SOURCE_DIR
# - momentum balance of the bodies in free fall within 0.5 % of the net
#   weight's impulse (each step's loads over that step, as the coupling
#   applies them);
# - at rest at the end: every speed below 1e-3 m/s;
# - deepest contact overlap of the inflated shapes below 7e-5 m, the rigid
#   engine's contact margin (2 % of the smallest bounding radius, 3.5 mm).
set -eu
exe=$1 source=$2
out=$(pwd)/mixed-set
copy=$source/prm/mixed-set/_validation_mixed-set.prm
trap 'rm -f "$copy"' EXIT
sed -e "s|^\( *set Directory *=\).*|\1 $out|" \
  "$source/prm/mixed-set/mixed-set.prm" > "$copy"
mpirun -np 2 "$exe" "$copy"
/usr/bin/python3 "$source/scripts/mixed_set.py" "$out" --label mixed-set \
  --max-balance-error 0.5 --max-final-speed 1e-3 --max-penetration 7e-5
