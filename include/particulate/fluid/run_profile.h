#ifndef particulate_fluid_run_profile_h
#define particulate_fluid_run_profile_h

#include <deal.II/base/timer.h>

#include <cstddef>
#include <map>
#include <string>

#include <mpi.h>

namespace particulate {
  namespace fluid {
    template <int dim>
    class NavierStokes;

    /**
     * Where the time of a run went and what the flow solver needed: what
     * the benchmarks in tests/performance print. Both time loops (pure flow
     * and particulate flow) fill it at the end of their run.
     */
    struct RunProfile
    {
      /// wall seconds per timer section, the slowest rank's
      std::map<std::string, double> phase_seconds;
      /// how often each timer section ran (rank 0)
      std::map<std::string, double> phase_calls;
      /// summed over all steps and stages
      unsigned long nonlinear_iterations = 0, linear_iterations = 0;
      /// inner CG solves with L_p in the Schur complement approximation
      /// and their iterations (rank 0's counts; all ranks agree)
      unsigned long pressure_poisson_solves     = 0;
      unsigned long pressure_poisson_iterations = 0;
      unsigned long n_velocity_dofs             = 0;
      /// wall seconds of the whole run (rank 0's clock)
      double wall_seconds = 0.;
      /// the flow solver's matrices, preconditioners and vectors, all ranks
      std::size_t flow_memory_bytes = 0;

      /** Seconds of timer section @p name (0 when it never ran). */
      double
      seconds(const std::string &name) const
      {
        const auto it = phase_seconds.find(name);
        return it == phase_seconds.end() ? 0. : it->second;
      }
    };

    /** Fill the timer and solver parts of @p profile (not the iteration
     *  counts, which the time loop sums as it goes); collective. */
    template <int dim>
    void
    collect_run_profile(const dealii::TimerOutput &timer,
                        const NavierStokes<dim>   &flow,
                        MPI_Comm                   comm,
                        RunProfile                &profile);
  } // namespace fluid
} // namespace particulate

#endif
