#include <particulate/fluid/navier_stokes.h>
#include <particulate/fluid/solver_failure.h>

#include <cmath>
#include <sstream>

#include "saddle_point_solver.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /** @p requested with the velocity solver of @p choice. */
      FluidParameters
      with_velocity_solver(const FluidParameters      &requested,
                           const VelocitySolverChoice &choice)
      {
        FluidParameters resolved                       = requested;
        resolved.linear_solver.velocity_preconditioner = choice.preconditioner;
        resolved.linear_solver.velocity_operator = choice.velocity_operator;
        return resolved;
      }
    } // namespace



    template <int dim>
    NavierStokes<dim>::NavierStokes(
      const FluidParameters                          &requested,
      parallel::fullydistributed::Triangulation<dim> &tria,
      TimerOutput                                    &timer)
      : velocity_solver(resolve_velocity_solver(requested.linear_solver,
                                                requested.boundary_conditions,
                                                tria))
      , parameters(with_velocity_solver(requested, velocity_solver))
      , pcout(std::cout,
              Utilities::MPI::this_mpi_process(tria.get_communicator()) == 0)
      , solver_log(std::cout,
                   parameters.linear_solver.verbose && pcout.is_active())
      , discretisation(parameters, tria, timer)
      , linear_solver(std::make_unique<SaddlePointSolver<dim>>(parameters,
                                                               timer,
                                                               solver_log))
      , time_integrator(parameters.nonlinear_solver.initial_guess)
    {}



    template <int dim>
    NavierStokes<dim>::~NavierStokes()
    {
      // the operator refers to the linear solver's velocity DoFs
      discretisation.release_operator();
    }



    template <int dim>
    void
    NavierStokes<dim>::setup_dofs()
    {
      // the operator before the velocity DoFs it works on, and the
      // preconditioners before the matrices they were built from
      discretisation.release_operator();
      linear_solver->clear();
      discretisation.distribute_dofs();
      linear_solver->setup(discretisation);
      discretisation.setup_operator(linear_solver->velocity_dof_handler());
      time_integrator.reinit(discretisation.get_owned_partitioning(),
                             discretisation.get_relevant_partitioning(),
                             discretisation.get_communicator());
      newton_update = discretisation.make_owned_vector();
    }



    template <int dim>
    void
    NavierStokes<dim>::set_fictitious_boundary_values(
      std::vector<std::pair<types::global_dof_index, double>> values,
      std::vector<types::global_dof_index>                    joint_dofs,
      std::vector<double>                                     start_values)
    {
      if (discretisation.set_fictitious_boundary_values(std::move(values),
                                                        std::move(joint_dofs),
                                                        std::move(
                                                          start_values)))
        linear_solver->pressure_operator_changed();
    }



    template <int dim>
    void
    NavierStokes<dim>::move_mesh(const std::function<void()> &move_vertices,
                                 const double                 time_step)
    {
      linear_solver->geometry_changing();
      discretisation.move_mesh(move_vertices, time_step);
      linear_solver->mesh_moved();
    }



    template <int dim>
    void
    NavierStokes<dim>::transfer_to_moved_mesh(
      const std::function<void()> &move_vertices)
    {
      linear_solver->geometry_changing();
      discretisation.transfer_to_moved_mesh(move_vertices);
      time_integrator.forget_history();
      linear_solver->mesh_replaced();
    }



    template <int dim>
    void
    NavierStokes<dim>::save_state(std::ostream &out) const
    {
      discretisation.save_solution(out);
      time_integrator.save(out);
    }



    template <int dim>
    void
    NavierStokes<dim>::load_state(std::istream &in)
    {
      discretisation.load_solution(in);
      time_integrator.load(in);
      reset_preconditioners();
    }



    template <int dim>
    void
    NavierStokes<dim>::reset_preconditioners()
    {
      linear_solver->reset();
    }



    template <int dim>
    std::size_t
    NavierStokes<dim>::memory_consumption() const
    {
      return discretisation.memory_consumption()
             + linear_solver->memory_consumption()
             + time_integrator.memory_consumption()
             + newton_update.memory_consumption();
    }



    template <int dim>
    SolverTraffic
    NavierStokes<dim>::solver_traffic() const
    {
      return linear_solver->traffic(discretisation);
    }



    template <int dim>
    std::pair<unsigned long, unsigned long>
    NavierStokes<dim>::pressure_poisson_counts() const
    {
      return linear_solver->pressure_poisson_counts();
    }



    template <int dim>
    void
    NavierStokes<dim>::assemble_jacobian(const Stage &stage,
                                         const bool   with_residual,
                                         const bool   newton)
    {
      discretisation.assemble(stage,
                              with_residual ? Target::jacobian_and_residual :
                                              Target::jacobian,
                              newton);
      linear_solver->matrix_changed();
    }



    template <int dim>
    SolveStatistics
    NavierStokes<dim>::solve_stage(const Stage &stage)
    {
      const auto &nl = parameters.nonlinear_solver;
      auto       &d  = discretisation;
      d.begin_stage(stage);
      linear_solver->set_masked_dofs(d.get_prescribed_velocity_dofs());
      BlockVector iterate = d.make_owned_vector();
      iterate             = d.get_solution();

      SolveStatistics stats;
      bool            newton = nl.method == NonlinearMethod::newton;
      // A shear-rate dependent viscosity makes Newton fail from rest (the
      // viscosity of fluid at rest is far from that of the flow), not only
      // far from a Newtonian solution at high Reynolds numbers: there the
      // stage returns to Newton once fixed-point steps have brought the
      // residual below a tenth of where Newton failed.
      const bool resume_newton
        = newton && d.get_viscosity_model().depends_on_shear_rate();
      double failed_newton_residual = 0.;
      // A stage nearly always needs at least one iteration: assembling the
      // first matrix with the initial residual saves a residual assembly.
      assemble_jacobian(stage, true, newton);
      bool         matrix_is_current = true;
      double       residual          = d.get_system_rhs().l2_norm();
      const double initial_residual  = residual;
      const double target            = std::max(nl.absolute_tolerance,
                                     nl.relative_tolerance * initial_residual);
      if (parameters.linear_solver.verbose)
        pcout << "      stage t = " << stage.time_old << " -> "
              << stage.time_new << ": initial residual " << initial_residual
              << " (target " << target << ")" << std::endl;

      // written so that a NaN residual enters the loop and is reported
      while (!(residual <= target))
        {
          if (!std::isfinite(residual))
            throw SolverFailure(
              SolverFailure::Kind::non_finite,
              "The flow solution is no longer finite (NaN or Inf in the "
              "residual at t = "
                + std::to_string(stage.time_new) + " s).",
              "The time step is probably too large for this mesh: reduce "
              "'Time step' in subsection 'Time'.");
          if (stats.nonlinear_iterations == nl.maximum_iterations)
            {
              std::ostringstream message;
              message << "The nonlinear solver did not converge in "
                      << nl.maximum_iterations
                      << " iterations at t = " << stage.time_new
                      << " s (residual " << residual << ", target " << target
                      << ").";
              throw SolverFailure(
                SolverFailure::Kind::nonlinear,
                message.str(),
                "Reduce 'Time step' in subsection 'Time' or raise 'Maximum "
                "iterations' in subsection 'Nonlinear solver'.");
            }
          // system_rhs already holds the residual of this iterate (the
          // damped update below assembled it)
          if (!matrix_is_current)
            assemble_jacobian(stage, false, newton);
          matrix_is_current = false;
          // Inexact Newton: solving the update more accurately than a tenth
          // of the stage's target cannot lower the residual below it, so the
          // last iteration of a stage stops there.
          const unsigned int linear_iterations = linear_solver->solve(
            stage,
            std::max(parameters.linear_solver.relative_tolerance * residual,
                     0.1 * target),
            d,
            newton_update);
          stats.linear_iterations += linear_iterations;
          ++stats.nonlinear_iterations;

          // damped update: halve the step until the residual decreases
          const BlockVector start        = iterate;
          double            step         = 1.;
          double            new_residual = 0.;
          for (unsigned int attempt = 0; attempt < 5; ++attempt)
            {
              iterate = start;
              iterate.add(step, newton_update);
              d.set_iterate(iterate);
              d.assemble(stage, Target::residual, newton);
              new_residual = d.get_system_rhs().l2_norm();
              if (new_residual < residual || !std::isfinite(residual))
                break;
              step *= 0.5;
            }
          if (new_residual >= residual && newton)
            {
              // Newton stagnates (far from the solution): use the more
              // robust fixed-point linearisation for the rest of the stage.
              newton                 = false;
              stats.used_fixed_point = true;
              failed_newton_residual = residual;
            }
          else if (!newton && resume_newton
                   && new_residual < 0.1 * failed_newton_residual)
            newton = true;
          if (parameters.linear_solver.verbose)
            pcout << "      nonlinear iteration " << stats.nonlinear_iterations
                  << ": residual " << new_residual << " (" << linear_iterations
                  << " FGMRES iterations, step " << step
                  << (newton ? ", Newton" : ", fixed point") << ")"
                  << std::endl;
          residual = new_residual;
        }
      stats.final_residual = residual;
      if (!parameters.boundary_conditions.pressure_is_determined())
        d.normalise_pressure();
      return stats;
    }



    template <int dim>
    SolveStatistics
    NavierStokes<dim>::advance(const double                       time,
                               const double                       k,
                               const core::TimeParameters::Scheme scheme)
    {
      discretisation.begin_step(time, k);
      return time_integrator.advance(
        time,
        k,
        scheme,
        discretisation.solution_for_time_integration(),
        discretisation.old_solution_for_time_integration(),
        [this](const Stage &stage) { return solve_stage(stage); });
    }

    template class NavierStokes<2>;
    template class NavierStokes<3>;
  } // namespace fluid
} // namespace particulate
