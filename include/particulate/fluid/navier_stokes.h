#ifndef particulate_fluid_navier_stokes_h
#define particulate_fluid_navier_stokes_h

#include <particulate/core/simulation_parameters.h>
#include <particulate/fluid/flow_discretisation.h>
#include <particulate/fluid/fluid_parameters.h>
#include <particulate/fluid/run_profile.h>
#include <particulate/fluid/time_integrator.h>
#include <particulate/fluid/velocity_solver_choice.h>
#include <particulate/fluid/viscosity_model.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace particulate {
  namespace fluid {
    template <int dim>
    class SaddlePointSolver;

    /**
     * Incompressible Navier-Stokes solver with Q2/P1disc elements on a
     * parallel::fullydistributed::Triangulation and Trilinos block matrices:
     * the facade the callers use over the flow solver's parts, and the
     * Newton iteration (with a fixed-point fallback) that joins them in a
     * stage.
     *
     * - FlowDiscretisation: DoFs, constraints, the residual and Jacobian of
     *   a stage (assembled, or the matrix-free MomentumOperator), the ALE
     *   terms, the solution.
     * - TimeIntegrator: the stages of fractional-step theta,
     *   Crank-Nicolson, backward Euler or the steady problem, and each
     *   stage's first iterate.
     * - SaddlePointSolver: FGMRES with the block-triangular preconditioner,
     *   made of a VelocityBlockInverse (algebraic multigrid,
     *   Jacobi-Chebyshev or geometric multigrid) and a
     *   SchurComplementInverse (Cahouet-Chabard or the least-squares
     *   commutator), each chosen by a factory from the case file's enum.
     *
     * The class knows nothing of particles. Users that impose extra
     * constraints (the fictitious boundary method) add them through
     * set_fictitious_boundary_values(); the ALE mesh velocity enters through
     * move_mesh() or set_mesh_velocity().
     */
    template <int dim>
    class NavierStokes
    {
    public:
      using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

      /** Keeps a copy of @p requested with its automatic choices made for
       *  @p tria (resolve_velocity_solver()). */
      NavierStokes(const FluidParameters &requested,
                   dealii::parallel::fullydistributed::Triangulation<dim> &tria,
                   dealii::TimerOutput &timer);
      ~NavierStokes();

      /**
       * Distribute DoFs and build constraints and matrices. The solution
       * is zero until set_initial_condition() (or load_state()).
       */
      void
      setup_dofs();

      /** Interpolate the initial condition at @p time. */
      void
      set_initial_condition(const double time)
      {
        discretisation.set_initial_condition(time);
      }

      /**
       * Advance from @p time by one macro step @p time_step with @p scheme
       * (three stages for fractional-step theta), or solve the steady
       * problem. Throws std::runtime_error when a solver diverges.
       */
      SolveStatistics
      advance(const double                       time,
              const double                       time_step,
              const core::TimeParameters::Scheme scheme);

      /** Solve one stage (public for tests of individual schemes). */
      SolveStatistics
      solve_stage(const Stage &stage);

      /**
       * Nodal interpolation of a velocity field (a function with dim
       * components) into the velocity components of @p vector (locally
       * owned layout); pressure entries are left untouched. deal.II's
       * VectorTools::interpolate cannot be used because FE_DGP has no
       * support points.
       */
      void
      interpolate_velocity(const dealii::Function<dim> &velocity,
                           BlockVector                 &vector) const
      {
        discretisation.interpolate_velocity(velocity, vector);
      }

      /**
       * Extra Dirichlet values on velocity DoFs, used by the fictitious
       * boundary method to impose the rigid velocity inside bodies (thesis
       * eq. 5.10c, 5.17): pairs of a locally relevant DoF index and its
       * value. They enter the constraints of every following stage (with
       * zero values for the Newton updates) on DoFs that the boundary
       * conditions and hanging nodes leave free, and stay until replaced.
       * Every rank must pass the values of all its locally relevant DoFs
       * inside bodies, so that the constraints agree across ranks.
       *
       * @p joint_dofs (sorted) are those of the values where the rigid
       * motions of two parts of one articulated body meet: no
       * divergence-free velocity takes both in one cell, so the cells with
       * one of them lose their continuity equations (their pressures are
       * decoupled, like those of cells inside a body).
       *
       * @p start_values, where given, are the same DoFs' values at the start
       * of the next time step (in the order of @p values): each stage of
       * that step then imposes the values interpolated linearly to its end
       * time, so that the nodes accelerate with the body through the stages
       * as a moving wall's Dirichlet values do. Imposed whole from the first
       * stage on, the acceleration of a multi-stage step would happen in its
       * first stage, and the pressure at the step's end would hold none of
       * the fluid's reaction to it (the added mass). Empty: @p values hold
       * for the whole step.
       */
      void
      set_fictitious_boundary_values(
        std::vector<std::pair<dealii::types::global_dof_index, double>> values,
        std::vector<dealii::types::global_dof_index> joint_dofs   = {},
        std::vector<double>                          start_values = {});

      /** ALE: mesh velocity w in the velocity components (ghosted). */
      void
      set_mesh_velocity(const BlockVector &mesh_velocity)
      {
        discretisation.set_mesh_velocity(mesh_velocity);
      }

      /**
       * ALE: @p move_vertices moves the triangulation's vertices (keeping
       * its connectivity) to where they are at the end of the next step of
       * length @p time_step. The nodal values stay with their nodes; the
       * mesh velocity w = (x_new - x_old) / time_step of every velocity
       * node enters the convection (u - w).grad u of that step, and the
       * matrices that depend only on the geometry (pressure mass, lumped
       * velocity mass) are rebuilt. Every rank must move the vertices of
       * its locally relevant cells alike.
       */
      void
      move_mesh(const std::function<void()> &move_vertices,
                const double                 time_step);

      /**
       * Remeshing: @p move_vertices moves the vertices (keeping the
       * connectivity) by more than a step's ALE motion can carry, e.g. to a
       * freshly adapted mesh. The velocity at every new node is evaluated
       * in the old mesh (finite-element interpolation, across ranks) and
       * the mesh does not move during the next step (w = 0). The pressure
       * keeps its cell-wise coefficients (the next solve determines it);
       * the next stage starts without extrapolation. Collective; every
       * rank must move the vertices of its locally relevant cells alike.
       * Throws std::runtime_error if a new node lies outside the old mesh.
       */
      void
      transfer_to_moved_mesh(const std::function<void()> &move_vertices);

      /**
       * Checkpoint: writes what the next advance() depends on, this rank's
       * part (locally owned entries of the current solution and of the
       * previous stage's start value used for extrapolation, and that
       * stage's time). The mesh and DoF numbering are not written: a
       * restart rebuilds them from the case file on the same number of
       * ranks, and load_state() checks that they match.
       */
      void
      save_state(std::ostream &out) const;

      /** Reads what save_state() wrote (after setup_dofs()). Throws
       *  std::runtime_error when the DoF layout differs. */
      void
      load_state(std::istream &in);

      /** The state a time step starts from, kept in memory. */
      struct StepStart
      {
        BlockVector             solution;
        TimeIntegrator::History history;
      };

      /** The current state, for a step that may have to be solved again
       *  (an implicitly coupled FBM step). */
      StepStart
      step_start() const
      {
        return {discretisation.get_solution(), time_integrator.history()};
      }

      /** Return to @p start, as if the steps since step_start() had not
       *  been taken. The mesh and DoFs must be the same; the kept
       *  preconditioners stay. */
      void
      return_to(const StepStart &start)
      {
        discretisation.restore_solution(start.solution);
        time_integrator.restore(start.history);
      }

      /**
       * Drops the kept preconditioners (velocity AMG, Schur complement
       * approximation); the next solve rebuilds them from its matrix. A
       * run does this whenever it saves a checkpoint, so that it and a run
       * restarted from that checkpoint compute the same numbers.
       */
      void
      reset_preconditioners();

      /**
       * Bytes held by this rank's matrices, preconditioners and vectors
       * (the performance benchmark reports it per DoF).
       */
      std::size_t
      memory_consumption() const;

      /** What one application of each part of the linear solve moves
       *  through memory on this rank (the benchmarks' bandwidth bound). */
      SolverTraffic
      solver_traffic() const;

      /** The matrix of the last linear solve (for benchmarks); empty with
       *  'Velocity operator = matrix-free'. */
      const dealii::TrilinosWrappers::BlockSparseMatrix &
      get_system_matrix() const
      {
        return discretisation.get_system_matrix();
      }

      /** Largest |u| dt / h over the locally owned cells, all ranks. */
      double
      cfl_number(const double time_step) const
      {
        return discretisation.cfl_number(time_step);
      }

      const dealii::DoFHandler<dim> &
      get_dof_handler() const
      {
        return discretisation.get_dof_handler();
      }
      const dealii::Mapping<dim> &
      get_mapping() const
      {
        return discretisation.get_mapping();
      }
      const dealii::FESystem<dim> &
      get_fe() const
      {
        return discretisation.get_fe();
      }
      /** The current solution with ghost entries. */
      const BlockVector &
      get_solution() const
      {
        return discretisation.get_solution();
      }
      /** The mesh velocity of the ALE terms (ghosted), or nullptr while the
       *  mesh has not moved. */
      const BlockVector *
      get_mesh_velocity() const
      {
        return discretisation.get_mesh_velocity();
      }
      const ViscosityModel &
      get_viscosity_model() const
      {
        return discretisation.get_viscosity_model();
      }
      /** The parameters the solver runs with: the requested ones with
       *  their automatic choices made. */
      const FluidParameters &
      get_parameters() const
      {
        return parameters;
      }
      /** The velocity preconditioner and operator in use, and whether they
       *  were chosen automatically, for the run's log. */
      const std::string &
      velocity_solver_description() const
      {
        return velocity_solver.description;
      }
      /** Pockets of fluid that the covered nodes and walls enclose, apart
       *  from the flow: each has the pressure of one cell decoupled, whose
       *  continuity equation takes up the flux that the bodies around it
       *  impose (FlowDiscretisation::n_enclosed_pockets()). */
      unsigned int
      n_enclosed_pockets() const
      {
        return discretisation.n_enclosed_pockets();
      }
      MPI_Comm
      get_communicator() const
      {
        return discretisation.get_communicator();
      }
      dealii::types::global_dof_index
      n_dofs() const
      {
        return discretisation.n_dofs();
      }
      dealii::types::global_dof_index
      n_velocity_dofs() const
      {
        return discretisation.n_velocity_dofs();
      }
      /** Inner CG solves with L_p inside the Schur complement approximation
       *  since the start, and their CG iterations (for the benchmarks). */
      std::pair<unsigned long, unsigned long>
      pressure_poisson_counts() const;

      /** A vector with this solver's layout, locally owned entries only. */
      BlockVector
      make_owned_vector() const
      {
        return discretisation.make_owned_vector();
      }
      /** A vector with this solver's layout and ghost entries. */
      BlockVector
      make_ghosted_vector() const
      {
        return discretisation.make_ghosted_vector();
      }

    private:
      /** Assemble the Jacobian of the current iterate (with its residual
       *  when @p with_residual) and tell the linear solver. */
      void
      assemble_jacobian(const Stage &stage,
                        const bool   with_residual,
                        const bool   newton);

      using Target = typename FlowDiscretisation<dim>::AssemblyTarget;

      /// what the automatic velocity solver choices became on this mesh
      const VelocitySolverChoice velocity_solver;
      const FluidParameters      parameters;
      dealii::ConditionalOStream pcout;
      /// rank 0 with 'Verbose': the linear solver's decisions
      dealii::ConditionalOStream solver_log;

      FlowDiscretisation<dim>                 discretisation;
      std::unique_ptr<SaddlePointSolver<dim>> linear_solver;
      TimeIntegrator                          time_integrator;
      BlockVector                             newton_update;
    };
  } // namespace fluid
} // namespace particulate

#endif
