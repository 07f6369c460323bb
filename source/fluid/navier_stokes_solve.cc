#include <particulate/fluid/navier_stokes.h>
#include <particulate/fluid/solver_failure.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "momentum_operator.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /**
       * Approximate action of L_p^{-1} (the discrete pressure Laplacian):
       * conjugate gradients with an AMG preconditioner to a loose relative
       * tolerance. The AMG V-cycle alone is not enough: the least-squares
       * commutator applies L_p^{-1} twice, and with Cahouet-Chabard FGMRES
       * needs several times the iterations for no faster step
       * (doc/performance.md, 'Pressure Laplacian: inner tolerance').
       */
      class PressureLaplaceInverse
      {
      public:
        PressureLaplaceInverse(const TrilinosWrappers::SparseMatrix    &matrix,
                               const TrilinosWrappers::PreconditionAMG &amg,
                               const double relative_tolerance)
          : matrix(matrix)
          , amg(amg)
          , relative_tolerance(relative_tolerance)
        {}

        void
        solve(TrilinosWrappers::MPI::Vector       &x,
              const TrilinosWrappers::MPI::Vector &b) const
        {
          ++solves;
          SolverControl                           control(200,
                                relative_tolerance * b.l2_norm(),
                                false,
                                false);
          SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
          x = 0;
          try
            {
              cg.solve(matrix, x, b, amg);
            }
          catch (const SolverControl::NoConvergence &)
            {
              // An inexact L_p^{-1} is still a valid preconditioner for the
              // flexible outer solver; FGMRES judges convergence itself.
            }
          iterations += control.last_step();
        }

        mutable unsigned int iterations = 0, solves = 0;

      private:
        const TrilinosWrappers::SparseMatrix    &matrix;
        const TrilinosWrappers::PreconditionAMG &amg;
        const double                             relative_tolerance;
      };



      /**
       * The saddle-point operator [A B^T; B 0] of the Newton system, either
       * the assembled block matrix or the matrix-free velocity block A with
       * the assembled (and constraint-masked) gradient B^T; B is its
       * transpose in both (B = -div).
       */
      class SystemOperator
      {
      public:
        using Vector        = TrilinosWrappers::MPI::Vector;
        using BlockVector   = TrilinosWrappers::MPI::BlockVector;
        using VelocityBlock = std::function<void(Vector &, const Vector &)>;

        explicit SystemOperator(
          const TrilinosWrappers::BlockSparseMatrix &matrix)
          : matrix(&matrix)
        {}

        SystemOperator(const VelocityBlock                  &velocity_block,
                       const TrilinosWrappers::SparseMatrix &gradient)
          : velocity_block(velocity_block)
          , gradient(&gradient)
        {}

        void
        vmult(BlockVector &dst, const BlockVector &src) const
        {
          if (matrix != nullptr)
            {
              matrix->vmult(dst, src);
              return;
            }
          velocity_block(dst.block(0), src.block(0));
          gradient->vmult_add(dst.block(0), src.block(1));
          gradient->Tvmult(dst.block(1), src.block(0));
        }

        /** dst = A src */
        void
        apply_velocity_block(Vector &dst, const Vector &src) const
        {
          if (matrix != nullptr)
            matrix->block(0, 0).vmult(dst, src);
          else
            velocity_block(dst, src);
        }

        /** dst = B^T src (pressure to velocity) */
        void
        apply_gradient(Vector &dst, const Vector &src) const
        {
          if (matrix != nullptr)
            matrix->block(0, 1).vmult(dst, src);
          else
            gradient->vmult(dst, src);
        }

        /** dst = B src (velocity to pressure) */
        void
        apply_divergence(Vector &dst, const Vector &src) const
        {
          if (matrix != nullptr)
            matrix->block(1, 0).vmult(dst, src);
          else
            gradient->Tvmult(dst, src);
        }

      private:
        const TrilinosWrappers::BlockSparseMatrix *matrix = nullptr;
        VelocityBlock                              velocity_block;
        const TrilinosWrappers::SparseMatrix      *gradient = nullptr;
      };



      /**
       * Upper block-triangular preconditioner P = [A B^T; 0 -S] with
       * S = B A^{-1} B^T (B = -div, so S is positive):
       *   x_p = -S^{-1} r_p,   x_u = A^{-1} (r_u - B^T x_p),
       * with one AMG V-cycle or a Chebyshev polynomial for A^{-1} and one of
       * two approximations of
       * S^{-1}:
       * - Cahouet-Chabard: theta_i mu M_p^{-1} + (rho/k) L_p^{-1};
       * - least-squares commutator: L_p^{-1} (B D^{-1} A D^{-1} B^T) L_p^{-1},
       * where L_p = B D^{-1} B^T and D is the lumped velocity mass matrix.
       */
      class BlockTriangularPreconditioner
      {
      public:
        using BlockVector = TrilinosWrappers::MPI::BlockVector;

        using VelocityInverse
          = std::function<void(TrilinosWrappers::MPI::Vector &,
                               const TrilinosWrappers::MPI::Vector &)>;

        BlockTriangularPreconditioner(
          const SystemOperator                    &system,
          const std::vector<IndexSet>             &owned_partitioning,
          const MPI_Comm                           communicator,
          const VelocityInverse                   &velocity_inverse,
          const TrilinosWrappers::PreconditionILU &mass_inverse,
          const PressureLaplaceInverse            &laplace_inverse,
          const TrilinosWrappers::MPI::Vector     &inverse_lumped_mass,
          const bool                               least_squares_commutator,
          const double                             viscous_weight,
          const double                             inertial_weight,
          TimerOutput                             &timer)
          : system(system)
          , velocity_inverse(velocity_inverse)
          , mass_inverse(mass_inverse)
          , laplace_inverse(laplace_inverse)
          , inverse_lumped_mass(inverse_lumped_mass)
          , least_squares_commutator(least_squares_commutator)
          , viscous_weight(viscous_weight)
          , inertial_weight(inertial_weight)
          , timer(timer)
          , tmp_u(owned_partitioning[0], communicator)
          , tmp_u2(tmp_u)
          , tmp_p(owned_partitioning[1], communicator)
        {}

        void
        vmult(BlockVector &dst, const BlockVector &src) const
        {
          {
            TimerOutput::Scope scope(timer, "fluid: Schur complement solves");
            apply_schur_inverse(dst.block(1), src.block(1));
          }
          system.apply_gradient(tmp_u, dst.block(1));
          tmp_u.sadd(-1., src.block(0));
          TimerOutput::Scope scope(timer, "fluid: velocity preconditioner");
          velocity_inverse(dst.block(0), tmp_u);
        }

      private:
        /** dst = -S^{-1} src, approximately. */
        void
        apply_schur_inverse(TrilinosWrappers::MPI::Vector       &dst,
                            const TrilinosWrappers::MPI::Vector &src) const
        {
          if (least_squares_commutator)
            {
              laplace_inverse.solve(tmp_p, src);
              system.apply_gradient(tmp_u, tmp_p);
              tmp_u.scale(inverse_lumped_mass);
              system.apply_velocity_block(tmp_u2, tmp_u);
              tmp_u2.scale(inverse_lumped_mass);
              system.apply_divergence(tmp_p, tmp_u2);
              laplace_inverse.solve(dst, tmp_p);
              dst *= -1.;
            }
          else
            {
              mass_inverse.vmult(dst, src);
              dst *= -viscous_weight;
              if (inertial_weight > 0.)
                {
                  laplace_inverse.solve(tmp_p, src);
                  dst.add(-inertial_weight, tmp_p);
                }
            }
        }

        const SystemOperator                    &system;
        const VelocityInverse                   &velocity_inverse;
        const TrilinosWrappers::PreconditionILU &mass_inverse;
        const PressureLaplaceInverse            &laplace_inverse;
        const TrilinosWrappers::MPI::Vector     &inverse_lumped_mass;
        const bool                               least_squares_commutator;
        const double                             viscous_weight;
        const double                             inertial_weight;
        TimerOutput                             &timer;
        mutable TrilinosWrappers::MPI::Vector    tmp_u, tmp_u2, tmp_p;
      };
    } // namespace



    namespace {
      /**
       * After FGMRES produced NaN or Inf: which ingredient did, so that the
       * message can say where to look (each part is applied to the
       * right-hand side once).
       */
      std::string
      locate_non_finite(
        const TrilinosWrappers::BlockSparseMatrix            *matrix,
        const TrilinosWrappers::MPI::BlockVector             &rhs,
        const BlockTriangularPreconditioner::VelocityInverse &velocity,
        const TrilinosWrappers::PreconditionILU              &mass,
        const PressureLaplaceInverse                         &laplace)
      {
        const auto finite = [](const TrilinosWrappers::MPI::Vector &v) {
          return std::isfinite(v.l2_norm());
        };
        if (!std::isfinite(rhs.l2_norm()))
          return "The right-hand side is not finite.";
        if (matrix != nullptr && !std::isfinite(matrix->frobenius_norm()))
          return "The system matrix is not finite.";
        TrilinosWrappers::MPI::Vector u(rhs.block(0)), p(rhs.block(1));
        velocity(u, rhs.block(0));
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
      /** Multiplication by the inverse diagonal of a Trilinos matrix
       *  (deal.II's DiagonalMatrix cannot be sized from one in 9.4). */
      struct Jacobi
      {
        TrilinosWrappers::MPI::Vector inverse_diagonal;

        void
        vmult(TrilinosWrappers::MPI::Vector       &dst,
              const TrilinosWrappers::MPI::Vector &src) const
        {
          dst = src;
          dst.scale(inverse_diagonal);
        }
      };
    } // namespace



    template <int dim>
    struct NavierStokes<dim>::VelocityChebyshev
    {
      PreconditionChebyshev<TrilinosWrappers::SparseMatrix,
                            TrilinosWrappers::MPI::Vector,
                            Jacobi>
        chebyshev;
    };



    /*
     * The Chebyshev polynomial spans the eigenvalue range of D^{-1} A (D the
     * diagonal of the velocity block A) that a few CG (Lanczos) steps
     * estimate; with smoothing range 0 it uses the estimated smallest
     * eigenvalue, so it acts as an approximate inverse, not a smoother. When
     * the mass term dominates, D^{-1} A has a condition number near that of
     * the Jacobi-scaled Q2 mass matrix (2.5^dim), whatever the mesh size.
     */
    template <int dim>
    void
    NavierStokes<dim>::build_velocity_chebyshev()
    {
      TimerOutput::Scope scope(timer, "fluid: velocity Chebyshev setup");
      const auto        &A        = system_matrix.block(0, 0);
      auto               jacobi   = std::make_shared<Jacobi>();
      auto              &diagonal = jacobi->inverse_diagonal;
      diagonal.reinit(owned_partitioning[0], communicator);
      for (const auto row : owned_partitioning[0])
        {
          const double a = A.diag_element(row);
          diagonal(row)  = a != 0. ? 1. / a : 1.;
        }
      diagonal.compress(VectorOperation::insert);
      typename decltype(VelocityChebyshev::chebyshev)::AdditionalData data;
      data.degree              = parameters.linear_solver.chebyshev_degree;
      data.smoothing_range     = 0.;
      data.eig_cg_n_iterations = 12;
      data.preconditioner      = jacobi;
      velocity_chebyshev       = std::make_shared<VelocityChebyshev>();
      velocity_chebyshev->chebyshev.initialize(A, data);
    }



    template <int dim>
    void
    NavierStokes<dim>::build_velocity_preconditioner()
    {
      TimerOutput::Scope             scope(timer, "fluid: velocity AMG setup");
      std::vector<std::vector<bool>> constant_modes;
      const FEValuesExtractors::Vector velocities(0);
      DoFTools::extract_constant_modes(dof_handler,
                                       fe.component_mask(velocities),
                                       constant_modes);
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.constant_modes = constant_modes;
      data.elliptic       = parameters.linear_solver.amg_elliptic;
      const std::string smoother
        = to_string(parameters.linear_solver.amg_smoother);
      data.smoother_type         = smoother.c_str();
      data.higher_order_elements = true;
      data.smoother_sweeps       = parameters.linear_solver.amg_smoother_sweeps;
      data.aggregation_threshold = 0.02;
      velocity_amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      velocity_amg->initialize(system_matrix.block(0, 0), data);
      amg_reference_iterations = 0;
    }



    template <int dim>
    void
    NavierStokes<dim>::linearise_velocity_multigrid(const Stage &stage)
    {
      TrilinosWrappers::MPI::Vector velocity(owned_partitioning[0],
                                             communicator);
      velocity          = solution.block(0);
      const bool steady = stage.time_step == 0.;
      velocity_multigrid->set_linearisation(
        velocity,
        steady ? 0. : parameters.properties.density / stage.time_step,
        stage.theta_implicit,
        *viscosity_model);
      velocity_multigrid_is_current = true;
    }



    /*
     * The velocity AMG hierarchy is kept across Newton iterations, stages and
     * time steps (its setup costs as much as a Krylov solve). A kept
     * hierarchy gets a limited number of iterations; if it needs more, or if
     * the count grows markedly over the one right after its construction, it
     * is rebuilt from the current matrix.
     */
    template <int dim>
    unsigned int
    NavierStokes<dim>::solve_linear(const Stage &stage, const double tolerance)
    {
      if (!schur_approximation_is_current)
        build_schur_complement_approximation();
      const bool use_chebyshev
        = parameters.linear_solver.velocity_preconditioner
          == VelocityPreconditioner::chebyshev;
      bool fresh = false;
      if (velocity_multigrid)
        {
          if (!velocity_multigrid_is_current)
            linearise_velocity_multigrid(stage);
          // linearised at this very matrix, unless the mesh has moved
          // since its geometry was built
          fresh = !multigrid_geometry_is_stale;
        }
      else if (use_chebyshev)
        {
          if (!velocity_chebyshev)
            build_velocity_chebyshev();
          fresh = true; // built from this very matrix
        }
      else if (!velocity_amg)
        {
          build_velocity_preconditioner();
          fresh = true;
        }

      TimerOutput::Scope       scope(timer, "fluid: linear solve");
      const bool               steady = stage.time_step == 0.;
      const double             mu     = viscosity_model->reference_viscosity();
      const SchurApproximation schur
        = parameters.linear_solver.schur_approximation;
      const bool least_squares_commutator
        = schur == SchurApproximation::least_squares_commutator
          || (schur == SchurApproximation::automatic && steady);
      // 'Pressure Poisson tolerance = automatic' (stored as 0): loose for
      // Cahouet-Chabard, tighter for LSC, which applies L_p^{-1} twice
      // (doc/performance.md, 'Pressure Laplacian: inner tolerance')
      const PressureLaplaceInverse laplace_inverse(
        pressure_laplacian,
        *laplace_amg,
        parameters.linear_solver.pressure_poisson_tolerance > 0. ?
          parameters.linear_solver.pressure_poisson_tolerance :
          (least_squares_commutator ? 1e-2 : 0.3));
      const unsigned int max_iterations
        = parameters.linear_solver.maximum_iterations;

      while (true)
        {
          const BlockTriangularPreconditioner::VelocityInverse velocity_inverse
            = [&](TrilinosWrappers::MPI::Vector       &dst,
                  const TrilinosWrappers::MPI::Vector &src) {
                if (velocity_multigrid)
                  velocity_multigrid->vmult(dst, src);
                else if (use_chebyshev)
                  velocity_chebyshev->chebyshev.vmult(dst, src);
                else
                  velocity_amg->vmult(dst, src);
              };
          const SystemOperator system
            = momentum_operator ? SystemOperator(
                [this](TrilinosWrappers::MPI::Vector       &dst,
                       const TrilinosWrappers::MPI::Vector &src) {
                  momentum_operator->vmult(dst, src);
                },
                constrained_gradient) :
                                  SystemOperator(system_matrix);
          const BlockTriangularPreconditioner preconditioner(
            system,
            owned_partitioning,
            communicator,
            velocity_inverse,
            *mass_ilu,
            laplace_inverse,
            inverse_lumped_mass,
            least_squares_commutator,
            stage.theta_implicit * mu,
            steady ? 0. : parameters.properties.density / stage.time_step,
            timer);
          const unsigned int reference = velocity_multigrid ?
                                           multigrid_reference_iterations :
                                           amg_reference_iterations;
          const unsigned int allowed
            = fresh ? max_iterations :
                      std::min(max_iterations, 2 * reference + 20);
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
                  // the kept hierarchy no longer fits the matrix
                  if (velocity_multigrid)
                    {
                      refresh_multigrid_geometry();
                      linearise_velocity_multigrid(stage);
                    }
                  else
                    build_velocity_preconditioner();
                  fresh = true;
                  continue;
                }
              std::ostringstream message;
              message << "The linear solver (FGMRES) did not converge in "
                      << e.last_step << " iterations (residual "
                      << e.last_residual << ", target " << tolerance << ").";
              if (!std::isfinite(e.last_residual))
                message << " "
                        << locate_non_finite(momentum_operator ? nullptr :
                                                                 &system_matrix,
                                             system_rhs,
                                             velocity_inverse,
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
          const unsigned int iterations = control.last_step();
          if (velocity_multigrid)
            {
              // with no fresh solve yet (a run or restart whose mesh moved
              // before its first solve) the first one stands in: its V-cycle
              // is one motion old, and counting all of its iterations as
              // extra would rebuild for nothing
              if (fresh || fresh_multigrid_iterations.empty())
                {
                  auto &recent = fresh_multigrid_iterations;
                  recent.push_back(iterations);
                  if (recent.size() > 5)
                    recent.erase(recent.begin());
                  std::vector<unsigned int> sorted = recent;
                  std::nth_element(sorted.begin(),
                                   sorted.begin() + sorted.size() / 2,
                                   sorted.end());
                  multigrid_reference_iterations = sorted[sorted.size() / 2];
                  if (parameters.linear_solver.verbose)
                    pcout << (fresh ? "      fresh V-cycle: " :
                                      "      first solve, taken as fresh: ")
                          << iterations << " FGMRES iterations (reference now "
                          << multigrid_reference_iterations << ")" << std::endl;
                }
              else
                {
                  // The stale V-cycle is rebuilt once it needs half as
                  // many iterations again as a fresh one (plus 5), the rule
                  // of the kept AMG below: a count, so that the choice and
                  // the run's numbers do not depend on the machine's load
                  const bool rebuild
                    = iterations > 1.5 * multigrid_reference_iterations + 5;
                  if (parameters.linear_solver.verbose)
                    pcout << "      kept V-cycle: " << iterations
                          << " FGMRES iterations against "
                          << multigrid_reference_iterations
                          << " with a fresh one" << (rebuild ? ": rebuilt" : "")
                          << std::endl;
                  if (rebuild)
                    refresh_multigrid_geometry(); // for the next solve
                }
              return iterations;
            }
          if (use_chebyshev)
            return iterations;
          if (fresh)
            amg_reference_iterations = iterations;
          else if (iterations > 1.5 * amg_reference_iterations + 5)
            velocity_amg.reset();
          return iterations;
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
          // last iteration of a stage stops there (10-20 % fewer FGMRES
          // iterations on ten Cate E4, doc/performance.md).
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
      using Scheme = core::TimeParameters::Scheme;
      std::vector<Stage> stages;
      switch (scheme)
        {
          case Scheme::steady:
            stages.push_back({0., 1., 0., time, time});
            break;
          case Scheme::backward_euler:
            stages.push_back({k, 1., 0., time, time + k});
            break;
          case Scheme::crank_nicolson:
            stages.push_back({k, 0.5, 0.5, time, time + k});
            break;
          case Scheme::fractional_step_theta:
            {
              // thesis eq. 5.14
              const double theta       = 1. - std::sqrt(2.) / 2.;
              const double theta_prime = 1. - 2. * theta;
              const double alpha       = (1. - 2. * theta) / (1. - theta);
              const double beta        = 1. - alpha;
              const double t1          = time + theta * k;
              const double t2          = time + (1. - theta) * k;
              stages.push_back({theta * k, alpha, beta, time, t1});
              stages.push_back({theta_prime * k, beta, alpha, t1, t2});
              stages.push_back({theta * k, alpha, beta, t2, time + k});
              break;
            }
        }
      // First Newton iterate of each stage: the solution at the stage's start
      // plus the rate of change over the last full time step. Fractional-step
      // theta's stages are not equally accurate snapshots of the flow (the
      // middle one swaps the implicit and explicit weights), and the body
      // velocities of an FBM run jump at the start of each step, so a rate
      // taken from one stage to the next extrapolates noise: it cost 10-20 %
      // more Newton and FGMRES iterations than no extrapolation at all
      // (doc/performance.md, "Initial guess").
      const bool extrapolate = parameters.nonlinear_solver.initial_guess
                                 == InitialGuess::extrapolated
                               && k > 0. && has_previous_solution
                               && time > previous_time;
      BlockVector rate;
      if (extrapolate)
        {
          rate.reinit(owned_partitioning, communicator);
          rate = solution;
          BlockVector previous(owned_partitioning, communicator);
          previous = previous_solution;
          rate -= previous;
          rate *= 1. / (time - previous_time);
        }
      previous_solution     = solution;
      previous_time         = time;
      has_previous_solution = k > 0.;

      SolveStatistics total;
      for (const Stage &stage : stages)
        {
          old_solution = solution;
          if (extrapolate)
            {
              BlockVector guess(owned_partitioning, communicator);
              guess = solution;
              guess.add(stage.time_new - stage.time_old, rate);
              solution = guess;
            }
          total += solve_stage(stage);
        }
      return total;
    }

    template void
    NavierStokes<2>::linearise_velocity_multigrid(const Stage &);
    template void
    NavierStokes<3>::linearise_velocity_multigrid(const Stage &);
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
