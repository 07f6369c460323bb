#!/usr/bin/env bash
# One-stop set-up on Debian bookworm: install the missing packages (as root),
# unpack CGAL's sample meshes, configure and build Particulate in build/
# (Release). Safe to run again: every step is skipped when already done.
#
# Usage: scripts/setup.sh [extra cmake arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
root_dir=$(pwd)
build_dir="${PARTICULATE_BUILD_DIR:-$root_dir/build}"

packages=(
  build-essential cmake ccache git pkg-config
  libdeal.ii-dev          # deal.II 9.4.1 with Trilinos, MPI, p4est, CGAL
  openmpi-bin libopenmpi-dev
  libeigen3-dev libcgal-dev
  libgsl-dev              # monotone cubic interpolation of viscosity tables
  libboost-dev            # Boost.CRC: the checksums of checkpoints
  libcgal-demo            # CGAL's sample surface meshes (data.tar.gz)
  libbullet-dev           # only the rigid-body benchmark links Bullet
  numdiff                 # regression tests compare outputs with tolerances
  python3 python3-numpy python3-matplotlib   # plots of every case
  clang-format
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "setup: missing Debian packages: ${missing[*]}" >&2
    echo "setup: run this script as root, or: sudo apt-get install ${missing[*]}" >&2
    exit 1
  fi
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# CGAL's sample meshes are used by tests and examples; they are not committed.
cgal_data="$build_dir/cgal-data"
if [ ! -d "$cgal_data/data/meshes" ]; then
  mkdir -p "$cgal_data"
  tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$cgal_data" data/meshes
fi

# nvcc lives outside PATH on the development image; CMake enables CUDA when found.
if [ -x /usr/local/cuda/bin/nvcc ] && ! command -v nvcc >/dev/null; then
  export PATH="/usr/local/cuda/bin:$PATH"
fi

if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S "$root_dir" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@"
fi
cmake --build "$build_dir" --parallel "$(nproc)"
