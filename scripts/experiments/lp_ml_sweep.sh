#!/usr/bin/env bash
# The sweep of doc/developer/fluid.md, "L_p's V-cycle: the smoother":
# ML settings for the pressure Laplacian's V-cycle on a moving sphere (ten
# Cate E4 benchmark, matrix-free operator with the velocity multigrid,
# 'nearest', fractional-step theta, dt = 5 ms). Needs the experiment hook:
#   git apply scripts/experiments/lp-ml-environment-hook.patch
#   cmake --build build --target bench_coupled_step
#   scripts/experiments/lp_ml_sweep.sh 1          # level (2: STEPS=3)
# (and 'git apply -R' the patch afterwards). The settings are ML's on top of
# the code's own; the Jacobi-Chebyshev degree-2 row (type=Chebyshev, sweeps=2)
# is what 'Pressure Laplacian smoother = Chebyshev' gives.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
level="${1:-1}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export PARTICULATE_SOURCE_DIR="$root"
work="$(mktemp -d)"; cd "$work"
variants=(
  ""
  "smoother: type=Chebyshev;smoother: sweeps=2"
  "smoother: type=Chebyshev;smoother: sweeps=3"
  "smoother: type=Chebyshev;smoother: sweeps=4"
  "smoother: type=Chebyshev;smoother: sweeps=6"
  "smoother: type=Chebyshev;smoother: sweeps=2;smoother: Chebyshev alpha=30.0"
  "smoother: type=Block Chebyshev;smoother: sweeps=2"
  "smoother: type=Chebyshev;smoother: sweeps=2;aggregation: threshold=0.0"
  "smoother: type=Chebyshev;smoother: sweeps=2;aggregation: threshold=0.05"
  "smoother: type=Chebyshev;smoother: sweeps=2;aggregation: damping factor=0.0"
  "smoother: type=Chebyshev;smoother: sweeps=2;prec type=MGW"
  "smoother: type=Chebyshev;smoother: sweeps=2;max levels=2"
  "max levels=1"
  "smoother: type=symmetric Gauss-Seidel;smoother: sweeps=2"
  "smoother: sweeps=2"
)
for v in "${variants[@]}"; do
  PARTICULATE_LP_ML="$v" mpirun -np 2 "$root/build/tests/performance/fbm/bench_coupled_step" \
    --scheme "fractional-step theta" --time-step 0.005 --steps "${STEPS:-6}" --set "subsection Linear solver
 set Velocity preconditioner = geometric multigrid
 set Velocity operator = matrix-free
end
subsection Particles
 set Covered nodes = nearest
 subsection Particle 0
  set Velocity = 0, 0, -0.12
 end
end" "$level" > run.log 2>&1
  echo "## ${v:-code default (ILU(0), 1 sweep)}"
  grep -E "^\| $level \||Schur complement solves|Schur approximation: AMG|velocity preconditioner \|" run.log
done
