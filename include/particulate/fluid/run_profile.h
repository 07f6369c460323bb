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
     * Bytes that one application of each part of the linear solve must
     * move between memory and the cores, from the sizes of the data the
     * part streams: a lower bound once the data exceed the caches (the
     * AMG's coarse levels, the velocity V-cycle's coarse solve and index
     * data beyond the matrices' column indices are not counted). With the
     * counts of a run and the machine's bandwidth they give the time a
     * memory-bound solve needs at least (tests/performance).
     */
    struct SolverTraffic
    {
      /// A v: the velocity block's data (matrix-free: geometry and
      /// linearisation fields; assembled: values and column indices) and
      /// the vectors read and written
      double velocity_operator = 0.;
      /// one product with B^T or B (values, column indices, vectors)
      double gradient = 0.;
      /// one application of the velocity block inverse
      double velocity_preconditioner = 0.;
      /// one CG iteration with L_p: its product, the finest level of its
      /// AMG V-cycle (smoother sweeps and residual) and the CG vectors
      double pressure_laplacian_iteration = 0.;
      /// one application of M_p's ILU (M_p's pattern) and its vectors
      double pressure_mass_inverse = 0.;
      /// one vector of the whole system (velocity and pressure)
      double system_vector = 0.;
    };

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
      /// the linear solve's traffic per application, all ranks (the
      /// solver as the run ended)
      SolverTraffic traffic;

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
