#include <particulate/fluid/navier_stokes.h>
#include <particulate/fluid/solver_failure.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <cmath>
#include <sstream>

#include "block_triangular_preconditioner.h"
#include "momentum_operator.h"
#include "saddle_point_operator.h"
#include "schur_complement.h"
#include "velocity_block_inverse.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /**
       * After FGMRES produced NaN or Inf: which ingredient did, so that the
       * message can say where to look (each part is applied to the
       * right-hand side once).
       */
      template <int dim>
      std::string
      locate_non_finite(const SaddlePointOperator                &system,
                        const TrilinosWrappers::MPI::BlockVector &rhs,
                        const VelocityBlockInverse<dim>          &velocity,
                        const TrilinosWrappers::PreconditionILU  &mass,
                        const PressureLaplaceInverse             &laplace)
      {
        const auto finite = [](const TrilinosWrappers::MPI::Vector &v) {
          return std::isfinite(v.l2_norm());
        };
        if (!std::isfinite(rhs.l2_norm()))
          return "The right-hand side is not finite.";
        const auto *matrix = system.assembled_matrix();
        if (matrix != nullptr && !std::isfinite(matrix->frobenius_norm()))
          return "The system matrix is not finite.";
        TrilinosWrappers::MPI::Vector u(rhs.block(0)), p(rhs.block(1));
        velocity.vmult(u, rhs.block(0));
        if (!finite(u))
          return "The velocity preconditioner returned NaN/Inf.";
        mass.vmult(p, rhs.block(1));
        if (!finite(p))
          return "The pressure mass ILU returned NaN/Inf.";
        laplace.solve(p, rhs.block(1));
        if (!finite(p))
          return "The pressure Laplacian solve (AMG on L_p) returned "
                 "NaN/Inf: L_p is probably singular next to a body.";
        return "Each preconditioner part alone is finite on the "
               "right-hand side.";
      }
    } // namespace



    template <int dim>
    VelocityLinearisation
    NavierStokes<dim>::velocity_linearisation(const Stage &stage) const
    {
      VelocityLinearisation a;
      a.matrix   = momentum_operator ? nullptr : &system_matrix.block(0, 0);
      a.velocity = &solution.block(0);
      a.mass_coefficient
        = stage.mass_coefficient(parameters.properties.density);
      a.theta_implicit = stage.theta_implicit;
      a.viscosity      = viscosity_model.get();
      return a;
    }



    /*
     * FGMRES with the block-triangular preconditioner. The velocity block
     * inverse may be one kept from an earlier matrix: it then gets a
     * limited number of iterations (twice what a fresh one needs, plus a
     * margin); if FGMRES needs more, it is rebuilt and the solve repeated.
     */
    template <int dim>
    unsigned int
    NavierStokes<dim>::solve_linear(const Stage &stage, const double tolerance)
    {
      if (!schur_approximation_is_current)
        build_schur_complement_approximation();
      const VelocityLinearisation linearisation = velocity_linearisation(stage);
      bool fresh = velocity_inverse->prepare(linearisation);

      TimerOutput::Scope       scope(timer, "fluid: linear solve");
      const bool               steady = stage.time_step == 0.;
      const SchurApproximation schur  = resolve_schur_approximation(
        parameters.linear_solver.schur_approximation,
        steady);
      const double poisson_tolerance
        = parameters.linear_solver.pressure_poisson_tolerance > 0. ?
            parameters.linear_solver.pressure_poisson_tolerance :
            automatic_pressure_poisson_tolerance(schur);
      const PressureLaplaceInverse laplace_inverse(pressure_laplacian,
                                                   *laplace_amg,
                                                   poisson_tolerance);
      const SaddlePointOperator    system
        = momentum_operator ? SaddlePointOperator(
            [this](TrilinosWrappers::MPI::Vector       &dst,
                   const TrilinosWrappers::MPI::Vector &src) {
              momentum_operator->vmult(dst, src);
            },
            constrained_gradient) :
                              SaddlePointOperator(system_matrix);
      SchurIngredients ingredients;
      ingredients.system              = &system;
      ingredients.laplace_inverse     = &laplace_inverse;
      ingredients.mass_inverse        = mass_ilu.get();
      ingredients.inverse_lumped_mass = &inverse_lumped_mass;
      ingredients.viscous_weight
        = stage.theta_implicit * viscosity_model->reference_viscosity();
      ingredients.inertial_weight
        = stage.mass_coefficient(parameters.properties.density);
      const auto schur_inverse
        = make_schur_complement_inverse(schur, ingredients);
      const BlockTriangularPreconditioner<dim> preconditioner(
        system,
        *velocity_inverse,
        *schur_inverse,
        owned_partitioning[0],
        communicator,
        timer);
      const unsigned int max_iterations
        = parameters.linear_solver.maximum_iterations;

      while (true)
        {
          const unsigned int allowed
            = fresh ?
                max_iterations :
                std::min(max_iterations,
                         2 * velocity_inverse->reference_iterations() + 20);
          SolverControl             control(allowed, tolerance, false, false);
          SolverFGMRES<BlockVector> solver(
            control,
            SolverFGMRES<BlockVector>::AdditionalData(
              parameters.linear_solver.krylov_size));
          newton_update = 0;
          try
            {
              solver.solve(system, newton_update, system_rhs, preconditioner);
            }
          catch (const SolverControl::NoConvergence &e)
            {
              if (!fresh)
                {
                  // the kept inverse no longer fits the matrix
                  velocity_inverse->rebuild(linearisation);
                  fresh = true;
                  continue;
                }
              std::ostringstream message;
              message << "The linear solver (FGMRES) did not converge in "
                      << e.last_step << " iterations (residual "
                      << e.last_residual << ", target " << tolerance << ").";
              if (!std::isfinite(e.last_residual))
                message << " "
                        << locate_non_finite(system,
                                             system_rhs,
                                             *velocity_inverse,
                                             *mass_ilu,
                                             laplace_inverse);
              throw SolverFailure(
                SolverFailure::Kind::linear,
                message.str(),
                "Reduce 'Time step' in subsection 'Time', or raise 'Maximum "
                "iterations' in subsection 'Linear solver'.");
            }
          zero_constraints.distribute(newton_update);
          pressure_poisson_solves += laplace_inverse.solves;
          pressure_poisson_iterations += laplace_inverse.iterations;
          velocity_inverse->record_solve(control.last_step(), fresh);
          return control.last_step();
        }
    }



    template <int dim>
    SolveStatistics
    NavierStokes<dim>::solve_stage(const Stage &stage)
    {
      const auto &nl = parameters.nonlinear_solver;
      make_constraints(stage.time_new);
      // The iterate starts from the previous solution with the new Dirichlet
      // values; the Newton updates then keep them (zero constraints).
      BlockVector iterate(owned_partitioning, communicator);
      iterate = solution;
      nonzero_constraints.distribute(iterate);
      for (const auto dof : decoupled_pressure_dofs)
        iterate(dof) = 0.;
      solution = iterate;
      if (momentum_operator)
        compute_explicit_residual(stage);

      SolveStatistics stats;
      bool            newton = nl.method == NonlinearMethod::newton;
      // A stage nearly always needs at least one iteration: assembling the
      // first matrix with the initial residual saves a residual assembly.
      assemble(stage, AssemblyTarget::jacobian_and_residual, newton);
      bool         matrix_is_current = true;
      double       residual          = system_rhs.l2_norm();
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
            assemble(stage, AssemblyTarget::jacobian, newton);
          matrix_is_current = false;
          // Inexact Newton: solving the update more accurately than a tenth
          // of the stage's target cannot lower the residual below it, so the
          // last iteration of a stage stops there.
          const unsigned int linear_iterations
            = solve_linear(stage,
                           std::max(parameters.linear_solver.relative_tolerance
                                      * residual,
                                    0.1 * target));
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
              for (const auto dof : decoupled_pressure_dofs)
                iterate(dof) = 0.;
              solution = iterate;
              assemble(stage, AssemblyTarget::residual, newton);
              new_residual = system_rhs.l2_norm();
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
            }
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
        normalise_pressure();
      return stats;
    }



    template <int dim>
    SolveStatistics
    NavierStokes<dim>::advance(const double                       time,
                               const double                       k,
                               const core::TimeParameters::Scheme scheme)
    {
      return time_integrator.advance(time,
                                     k,
                                     scheme,
                                     solution,
                                     old_solution,
                                     [this](const Stage &stage) {
                                       return solve_stage(stage);
                                     });
    }

    template VelocityLinearisation
    NavierStokes<2>::velocity_linearisation(const Stage &) const;
    template VelocityLinearisation
    NavierStokes<3>::velocity_linearisation(const Stage &) const;
    template unsigned int
    NavierStokes<2>::solve_linear(const Stage &, const double);
    template unsigned int
    NavierStokes<3>::solve_linear(const Stage &, const double);
    template SolveStatistics
    NavierStokes<2>::solve_stage(const Stage &);
    template SolveStatistics
    NavierStokes<3>::solve_stage(const Stage &);
    template SolveStatistics
    NavierStokes<2>::advance(const double,
                             const double,
                             const core::TimeParameters::Scheme);
    template SolveStatistics
    NavierStokes<3>::advance(const double,
                             const double,
                             const core::TimeParameters::Scheme);
  } // namespace fluid
} // namespace particulate
