#include <particulate/core/time_series_writer.h>
#include <particulate/fluid/flow_diagnostics.h>
#include <particulate/fluid/flow_output.h>
#include <particulate/fluid/flow_simulation.h>
#include <particulate/fluid/navier_stokes.h>
#include <particulate/fluid/run_frame.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    void
    FlowCaseParameters::declare(ParameterHandler &prm)
    {
      core::SimulationParameters::declare(prm);
      core::TimeParameters::declare(prm);
      core::OutputParameters::declare(prm);
      core::MeshParameters::declare(prm);
      FluidParameters::declare(prm);
    }

    void
    FlowCaseParameters::parse(ParameterHandler &prm)
    {
      simulation.parse(prm);
      time.parse(prm);
      output.parse(prm);
      mesh.parse(prm);
      fluid.parse(prm);
      if (time.scheme == core::TimeParameters::Scheme::steady
          && fluid.linear_solver.velocity_preconditioner
               == VelocityPreconditioner::chebyshev)
        throw std::runtime_error(
          "subsection 'Linear solver': 'Velocity preconditioner = "
          "Chebyshev' works only for time-dependent flow (the mass term "
          "makes the velocity block easy); with 'Scheme = steady' in "
          "subsection 'Time' set it to 'AMG'.");
      // The geometric multigrid smooths only the symmetric part of the
      // velocity block, which the mass term dominates in time-dependent
      // flow only (fluid_generalized_newtonian_poiseuille: a steady flow it
      // does not carry).
      if (time.scheme == core::TimeParameters::Scheme::steady)
        fluid.linear_solver.multigrid_ruled_out_by = "steady flow";
    }



    template <int dim>
    FlowSimulation<dim>::FlowSimulation(const FlowCaseParameters &parameters,
                                        const std::string &parameter_file,
                                        MPI_Comm           comm)
      : parameters(parameters)
      , parameter_file(parameter_file)
      , communicator(comm)
    {}



    namespace {
      template <int dim>
      Point<dim>
      to_point(const std::vector<double> &v, const std::string &entry)
      {
        if (v.size() < dim)
          throw std::runtime_error("subsection 'Forces': the entry '" + entry
                                   + "' needs " + std::to_string(dim)
                                   + " coordinates.");
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = v[d];
        return p;
      }
    } // namespace



    template <int dim>
    FlowRunSummary
    FlowSimulation<dim>::run()
    {
      RunFrame<dim> frame(parameters, parameter_file, communicator);
      auto         &pcout  = frame.pcout;
      auto         &timer  = frame.timer;
      const auto   &tria   = frame.tria;
      const auto   &forces = parameters.fluid.forces;
      const auto   &time_p = parameters.time;
      const bool steady = time_p.scheme == core::TimeParameters::Scheme::steady;

      const auto mesh_ids = frame.create_mesh();
      for (const unsigned int id : forces.body_boundary_ids)
        if (std::find(mesh_ids.begin(), mesh_ids.end(), id) == mesh_ids.end())
          throw std::runtime_error(parameter_file
                                   + ": subsection 'Forces': 'Body boundary "
                                     "ids' names boundary id "
                                   + std::to_string(id)
                                   + ", which is not on the mesh.");
      const bool has_pressure_points = !forces.pressure_point_a.empty();
      Point<dim> point_a, point_b;
      if (has_pressure_points)
        {
          point_a = to_point<dim>(forces.pressure_point_a, "Pressure point A");
          point_b = to_point<dim>(forces.pressure_point_b, "Pressure point B");
        }

      NavierStokes<dim> flow(parameters.fluid, frame.tria, timer);
      flow.setup_dofs();
      flow.set_initial_condition(0.);
      pcout << frame.size_line(flow)
            << "\nVelocity solver: " << flow.velocity_solver_description()
            << std::endl;

      const auto indicator
        = forces.body_boundary_ids.empty() ?
            flow.make_ghosted_vector() :
            boundary_indicator(flow, forces.body_boundary_ids);
      const double coefficient_scale
        = 2.
          / (parameters.fluid.properties.density * forces.reference_velocity
             * forces.reference_velocity * forces.reference_area);

      std::vector<std::string> columns{"time"};
      const char              *axes[] = {"x", "y", "z"};
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back(std::string("F_") + axes[d]);
      for (const std::string name : {"c_D",
                                     "c_L",
                                     "c_D_volume",
                                     "c_L_volume",
                                     "delta_p",
                                     "kinetic_energy",
                                     "nonlinear_iterations",
                                     "linear_iterations",
                                     "time_step"})
        columns.push_back(name);
      const std::string     &dir = parameters.output.directory;
      core::TimeSeriesWriter series(dir + "/flow.dat", columns, communicator);
      FlowOutput<dim>        output(dir, "flow");

      FlowRunSummary summary;
      summary.n_dofs  = flow.n_dofs();
      summary.n_cells = tria.n_global_active_cells();
      const auto record =
        [&](const double time, const double dt, const SolveStatistics &stats) {
          TimerOutput::Scope scope(timer, "diagnostics");
          Tensor<1, dim>     f, f_volume;
          if (!forces.body_boundary_ids.empty())
            {
              f        = surface_force(flow, forces.body_boundary_ids);
              f_volume = volume_force(flow, indicator);
            }
          summary.drag_coefficient        = coefficient_scale * f[0];
          summary.lift_coefficient        = coefficient_scale * f[1];
          summary.drag_coefficient_volume = coefficient_scale * f_volume[0];
          summary.lift_coefficient_volume = coefficient_scale * f_volume[1];
          summary.pressure_difference
            = has_pressure_points ?
                pressure_at(flow, point_a) - pressure_at(flow, point_b) :
                0.;
          summary.kinetic_energy = kinetic_energy(flow);
          std::vector<double> row{time};
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(f[d]);
          for (const double v : {summary.drag_coefficient,
                                 summary.lift_coefficient,
                                 summary.drag_coefficient_volume,
                                 summary.lift_coefficient_volume,
                                 summary.pressure_difference,
                                 summary.kinetic_energy,
                                 double(stats.nonlinear_iterations),
                                 double(stats.linear_iterations),
                                 dt})
            row.push_back(v);
          series.write_row(row);
        };
      const auto write_fields = [&](const unsigned int step, const double t) {
        if (parameters.output.write_vtu)
          {
            TimerOutput::Scope scope(timer, "output");
            output.write(flow, step, t);
          }
      };

      frame.start_progress(0.);

      double       t    = 0.;
      double       dt   = time_p.time_step;
      unsigned int step = 0;
      if (steady)
        {
          SolveStatistics stats;
          {
            TimerOutput::Scope scope(timer, "time step (total)");
            stats = flow.advance(0., 0., core::TimeParameters::Scheme::steady);
          }
          summary.nonlinear_iterations += stats.nonlinear_iterations;
          summary.linear_iterations += stats.linear_iterations;
          record(0., 0., stats);
          write_fields(0, 0.);
          frame.report_step(0, 1., 0., stats);
          step = 1;
        }
      else
        {
          record(0., dt, SolveStatistics());
          write_fields(0, 0.);
          while (!frame.at_end_time(t))
            {
              dt = std::min(dt, time_p.end_time - t);
              SolveStatistics stats;
              {
                // everything of a step but diagnostics and output: what the
                // benchmarks divide by the steps
                TimerOutput::Scope scope(timer, "time step (total)");
                stats = flow.advance(t, dt, time_p.scheme);
              }
              summary.nonlinear_iterations += stats.nonlinear_iterations;
              summary.linear_iterations += stats.linear_iterations;
              t += dt;
              ++step;
              record(t, dt, stats);
              if (frame.fields_due(step, t))
                write_fields(step, t);
              frame.report_step(step, t, dt, stats);
              if (time_p.adaptive)
                dt = time_p.next_time_step(dt, flow.cfl_number(dt));
            }
        }
      summary.n_steps  = step;
      summary.end_time = t;

      // the quantities the case asked for in subsection Forces
      std::ostringstream results;
      if (!forces.body_boundary_ids.empty())
        results << "  c_D = " << summary.drag_coefficient
                << "  c_L = " << summary.lift_coefficient
                << "  (volume integral: c_D = "
                << summary.drag_coefficient_volume
                << ", c_L = " << summary.lift_coefficient_volume << ")";
      if (has_pressure_points)
        results << "  delta_p = " << summary.pressure_difference;
      if (!results.str().empty())
        pcout << "\nFinal:" << results.str().substr(1);
      pcout << "\nResults are in " << dir << "/ (flow.pvd, flow.dat)"
            << std::endl;
      frame.finish(flow, summary);
      if (flow_inspector)
        flow_inspector(flow);
      return summary;
    }

    template class FlowSimulation<2>;
    template class FlowSimulation<3>;
  } // namespace fluid
} // namespace particulate
