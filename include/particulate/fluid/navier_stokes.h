#ifndef particulate_fluid_navier_stokes_h
#define particulate_fluid_navier_stokes_h

#include <particulate/core/simulation_parameters.h>
#include <particulate/fluid/fluid_parameters.h>
#include <particulate/fluid/pressure_laplacian.h>
#include <particulate/fluid/time_integrator.h>
#include <particulate/fluid/viscosity_model.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace particulate {
  namespace fluid {
    template <int dim>
    class MomentumOperator;
    template <int dim>
    class VelocityBlockInverse;
    struct VelocityLinearisation;

    /**
     * Incompressible Navier-Stokes solver with Q2/P1disc elements on a
     * parallel::fullydistributed::Triangulation and Trilinos block matrices:
     * the facade over the flow solver's parts.
     *
     * - Discretisation and operator (this class): DoFs, constraints,
     *   residual, Jacobian (assembled, or the matrix-free MomentumOperator),
     *   the ALE terms; Newton with a fixed-point fallback for each stage.
     * - Time integrator (TimeIntegrator): the stages of fractional-step
     *   theta, Crank-Nicolson, backward Euler or the steady problem, and
     *   each stage's first iterate.
     * - Linear solver: FGMRES with the BlockTriangularPreconditioner, made
     *   of a VelocityBlockInverse (algebraic multigrid, Jacobi-Chebyshev or
     *   geometric multigrid) and a SchurComplementInverse (Cahouet-Chabard
     *   theta_i mu M_p^{-1} + (rho/k) L_p^{-1}, or the least-squares
     *   commutator), each chosen by a factory from the case file's enum.
     *
     * The class knows nothing of particles. Users that impose extra
     * constraints (the fictitious boundary method) add them through
     * set_additional_constraints(); the ALE mesh velocity enters through
     * set_mesh_velocity().
     */
    template <int dim>
    class NavierStokes
    {
    public:
      using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

      NavierStokes(const FluidParameters &parameters,
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
      set_initial_condition(const double time);

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
                           BlockVector                 &vector) const;

      /**
       * Extra Dirichlet values on velocity DoFs, used by the fictitious
       * boundary method to impose the rigid velocity inside bodies (thesis
       * eq. 5.10c, 5.17): pairs of a locally relevant DoF index and its
       * value. They enter the constraints of every following stage (with
       * zero values for the Newton updates) on DoFs that the boundary
       * conditions and hanging nodes leave free, and stay until replaced.
       * Every rank must pass the values of all its locally relevant DoFs
       * inside bodies, so that the constraints agree across ranks.
       */
      void
      set_fictitious_boundary_values(
        std::vector<std::pair<dealii::types::global_dof_index, double>> values);

      /** ALE: mesh velocity w in the velocity components (ghosted). */
      void
      set_mesh_velocity(const BlockVector &mesh_velocity);

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

      /** The matrix of the last linear solve (for benchmarks); empty with
       *  'Velocity operator = matrix-free'. */
      const dealii::TrilinosWrappers::BlockSparseMatrix &
      get_system_matrix() const
      {
        return system_matrix;
      }

      /** Largest |u| dt / h over the locally owned cells, all ranks. */
      double
      cfl_number(const double time_step) const;

      const dealii::DoFHandler<dim> &
      get_dof_handler() const
      {
        return dof_handler;
      }
      const dealii::Mapping<dim> &
      get_mapping() const
      {
        return mapping;
      }
      const dealii::FESystem<dim> &
      get_fe() const
      {
        return fe;
      }
      /** The current solution with ghost entries. */
      const BlockVector &
      get_solution() const
      {
        return solution;
      }
      /** The mesh velocity of the ALE terms (ghosted), or nullptr while the
       *  mesh has not moved. */
      const BlockVector *
      get_mesh_velocity() const
      {
        return has_mesh_velocity ? &mesh_velocity : nullptr;
      }
      const ViscosityModel &
      get_viscosity_model() const
      {
        return *viscosity_model;
      }
      const FluidParameters &
      get_parameters() const
      {
        return parameters;
      }
      MPI_Comm
      get_communicator() const
      {
        return communicator;
      }
      dealii::types::global_dof_index
      n_dofs() const
      {
        return dof_handler.n_dofs();
      }
      dealii::types::global_dof_index
      n_velocity_dofs() const
      {
        return owned_partitioning.empty() ? 0 : dofs_per_block[0];
      }
      /** Inner CG solves with L_p inside the Schur complement approximation
       *  since the start, and their CG iterations (for the benchmarks). */
      std::pair<unsigned long, unsigned long>
      pressure_poisson_counts() const
      {
        return {pressure_poisson_solves, pressure_poisson_iterations};
      }

      /** A vector with this solver's layout, locally owned entries only. */
      BlockVector
      make_owned_vector() const
      {
        return BlockVector(owned_partitioning, communicator);
      }
      /** A vector with this solver's layout and ghost entries. */
      BlockVector
      make_ghosted_vector() const
      {
        return BlockVector(owned_partitioning,
                           relevant_partitioning,
                           communicator);
      }

    private:
      void
      make_constraints(const double time);
      void
      setup_matrices();
      /** The pressure mass matrix and the lumped velocity mass. */
      void
      assemble_geometric_matrices();
      /** What assemble() computes: the right-hand side -R of the current
       *  iterate into system_rhs, the Jacobian into system_matrix, or
       *  both in one pass over the cells. */
      enum class AssemblyTarget
      {
        residual,
        jacobian,
        jacobian_and_residual
      };
      void
      assemble(const Stage         &stage,
               const AssemblyTarget target,
               const bool           newton);
      /** With the matrix-free velocity operator: hand the current iterate
       *  to it (what assembling the Jacobian is for the assembled one). */
      void
      linearise_momentum_operator(const Stage &stage, const bool newton);
      /** With the matrix-free velocity operator: the part of the residual
       *  that is fixed within a stage (old solution, body force). */
      void
      compute_explicit_residual(const Stage &stage);
      /** With the matrix-free velocity operator: system_rhs = -R without a
       *  FEValues loop (the nonlinear form, B^T p and B u). */
      void
      assemble_residual_matrix_free(const Stage &stage);
      /** L_p and its AMG, M_p and its ILU. */
      void
      build_schur_complement_approximation();
      /** What the velocity preconditioner is built from at @p stage. */
      VelocityLinearisation
      velocity_linearisation(const Stage &stage) const;
      unsigned int
      solve_linear(const Stage &stage, const double tolerance);
      void
      normalise_pressure();

      const FluidParameters     &parameters;
      MPI_Comm                   communicator;
      dealii::ConditionalOStream pcout;
      /// rank 0 with 'Verbose': the linear solver's decisions
      dealii::ConditionalOStream solver_log;
      dealii::TimerOutput       &timer;

      dealii::parallel::fullydistributed::Triangulation<dim> &triangulation;
      const dealii::FESystem<dim>                             fe;
      const dealii::MappingQ<dim>                             mapping;
      dealii::DoFHandler<dim>                                 dof_handler;
      std::unique_ptr<ViscosityModel>                         viscosity_model;
      std::unique_ptr<dealii::Function<dim>> body_force, boundary_velocity;

      std::vector<dealii::IndexSet>                owned_partitioning;
      std::vector<dealii::IndexSet>                relevant_partitioning;
      std::vector<dealii::types::global_dof_index> dofs_per_block;
      dealii::IndexSet                             locally_relevant_dofs;

      /// Dirichlet values at the stage's end time (applied to the solution)
      dealii::AffineConstraints<double> nonzero_constraints;
      /// the same rows with zero values (applied to Newton updates)
      dealii::AffineConstraints<double> zero_constraints;
      /// velocity values imposed inside fictitious-boundary bodies
      std::vector<std::pair<dealii::types::global_dof_index, double>>
        fictitious_boundary_values;
      /// Pressure DoFs (locally owned, sorted) that no equation determines:
      /// all those of a cell whose velocities are all constrained (inside a
      /// body), and one per null mode of a cell next to a body whose free
      /// velocities do not see every pressure mode (see
      /// find_undetermined_pressure_dofs). They are decoupled: no row or
      /// column in the system, and kept at zero after every Newton update.
      std::vector<dealii::types::global_dof_index> decoupled_pressure_dofs;
      /// the covered velocity DoFs that search was made for (a list that
      /// matches none after new DoFs or a moved mesh)
      std::vector<dealii::types::global_dof_index>
        decoupled_pressures_searched_for;

      dealii::TrilinosWrappers::BlockSparseMatrix system_matrix;
      /// 'Velocity operator = matrix-free': the velocity block as an
      /// operator (the assembled system_matrix stays empty), the gradient
      /// B^T without constraints (a mesh quantity), and B^T with the rows
      /// of constrained velocities and the columns of decoupled pressures
      /// zeroed (rebuilt with the Schur complement approximation, i.e.
      /// when the constrained nodes change)
      std::unique_ptr<MomentumOperator<dim>> momentum_operator;
      dealii::TrilinosWrappers::SparseMatrix gradient_matrix;
      dealii::TrilinosWrappers::SparseMatrix constrained_gradient;
      /// locally owned constrained velocity DoFs (matrix-free operator)
      std::vector<dealii::types::global_dof_index> constrained_velocity_dofs;
      /// the velocity DoFs that only bodies constrain (covered nodes not on
      /// a Dirichlet or free-slip boundary), sorted
      std::vector<dealii::types::global_dof_index> body_constrained_dofs;
      /// the stage's explicit part of R_u (matrix-free operator)
      dealii::TrilinosWrappers::MPI::Vector explicit_residual;
      /// pressure mass matrix M_p in block (1,1); other blocks empty
      dealii::TrilinosWrappers::BlockSparseMatrix pressure_mass;
      /// L_p = B diag(M_u)^{-1} B^T, rebuilt when B changes
      dealii::TrilinosWrappers::SparseMatrix pressure_laplacian;
      /// its in-place update when only the covered nodes change
      /// (matrix-free velocity operator)
      PressureLaplacian pressure_laplacian_update;
      /// 1 / (row sums of the velocity mass matrix), velocity block layout
      dealii::TrilinosWrappers::MPI::Vector inverse_lumped_mass;
      bool           schur_approximation_is_current = false;
      BlockVector    system_rhs;
      BlockVector    newton_update;
      BlockVector    solution;      // ghosted
      BlockVector    old_solution;  // ghosted
      BlockVector    mesh_velocity; // ghosted
      bool           has_mesh_velocity = false;
      TimeIntegrator time_integrator;
      /// inner L_p solves and their CG iterations, summed over the run
      unsigned long pressure_poisson_solves     = 0;
      unsigned long pressure_poisson_iterations = 0;

      /// the approximate inverse of the velocity block ('Velocity
      /// preconditioner')
      std::unique_ptr<VelocityBlockInverse<dim>> velocity_inverse;
      std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> laplace_amg;
      /// the near-null space of L_p's AMG (pressure_near_null_space()):
      /// it depends on the mesh only, so it is kept until the mesh moves
      std::vector<double> laplace_near_null_space;
      std::unique_ptr<dealii::TrilinosWrappers::PreconditionILU> mass_ilu;
    };
  } // namespace fluid
} // namespace particulate

#endif
