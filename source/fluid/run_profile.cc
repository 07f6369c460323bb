#include <particulate/fluid/navier_stokes.h>
#include <particulate/fluid/run_profile.h>

#include <deal.II/base/mpi.h>

#include <tuple>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    void
    collect_run_profile(const TimerOutput       &timer,
                        const NavierStokes<dim> &flow,
                        MPI_Comm                 comm,
                        RunProfile              &profile)
    {
      // the slowest rank sets the pace of a step
      for (const auto &[section, seconds] :
           timer.get_summary_data(TimerOutput::total_wall_time))
        profile.phase_seconds[section] = Utilities::MPI::max(seconds, comm);
      profile.phase_calls     = timer.get_summary_data(TimerOutput::n_calls);
      profile.n_velocity_dofs = flow.n_velocity_dofs();
      std::tie(profile.pressure_poisson_solves,
               profile.pressure_poisson_iterations)
        = flow.pressure_poisson_counts();
      profile.flow_memory_bytes
        = Utilities::MPI::sum(flow.memory_consumption(), comm);
      const SolverTraffic local = flow.solver_traffic();
      auto               &all   = profile.traffic;
      all.velocity_operator
        = Utilities::MPI::sum(local.velocity_operator, comm);
      all.gradient = Utilities::MPI::sum(local.gradient, comm);
      all.velocity_preconditioner
        = Utilities::MPI::sum(local.velocity_preconditioner, comm);
      all.pressure_laplacian_iteration
        = Utilities::MPI::sum(local.pressure_laplacian_iteration, comm);
      all.pressure_mass_inverse
        = Utilities::MPI::sum(local.pressure_mass_inverse, comm);
      all.system_vector = Utilities::MPI::sum(local.system_vector, comm);
    }

    template void
    collect_run_profile(const TimerOutput &,
                        const NavierStokes<2> &,
                        MPI_Comm,
                        RunProfile &);
    template void
    collect_run_profile(const TimerOutput &,
                        const NavierStokes<3> &,
                        MPI_Comm,
                        RunProfile &);
  } // namespace fluid
} // namespace particulate
