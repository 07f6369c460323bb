#!/usr/bin/env bash
# Builds cuda/ (Release) on a machine with an NVIDIA GPU, runs the CPU and GPU
# tests and the benchmark, and prints the benchmark table last.
#
# Usage: bash cuda/run_on_gpu.sh [build-dir]   (default: build-cuda beside cuda/)
# Logs go to $OUT when set (the device tool), else to <build-dir>/logs.
# CUDA_ARCHITECTURES overrides the default "90-real;75-virtual" (sm_90 + PTX).
# BENCH_ARGS are passed to bench_containment. Where Nsight Compute (ncu) is
# installed, the kernels of the 129^3 scenes are also timed by the hardware
# (gpu__time_duration, median over launches) as a cross-check of the event
# timings; PARTICULATE_NCU=0 skips that.
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

ncu_log="$logs/ncu.log"
if [ "${PARTICULATE_NCU:-1}" != 0 ] && command -v ncu >/dev/null; then
  echo "== ncu: gpu__time_duration at 129^3 (clocks and caches as found)"
  : >"$ncu_log"
  for scene in 'map x1$' 'map x100' 'spheres x1$' 'spheres x100'; do
    echo "#### $scene" >>"$ncu_log"
    timeout 300 ncu --clock-control none --cache-control none --metrics gpu__time_duration.sum \
      -k 'regex:classify_kernel|io_only_kernel' "$build/bench_containment" --kernel-only \
      --launches 20 --size 129 --scene "$scene" >>"$ncu_log" 2>&1 || status=1
  done
  # Launches over all points only (classify() also launches per chunk);
  # median per scene and kernel.
  { echo "| scene (129^3) | kernel | launches | gpu__time_duration median us |"
    echo "|---|---|---:|---:|"
    awk '/^####/ { scene = substr($0, 6); sub(/\$$/, "", scene) }
       /(classify|io_only)_kernel.*\([0-9]+, 1, 1\)x/ {
         kernel = ($0 ~ /io_only_kernel/) ? "I/O only" : "classify"
         g = $0; sub(/.*\) \(/, "", g); sub(/,.*/, "", g); grid = g + 0 }
       /gpu__time_duration.sum/ {
         key = scene "|" kernel; unit = $(NF - 1); v = $NF + 0
         if (unit == "ns") v /= 1000; if (unit == "ms") v *= 1000
         if (grid > maxg[key]) { maxg[key] = grid; cnt[key] = 0 }
         if (grid == maxg[key]) vals[key, ++cnt[key]] = v }
       END {
         for (key in cnt) {
           n = cnt[key]; for (i = 1; i <= n; ++i) a[i] = vals[key, i]
           for (i = 2; i <= n; ++i) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; --j) a[j + 1] = a[j]; a[j + 1] = t }
           m = (n % 2) ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
           split(key, k, "|"); printf "| %s | %s | %d | %.2f |\n", k[1], k[2], n, m } }' \
    "$ncu_log" | sort; } >"$logs/ncu_summary.txt"
fi

echo "== summary: CPU test $(tail -1 "$logs/test_cpu.log"); GPU test rc=$rc"
grep '^|' "$logs/bench.log"
[ -s "$logs/ncu_summary.txt" ] && cat "$logs/ncu_summary.txt"
exit $status
