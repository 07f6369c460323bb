#!/usr/bin/env bash
# README command 1: set everything up (packages, configure, build) and run the
# quick-start case, then plot its drag and lift. Results: output/quickstart/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build/particulate prm/quickstart/quickstart.prm
/usr/bin/python3 scripts/plot_time_series.py output/quickstart/flow.dat \
  --columns c_D c_L delta_p --output output/quickstart/flow.png \
  --title "Quick start: cylinder in a channel, Re = 100"
