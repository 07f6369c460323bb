#!/usr/bin/env bash
# README command 1: set everything up (packages, configure, build), run the
# quick-start case on two MPI ranks and plot its particles. Results:
# output/quickstart/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# Open MPI refuses to start as root unless told that it is meant
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun -np 2 build/particulate prm/quickstart/quickstart.prm
/usr/bin/python3 scripts/plot_particles.py output/quickstart \
  --title "Quick start: six disks settling in a closed box"
