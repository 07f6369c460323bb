#!/usr/bin/env bash
# Builds cuda/ (Release) on a machine with an NVIDIA GPU, runs the CPU and GPU
# tests and the benchmark, and prints the benchmark table last.
#
# Usage: bash cuda/run_on_gpu.sh [build-dir]   (default: build-cuda beside cuda/)
# Logs go to $OUT when set (the device tool), else to <build-dir>/logs.
# CUDA_ARCHITECTURES overrides the default "90-real;75-virtual" (sm_90 + PTX).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build-cuda}
logs=${OUT:-$build/logs}
mkdir -p "$build" "$logs"
export PATH=/usr/local/cuda/bin:$PATH

echo "== device"
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm,clocks.max.mem --format=csv,noheader || true
nvcc --version | tail -1

echo "== build (Release)"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CUDA_ARCHITECTURES="${CUDA_ARCHITECTURES:-90-real;75-virtual}" >"$logs/configure.log" 2>&1 \
  || { cat "$logs/configure.log"; exit 1; }
grep "particulate_containment" "$logs/configure.log"
cmake --build "$build" -j"$(nproc)" >"$logs/build.log" 2>&1 || { tail -50 "$logs/build.log"; exit 1; }
grep -i "warning" "$logs/build.log" | head -20

status=0
echo "== CPU test (label unit)"
"$build/test_containment_cpu" >"$logs/test_cpu.log" 2>&1 || status=1
tail -3 "$logs/test_cpu.log"
echo "== GPU test (label gpu)"
"$build/test_containment_gpu" 2>&1 | tee "$logs/test_gpu.log"
rc=${PIPESTATUS[0]}
[ "$rc" -eq 0 ] || status=1
echo "== benchmark"
"$build/bench_containment" ${BENCH_ARGS:-} 2>&1 | tee "$logs/bench.log" | grep -v '^|'
[ "${PIPESTATUS[0]}" -eq 0 ] || status=1

echo "== summary: CPU test $(tail -1 "$logs/test_cpu.log"); GPU test rc=$rc"
grep '^|' "$logs/bench.log"
exit $status
