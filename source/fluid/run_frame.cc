#include <particulate/core/mesh.h>
#include <particulate/fluid/run_frame.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cstdio>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    RunFrame<dim>::RunFrame(const FlowCaseParameters &parameters,
                            const std::string        &parameter_file,
                            MPI_Comm                  comm)
      : pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      , timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
      , tria(comm)
      , case_parameters(parameters)
      , parameter_file(parameter_file)
      , communicator(comm)
    {}



    template <int dim>
    std::vector<types::boundary_id>
    RunFrame<dim>::create_mesh()
    {
      {
        TimerOutput::Scope scope(timer, "mesh");
        core::create_mesh(case_parameters.mesh, tria);
      }
      const auto ids = core::global_boundary_ids(tria);
      case_parameters.fluid.boundary_conditions.check(ids, parameter_file);
      return ids;
    }



    template <int dim>
    std::string
    RunFrame<dim>::size_line(const NavierStokes<dim> &flow) const
    {
      return "Mesh: " + std::to_string(tria.n_global_active_cells())
             + " cells, " + std::to_string(flow.n_dofs()) + " DoFs ("
             + std::to_string(flow.n_velocity_dofs()) + " velocity + "
             + std::to_string(flow.n_dofs() - flow.n_velocity_dofs())
             + " pressure) on "
             + std::to_string(Utilities::MPI::n_mpi_processes(communicator))
             + " rank(s)";
    }



    template <int dim>
    void
    RunFrame<dim>::start_progress(const double start)
    {
      const auto &time_p = case_parameters.time;
      progress           = std::make_unique<core::ProgressReporter>(
        pcout.get_stream(),
        start,
        time_p.scheme == core::TimeParameters::Scheme::steady ?
                    1. :
                    time_p.end_time);
    }



    template <int dim>
    void
    RunFrame<dim>::report_step(const unsigned int     step,
                               const double           time,
                               const double           time_step,
                               const SolveStatistics &s,
                               const std::string     &more) const
    {
      // the largest rank's resident set: a run whose memory grows step by
      // step shows it here
      dealii::Utilities::System::MemoryStats memory;
      dealii::Utilities::System::get_memory_stats(memory);
      const double resident_mib
        = dealii::Utilities::MPI::max(memory.VmRSS / 1024., communicator);
      if (!pcout.is_active())
        return;
      char buffer[96];
      std::snprintf(buffer,
                    sizeof(buffer),
                    "nonlinear %2u%s linear %4u",
                    s.nonlinear_iterations,
                    s.used_fixed_point ? "*" : " ",
                    s.linear_iterations);
      progress->report(step, time, time_step, buffer + more, resident_mib);
    }



    template <int dim>
    bool
    RunFrame<dim>::at_end_time(const double time) const
    {
      const double end = case_parameters.time.end_time;
      return time >= end - 1e-12 * std::max(1., end);
    }



    template <int dim>
    bool
    RunFrame<dim>::fields_due(const unsigned int step, const double time) const
    {
      const auto &output_p = case_parameters.output;
      return (output_p.interval > 0 && step % output_p.interval == 0)
             || at_end_time(time);
    }



    template <int dim>
    double
    RunFrame<dim>::elapsed_seconds() const
    {
      return progress->elapsed_seconds();
    }



    template <int dim>
    void
    RunFrame<dim>::finish(const NavierStokes<dim> &flow,
                          RunProfile              &profile) const
    {
      profile.wall_seconds = elapsed_seconds();
      timer.print_wall_time_statistics(communicator);
      collect_run_profile(timer, flow, communicator, profile);
    }

    template class RunFrame<2>;
    template class RunFrame<3>;
  } // namespace fluid
} // namespace particulate
