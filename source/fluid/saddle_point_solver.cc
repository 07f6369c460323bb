#include "saddle_point_solver.h"

#include <particulate/fluid/solver_failure.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <cmath>
#include <sstream>

#include "block_triangular_preconditioner.h"
#include "momentum_operator.h"
#include "pressure_laplacian_amg.h"
#include "saddle_point_operator.h"
#include "schur_complement.h"

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



    namespace {
      /** What the velocity preconditioner is built from at @p stage. */
      template <int dim>
      VelocityLinearisation
      velocity_linearisation(const FlowDiscretisation<dim> &d,
                             const Stage                   &stage)
      {
        VelocityLinearisation a;
        a.matrix   = d.assembled_velocity_block();
        a.velocity = &d.get_solution().block(0);
        a.mass_coefficient
          = stage.mass_coefficient(d.get_parameters().properties.density);
        a.theta_implicit = stage.theta_implicit;
        a.viscosity      = &d.get_viscosity_model();
        return a;
      }
    } // namespace



    template <int dim>
    SaddlePointSolver<dim>::SaddlePointSolver(const FluidParameters &parameters,
                                              TimerOutput           &timer,
                                              const ConditionalOStream &log)
      : parameters(parameters)
      , timer(timer)
      , log(log)
    {}



    template <int dim>
    SaddlePointSolver<dim>::~SaddlePointSolver() = default;



    template <int dim>
    void
    SaddlePointSolver<dim>::clear()
    {
      velocity_inverse.reset();
      laplace_amg.reset();
      laplace_near_null_space.clear();
      mass_ilu.reset();
      schur_state         = SchurState::missing;
      mass_ilu_is_current = false;
      gradient_is_current = false;
    }



    template <int dim>
    void
    SaddlePointSolver<dim>::setup(const FlowDiscretisation<dim> &d)
    {
      clear();
      velocity_inverse
        = make_velocity_block_inverse<dim>(parameters,
                                           d.get_dof_handler(),
                                           d.get_owned_partitioning()[0],
                                           d.get_mapping(),
                                           d.get_communicator(),
                                           timer,
                                           log);
    }



    template <int dim>
    const DoFHandler<dim> *
    SaddlePointSolver<dim>::velocity_dof_handler() const
    {
      return velocity_inverse->velocity_dof_handler();
    }



    template <int dim>
    void
    SaddlePointSolver<dim>::matrix_changed()
    {
      velocity_inverse->matrix_changed();
    }



    template <int dim>
    void
    SaddlePointSolver<dim>::set_masked_dofs(
      const std::vector<types::global_dof_index> &dofs)
    {
      velocity_inverse->set_masked_dofs(dofs);
    }



    template <int dim>
    void
    SaddlePointSolver<dim>::geometry_changing()
    {
      // B, M_p and the lumped velocity mass are assembled again in place
      // (same matrices, new values): L_p, its V-cycle and M_p's ILU stay
      // valid preconditioners, built on the mesh before the motion
      laplace_near_null_space.clear();
      if (schur_state == SchurState::current)
        schur_state = SchurState::aged;
      mass_ilu_is_current = false;
      gradient_is_current = false;
    }



    template <int dim>
    void
    SaddlePointSolver<dim>::mesh_moved()
    {
      velocity_inverse->mesh_moved();
    }



    template <int dim>
    void
    SaddlePointSolver<dim>::mesh_replaced()
    {
      velocity_inverse->mesh_replaced();
      schur_state = SchurState::missing;
    }



    template <int dim>
    void
    SaddlePointSolver<dim>::reset()
    {
      velocity_inverse->reset();
      schur_state = SchurState::missing;
    }



    template <int dim>
    void
    SaddlePointSolver<dim>::build_schur_ingredients(FlowDiscretisation<dim> &d)
    {
      TimerOutput::Scope scope(timer, "fluid: Schur approximation");
      {
        TimerOutput::Scope lp_scope(timer, "fluid: Schur approximation: L_p");
        // ML's ILU smoothers ask the matrix for its communicator when
        // destroyed: the old V-cycle goes before its matrix changes
        laplace_amg.reset();
        d.build_pressure_laplacian();
        structure_in_schur = d.pressure_operator_structure();
      }
      TimerOutput::Scope amg_scope(timer,
                                   "fluid: Schur approximation: AMG set-up");
      if (!mass_ilu_is_current) // M_p changes with the mesh only
        {
          mass_ilu = std::make_unique<TrilinosWrappers::PreconditionILU>();
          mass_ilu->initialize(d.get_pressure_mass());
          mass_ilu_is_current = true;
        }
      // A new V-cycle for every new L_p. Re-using the old aggregates
      // (PreconditionAMG::reinit) saves little, since the smoothers and
      // Galerkin products dominate the set-up; keeping the old V-cycle for
      // the updated L_p fails where a body frees a pressure, which was an
      // isolated row in the old operator.
      laplace_amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      const bool cells_are_blocks = initialize_pressure_laplacian_amg(
        *laplace_amg,
        d.get_pressure_laplacian(),
        d.get_dof_handler(),
        d.get_mapping(),
        d.get_owned_partitioning()[1],
        d.n_velocity_dofs(),
        parameters.linear_solver.pressure_laplacian_smoother,
        laplace_near_null_space,
        d.get_communicator());
      log << "      L_p AMG: "
          << (cells_are_blocks ? "aggregation by cells, constant mode" :
                                 "one near-null vector per pressure mode")
          << std::endl;
      schur_state = SchurState::current;
    }



    template <int dim>
    bool
    SaddlePointSolver<dim>::schur_ingredients_need_building(
      const FlowDiscretisation<dim> &d,
      const bool                     velocity_is_fresh) const
    {
      if (schur_state == SchurState::missing)
        return true;
      // Other covered nodes or decoupled pressures: another structure. A
      // step may mark its bodies more than once (where it starts, then at
      // the predicted interface); what counts is the marking solved with.
      const bool structure_changed
        = Utilities::MPI::logical_or(!(d.pressure_operator_structure()
                                       == structure_in_schur),
                                     d.get_communicator());
      if (structure_changed)
        return true;
      if (schur_state == SchurState::current)
        return false;
      // Aged: kept through the motions of the mesh as long as the velocity
      // V-cycle is, and built anew with it. The V-cycle is refreshed once
      // FGMRES needs markedly more iterations than with a fresh
      // preconditioner (VelocityMultigridInverse::record_solve); with the
      // Schur ingredients renewed at the same time, that reference count is
      // one of a preconditioner fresh in both blocks, and an aged L_p wears
      // the preconditioner out like an aged V-cycle. Kept until L_p's
      // structure changes, which on a carried mesh is only at a fresh
      // adaptation, they cost FGMRES 1.8 times the iterations over a
      // sedimentation (doc/performance.md, "Preconditioners on a moving
      // mesh"). A kept solve that fails rebuilds them (solve()).
      // Not with the assembled operator: there a kept L_p let Newton
      // diverge on a Laplace-alpha mesh pressed between a disk and a wall
      // (fbm_restart_matches_uninterrupted, '_carried').
      return velocity_is_fresh
             || parameters.linear_solver.multigrid_on_moving_mesh
                  == MultigridOnMovingMesh::rebuild
             || parameters.linear_solver.velocity_operator
                  == VelocityOperator::assembled;
    }



    /*
     * FGMRES with the block-triangular preconditioner. The velocity block
     * inverse and the Schur ingredients may be kept from an earlier matrix
     * or mesh: the solve then gets a limited number of iterations (twice
     * what a fresh one needs, plus a margin); if FGMRES needs more, both
     * are rebuilt and the solve repeated.
     */
    template <int dim>
    unsigned int
    SaddlePointSolver<dim>::solve(const Stage             &stage,
                                  const double             tolerance,
                                  FlowDiscretisation<dim> &discretisation,
                                  BlockVector             &newton_update)
    {
      if (!gradient_is_current)
        {
          discretisation.constrain_gradient();
          gradient_is_current = true;
        }
      const VelocityLinearisation linearisation
        = velocity_linearisation(discretisation, stage);
      bool fresh = velocity_inverse->prepare(linearisation);
      if (schur_ingredients_need_building(discretisation, fresh))
        build_schur_ingredients(discretisation);
      const unsigned int max_iterations
        = parameters.linear_solver.maximum_iterations;
      while (true)
        {
          const bool         kept = !fresh || schur_state == SchurState::aged;
          const unsigned int allowed
            = kept ?
                std::min(max_iterations,
                         2 * velocity_inverse->reference_iterations() + 20) :
                max_iterations;
          const FgmresOutcome outcome = run_fgmres(stage,
                                                   tolerance,
                                                   allowed,
                                                   discretisation,
                                                   newton_update);
          if (outcome.converged)
            {
              velocity_inverse->record_solve(outcome.iterations, fresh);
              return outcome.iterations;
            }
          if (kept)
            {
              // the kept preconditioner no longer fits the matrix
              if (!fresh)
                velocity_inverse->rebuild(linearisation);
              fresh = true;
              if (schur_state == SchurState::aged)
                build_schur_ingredients(discretisation);
              continue;
            }
          std::ostringstream message;
          message << "The linear solver (FGMRES) did not converge in "
                  << outcome.iterations << " iterations (residual "
                  << outcome.residual << ", target " << tolerance << ").";
          if (!outcome.non_finite_cause.empty())
            message << " " << outcome.non_finite_cause;
          throw SolverFailure(
            SolverFailure::Kind::linear,
            message.str(),
            "Reduce 'Time step' in subsection 'Time', or raise 'Maximum "
            "iterations' in subsection 'Linear solver'.");
        }
    }



    template <int dim>
    typename SaddlePointSolver<dim>::FgmresOutcome
    SaddlePointSolver<dim>::run_fgmres(const Stage             &stage,
                                       const double             tolerance,
                                       const unsigned int       allowed,
                                       FlowDiscretisation<dim> &discretisation,
                                       BlockVector             &newton_update)
    {
      const auto              &d = discretisation;
      TimerOutput::Scope       scope(timer, "fluid: linear solve");
      const bool               steady = stage.time_step == 0.;
      const SchurApproximation schur  = resolve_schur_approximation(
        parameters.linear_solver.schur_approximation,
        steady);
      const double poisson_tolerance
        = parameters.linear_solver.pressure_poisson_tolerance > 0. ?
            parameters.linear_solver.pressure_poisson_tolerance :
            automatic_pressure_poisson_tolerance(schur);
      const PressureLaplaceInverse laplace_inverse(d.get_pressure_laplacian(),
                                                   *laplace_amg,
                                                   poisson_tolerance);
      const MomentumOperator<dim> *momentum_operator
        = d.get_momentum_operator();
      const SaddlePointOperator system
        = momentum_operator ? SaddlePointOperator(
            [momentum_operator](TrilinosWrappers::MPI::Vector       &dst,
                                const TrilinosWrappers::MPI::Vector &src) {
              momentum_operator->vmult(dst, src);
            },
            d.get_constrained_gradient()) :
                              SaddlePointOperator(d.get_system_matrix());
      SchurIngredients ingredients;
      ingredients.system              = &system;
      ingredients.laplace_inverse     = &laplace_inverse;
      ingredients.mass_inverse        = mass_ilu.get();
      ingredients.inverse_lumped_mass = &d.get_inverse_lumped_mass();
      ingredients.viscous_weight
        = stage.theta_implicit * d.get_viscosity_model().reference_viscosity();
      ingredients.inertial_weight
        = stage.mass_coefficient(parameters.properties.density);
      const auto schur_inverse
        = make_schur_complement_inverse(schur, ingredients);
      const BlockTriangularPreconditioner<dim> preconditioner(
        system,
        *velocity_inverse,
        *schur_inverse,
        d.get_owned_partitioning()[0],
        d.get_communicator(),
        timer);
      SolverControl             control(allowed, tolerance, false, false);
      SolverFGMRES<BlockVector> solver(
        control,
        SolverFGMRES<BlockVector>::AdditionalData(
          parameters.linear_solver.krylov_size));
      newton_update = 0;
      FgmresOutcome outcome;
      try
        {
          solver.solve(system,
                       newton_update,
                       d.get_system_rhs(),
                       preconditioner);
        }
      catch (const SolverControl::NoConvergence &e)
        {
          outcome.converged  = false;
          outcome.iterations = e.last_step;
          outcome.residual   = e.last_residual;
          if (!std::isfinite(e.last_residual))
            outcome.non_finite_cause = locate_non_finite(system,
                                                         d.get_system_rhs(),
                                                         *velocity_inverse,
                                                         *mass_ilu,
                                                         laplace_inverse);
          return outcome;
        }
      discretisation.distribute_update(newton_update);
      pressure_poisson_solves += laplace_inverse.solves;
      pressure_poisson_iterations += laplace_inverse.iterations;
      outcome.iterations = control.last_step();
      outcome.residual   = control.last_value();
      return outcome;
    }



    namespace {
      /** Values and column indices of this rank's rows, and the row
       *  offsets: what one product streams of the matrix. */
      double
      stored_bytes(const TrilinosWrappers::SparseMatrix &matrix)
      {
        const Epetra_CrsMatrix &m = matrix.trilinos_matrix();
        return (sizeof(double) + sizeof(int)) * m.NumMyNonzeros()
               + sizeof(int) * (m.NumMyRows() + 1.);
      }
    } // namespace



    template <int dim>
    SolverTraffic
    SaddlePointSolver<dim>::traffic(const FlowDiscretisation<dim> &d) const
    {
      const auto   &owned           = d.get_owned_partitioning();
      const double  vector          = sizeof(double) * owned[0].n_elements();
      const double  pressure_vector = sizeof(double) * owned[1].n_elements();
      SolverTraffic t;
      t.system_vector      = vector + pressure_vector;
      const auto *momentum = d.get_momentum_operator();
      // the source read, the product written
      t.velocity_operator
        = 2. * vector
          + (momentum ? momentum->memory_consumption() :
                        stored_bytes(d.get_system_matrix().block(0, 0)));
      t.gradient = vector + pressure_vector
                   + stored_bytes(momentum ? d.get_constrained_gradient() :
                                             d.get_system_matrix().block(0, 1));
      t.velocity_preconditioner
        = velocity_inverse ?
            velocity_inverse->bytes_per_application(t.velocity_operator) :
            0.;
      // the CG product, and on the AMG's finest level the residual and
      // one pass over L_p (its ILU factors, or one Chebyshev product) per
      // smoother sweep before and after; CG's and the V-cycle's vectors
      const double sweeps = parameters.linear_solver.pressure_laplacian_smoother
                                == PressureLaplacianSmoother::ilu ?
                              2. :
                              4.;
      t.pressure_laplacian_iteration
        = (2. + sweeps) * stored_bytes(d.get_pressure_laplacian())
          + 8. * pressure_vector;
      t.pressure_mass_inverse
        = stored_bytes(d.get_pressure_mass()) + 2. * pressure_vector;
      return t;
    }



    template <int dim>
    std::size_t
    SaddlePointSolver<dim>::memory_consumption() const
    {
      return (velocity_inverse ? velocity_inverse->memory_consumption() : 0)
             + (laplace_amg ? laplace_amg->memory_consumption() : 0);
    }

    template class SaddlePointSolver<2>;
    template class SaddlePointSolver<3>;
  } // namespace fluid
} // namespace particulate
