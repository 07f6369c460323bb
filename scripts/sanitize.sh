#!/usr/bin/env bash
# Builds the deal.II-free libraries (geometry, rigid, cuda's CPU path) and
# their tests with AddressSanitizer and UndefinedBehaviorSanitizer, and runs
# the default test set (ctest -LE 'validation|performance', as CI). Any
# sanitizer finding aborts the test that made it, and the script exits
# non-zero. See doc/developer/checks.md, section "Sanitizers".
#
# Usage: scripts/sanitize.sh [build-dir] [extra cmake arguments]
#   build-dir   default build-sanitize (relative to the repository root)
#   JOBS=n      parallel compile and test jobs (default: $(nproc))
#   TESTS=re    run only the tests whose names match the regular expression
#
# Choices:
# - A light build (-DPARTICULATE_WITH_DEALII=OFF): the deal.II modules link
#   an uninstrumented deal.II, Trilinos and MPI, whose own allocations and
#   intercepted calls give reports we cannot fix here.
# - CMAKE_BUILD_TYPE=Debug, compiled at -O2: assertions stay on (assert,
#   Eigen's index checks, CGAL's preconditions, and libstdc++'s with
#   -D_GLIBCXX_ASSERTIONS), which catch out-of-range access inside Eigen's
#   fixed-size objects and within a vector's capacity that ASan cannot see.
#   -O2 rather than Debug's -O0 or ASan's usual -O1: Eigen and CGAL need
#   inlining, and at -O1 rigid_planar_lock alone ran 18 minutes.
# - GCC's -fsanitize=undefined leaves out float-cast-overflow (Clang's
#   includes it); it is added, as a float converted to an int that cannot
#   hold it is undefined behaviour too.
# - The CUDA path is off (-DPARTICULATE_WITH_CUDA=OFF): nvcc-compiled code is
#   not instrumented. The gpu test then exits 77 and is reported as skipped,
#   as on any machine without a device.
# - validation and performance tests are excluded, as in README's test
#   command: in this build the validation tests are the unit tests'
#   executables run at larger sizes (hours here), the performance tests are
#   benchmarks.
set -euo pipefail
cd "$(dirname "$0")/.."
root_dir=$(pwd)
build_dir="${1:-build-sanitize}"
shift || true
jobs="${JOBS:-$(nproc)}"

sanitize="-fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer"
sanitize+=" -fno-sanitize-recover=undefined,float-cast-overflow"

cmake -S "$root_dir" -B "$build_dir" \
  -DPARTICULATE_WITH_DEALII=OFF \
  -DPARTICULATE_WITH_CUDA=OFF \
  -DCMAKE_BUILD_TYPE=Debug -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
  -DCMAKE_CXX_FLAGS_DEBUG="-O2 -g -D_GLIBCXX_ASSERTIONS" \
  -DCMAKE_CXX_FLAGS="$sanitize" \
  -DCMAKE_EXE_LINKER_FLAGS="$sanitize" \
  "$@"
cmake --build "$build_dir" -j "$jobs"

# CGAL's sample meshes, used by some geometry tests (as scripts/setup.sh).
cgal_data="$build_dir/cgal-data"
if [ ! -d "$cgal_data/data/meshes" ] \
  && [ -f /usr/share/doc/libcgal-dev/data.tar.gz ]; then
  mkdir -p "$cgal_data"
  tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$cgal_data" data/meshes
fi

# halt_on_error / abort_on_error: the first finding ends the test with a
# failure; detect_leaks: LeakSanitizer at exit. detect_stack_use_after_return
# stays off: it moves every frame to the heap and made the CGAL-heavy tests
# (deep AABB-tree recursion) run for hours.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1:print_summary=1"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1:print_summary=1"
suppressions="$root_dir/scripts/sanitize.supp"
if [ -f "$suppressions" ]; then
  export UBSAN_OPTIONS="$UBSAN_OPTIONS:suppressions=$suppressions"
fi

cd "$build_dir"
ctest --output-on-failure -j "$jobs" -LE 'validation|performance' \
  ${TESTS:+-R "$TESTS"}
