#ifndef particulate_tests_performance_bandwidth_bound_h
#define particulate_tests_performance_bandwidth_bound_h

// What memory bandwidth allows the linear solves of a run: the bytes its
// FGMRES solves moved at least (counts of the run times the traffic of one
// application of each part, fluid::SolverTraffic), over the machine's
// read bandwidth, against the time the solves took.

#include <particulate/fluid/run_profile.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "phase_table.h"

namespace particulate {
  namespace benchmarks {
    /** Bytes of one run's linear solves, per part, all ranks. */
    struct SolveTraffic
    {
      double operator_products = 0., velocity_cycles = 0., schur = 0.,
             krylov = 0.;

      double
      total() const
      {
        return operator_products + velocity_cycles + schur + krylov;
      }
    };

    /**
     * The counts of @p p priced with its traffic:
     * - FGMRES: one product with the saddle-point operator (A, B^T, B) per
     *   iteration and one per solve (the initial residual);
     * - each preconditioner application: a velocity block inverse and one
     *   product with B^T; each Schur application: M_p's ILU, and the CG
     *   iterations with L_p counted on their own;
     * - Krylov vectors: a solve of m iterations writes 2 m vectors (the
     *   basis and the preconditioned ones), reads the j vectors before the
     *   j-th in its orthogonalisation and the m preconditioned ones for
     *   the update, taken at the run's mean m per solve.
     */
    inline SolveTraffic
    solve_traffic(const fluid::RunProfile &p)
    {
      const auto calls = [&p](const std::string &name) {
        const auto it = p.phase_calls.find(name);
        return it == p.phase_calls.end() ? 0. : it->second;
      };
      const auto  &t          = p.traffic;
      const double iterations = p.linear_iterations;
      const double solves = std::max<double>(calls("fluid: linear solve"), 1.);
      const double m      = iterations / solves;
      SolveTraffic s;
      s.operator_products
        = (iterations + solves) * (t.velocity_operator + 2. * t.gradient);
      const double preconditioner_calls
        = calls("fluid: velocity preconditioner");
      s.velocity_cycles
        = preconditioner_calls * (t.velocity_preconditioner + t.gradient);
      s.schur
        = calls("fluid: Schur complement solves") * t.pressure_mass_inverse
          + p.pressure_poisson_iterations * t.pressure_laplacian_iteration;
      s.krylov = solves * (m * (m - 1.) / 2. + 3. * m) * t.system_vector;
      return s;
    }

    /** Per run: GB per step by part, the time they need at
     *  @p read_bandwidth [GB/s], and the FGMRES time measured. */
    inline void
    print_bandwidth_bound(const std::vector<ProfiledRun> &runs,
                          const double                    read_bandwidth)
    {
      std::printf(
        "\nBandwidth bound of the linear solves (fluid::SolverTraffic: the "
        "bytes the parts stream at least, all ranks, at %.1f GB/s read):\n\n"
        "| run | GB per step: operator products | V-cycles | Schur (L_p CG, "
        "M_p ILU) | Krylov vectors | total | bound [s per step] | FGMRES "
        "measured [s per step] | bound / measured |\n"
        "|---|---|---|---|---|---|---|---|---|\n",
        read_bandwidth);
      for (const auto &run : runs)
        {
          const auto   traffic = solve_traffic(*run.profile);
          const double n       = run.n_steps * 1e9;
          const double bound   = traffic.total() / n / read_bandwidth;
          const double measured
            = run.profile->seconds("fluid: linear solve") / run.n_steps;
          std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.3f | %.3f "
                      "| %.0f %% |\n",
                      run.label.c_str(),
                      traffic.operator_products / n,
                      traffic.velocity_cycles / n,
                      traffic.schur / n,
                      traffic.krylov / n,
                      traffic.total() / n,
                      bound,
                      measured,
                      100. * bound / measured);
        }
    }
  } // namespace benchmarks
} // namespace particulate

#endif
