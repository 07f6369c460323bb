#ifndef particulate_fluid_flow_discretisation_h
#define particulate_fluid_flow_discretisation_h

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

#include <functional>
#include <iosfwd>
#include <memory>
#include <utility>
#include <vector>

namespace particulate {
  namespace fluid {
    template <int dim>
    class MomentumOperator;

    /**
     * The discretisation of the incompressible Navier-Stokes equations and
     * its operator: Q2/P1disc elements on a
     * parallel::fullydistributed::Triangulation, the DoFs and constraints
     * (boundary conditions, hanging nodes, the fictitious-boundary values
     * and the pressures they leave undetermined), the residual of a stage
     * and its Jacobian (an assembled Trilinos block matrix, or the
     * matrix-free MomentumOperator with assembled divergence blocks), the
     * ALE mesh velocity, and the pressure-side matrices the Schur
     * complement approximations are made of (M_p, the lumped velocity mass,
     * L_p = B D^{-1} B^T).
     *
     * It holds the solution; the Newton iteration, the linear solver and the
     * time integrator that work on it are the other parts of NavierStokes.
     */
    template <int dim>
    class FlowDiscretisation
    {
    public:
      using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

      FlowDiscretisation(
        const FluidParameters                                  &parameters,
        dealii::parallel::fullydistributed::Triangulation<dim> &tria,
        dealii::TimerOutput                                    &timer);
      ~FlowDiscretisation();

      /** Distribute and number the DoFs (velocity block first). */
      void
      distribute_dofs();

      /**
       * Constraints, matrices and vectors for the DoFs of
       * distribute_dofs(). @p velocity_dofs, the Q2^dim velocity DoF handler
       * numbered like the velocity block, is what the matrix-free operator
       * works on ('Velocity operator = matrix-free'; may be nullptr
       * otherwise). The solution is zero.
       */
      void
      setup_operator(const dealii::DoFHandler<dim> *velocity_dofs);

      /** Drops the matrix-free operator: the DoF handler it works on
       *  belongs to the linear solver, which must not clear or destroy it
       *  while the operator still refers to it. */
      void
      release_operator();

      /** Interpolate the initial condition at @p time. */
      void
      set_initial_condition(const double time);

      /** See NavierStokes::interpolate_velocity(). */
      void
      interpolate_velocity(const dealii::Function<dim> &velocity,
                           BlockVector                 &vector) const;

      /** See NavierStokes::set_fictitious_boundary_values(). Returns
       *  whether the set of constrained DoFs changed on any rank
       *  (collective). */
      bool
      set_fictitious_boundary_values(
        std::vector<std::pair<dealii::types::global_dof_index, double>> values,
        std::vector<dealii::types::global_dof_index> joint_dofs,
        std::vector<double>                          start_values);

      /** The time step from @p time over @p k that the next stages belong
       *  to: the fictitious-boundary values are interpolated over it. */
      void
      begin_step(const double time, const double k);

      /** ALE: mesh velocity w in the velocity components (ghosted). */
      void
      set_mesh_velocity(const BlockVector &mesh_velocity);

      /** See NavierStokes::move_mesh(). */
      void
      move_mesh(const std::function<void()> &move_vertices,
                const double                 time_step);

      /** See NavierStokes::transfer_to_moved_mesh(). */
      void
      transfer_to_moved_mesh(const std::function<void()> &move_vertices);

      /** What assemble() computes: the right-hand side -R of the current
       *  iterate, the Jacobian, or both in one pass over the cells. */
      enum class AssemblyTarget
      {
        residual,
        jacobian,
        jacobian_and_residual
      };

      /**
       * Start @p stage: the constraints at its end time, the current
       * solution with their values as first iterate (undetermined
       * pressures zero), and the parts of the residual that are fixed
       * within the stage.
       */
      void
      begin_stage(const Stage &stage);

      /** The right-hand side -R of the current iterate, the Jacobian (or
       *  the matrix-free operator's linearisation), or both; @p newton
       *  false leaves out the Newton part of the convection. */
      void
      assemble(const Stage         &stage,
               const AssemblyTarget target,
               const bool           newton);

      /** The right-hand side of the last residual assembly. */
      const BlockVector &
      get_system_rhs() const
      {
        return system_rhs;
      }

      /** Make @p ghosted, a solution get_solution() returned on the same
       *  DoFs, the current one again. */
      void
      restore_solution(const BlockVector &ghosted)
      {
        solution = ghosted;
      }

      /** Make @p iterate (locally owned layout) the current solution, its
       *  undetermined pressures set to zero. */
      void
      set_iterate(BlockVector &iterate);

      /** A Newton update takes the homogeneous constraints. */
      void
      distribute_update(BlockVector &update) const
      {
        zero_constraints.distribute(update);
      }

      /** Give the pressure zero mean (enclosed flow). */
      void
      normalise_pressure();

      /**
       * The constraint-masked gradient of the matrix-free operator
       * (get_constrained_gradient()) for the current mesh and constraints;
       * nothing with the assembled operator. Part of the operator: after
       * every mesh motion and change of the constraints.
       */
      void
      constrain_gradient();

      /**
       * L_p = B D^{-1} B^T of the current constraints (undetermined
       * pressures decoupled, one pressure pinned in enclosed flow). Who
       * built a preconditioner from the old L_p drops it first.
       */
      void
      build_pressure_laplacian();

      /** What shapes L_p besides the mesh (this rank's part, sorted). */
      struct PressureOperatorStructure
      {
        /// velocity DoFs the bodies constrain
        std::vector<dealii::types::global_dof_index> covered;
        /// pressures decoupled from the flow (undetermined next to bodies,
        /// or pinned in enclosed pockets)
        std::vector<dealii::types::global_dof_index> decoupled;

        bool
        operator==(const PressureOperatorStructure &other) const
        {
          return covered == other.covered && decoupled == other.decoupled;
        }
      };

      /** The structure of the current constraints. */
      PressureOperatorStructure
      pressure_operator_structure() const
      {
        return {body_constrained_dofs, decoupled_pressure_dofs};
      }

      /** The Newton system's velocity block, assembled; nullptr with the
       *  matrix-free operator. */
      const dealii::TrilinosWrappers::SparseMatrix *
      assembled_velocity_block() const;

      /** dst = A src with the matrix-free operator (nullptr otherwise). */
      const MomentumOperator<dim> *
      get_momentum_operator() const
      {
        return momentum_operator.get();
      }

      /** B^T with the rows of constrained velocities and the columns of
       *  undetermined pressures zero (matrix-free operator). */
      const dealii::TrilinosWrappers::SparseMatrix &
      get_constrained_gradient() const
      {
        return constrained_gradient;
      }

      const dealii::TrilinosWrappers::SparseMatrix &
      get_pressure_laplacian() const
      {
        return pressure_laplacian;
      }

      /** The pressure mass matrix M_p. */
      const dealii::TrilinosWrappers::SparseMatrix &
      get_pressure_mass() const
      {
        return pressure_mass.block(1, 1);
      }

      /** 1 / (row sums of the velocity mass matrix), velocity layout. */
      const dealii::TrilinosWrappers::MPI::Vector &
      get_inverse_lumped_mass() const
      {
        return inverse_lumped_mass;
      }

      /** The velocity DoFs (sorted) that the fictitious boundary fixes. */
      const std::vector<dealii::types::global_dof_index> &
      get_prescribed_velocity_dofs() const
      {
        return prescribed_velocity_dofs;
      }

      /** Checkpoint: the current solution (this rank's locally owned
       *  entries) and the DoF layout it belongs to. */
      void
      save_solution(std::ostream &out) const;

      /** Reads what save_solution() wrote. Throws std::runtime_error when
       *  the DoF layout differs. */
      void
      load_solution(std::istream &in);

      /** Bytes held by this rank's matrices and vectors. */
      std::size_t
      memory_consumption() const;

      /** The assembled matrix of the last Jacobian; empty with
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
      /** The current solution and the start value of the stage, for the
       *  time integrator (ghosted). */
      BlockVector &
      solution_for_time_integration()
      {
        return solution;
      }
      BlockVector &
      old_solution_for_time_integration()
      {
        return old_solution;
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
      /** Pockets of fluid that the constraints wall off from the flow,
       *  whose pressure is decoupled in one cell each (at the last set-up
       *  of the constraints). */
      unsigned int
      n_enclosed_pockets() const
      {
        return enclosed_pockets;
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
      const std::vector<dealii::IndexSet> &
      get_owned_partitioning() const
      {
        return owned_partitioning;
      }
      const std::vector<dealii::IndexSet> &
      get_relevant_partitioning() const
      {
        return relevant_partitioning;
      }
      /** A vector with this layout, locally owned entries only. */
      BlockVector
      make_owned_vector() const
      {
        return BlockVector(owned_partitioning, communicator);
      }
      /** A vector with this layout and ghost entries. */
      BlockVector
      make_ghosted_vector() const
      {
        return BlockVector(owned_partitioning,
                           relevant_partitioning,
                           communicator);
      }

    private:
      /** 1 at the owned pressures, 0 at the decoupled ones. */
      dealii::TrilinosWrappers::MPI::Vector
      free_pressure_mask() const;

      void
      make_constraints(const double time);
      /** The fictitious-boundary value of entry @p j at @p time. */
      double
      fictitious_boundary_value(const std::size_t j, const double time) const;
      void
      setup_matrices();
      /** The pressure mass matrix and the lumped velocity mass. */
      void
      assemble_geometric_matrices();
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
      /** Enclosed flow: removes from the continuity rows of system_rhs
       *  their part along the pressure mode no equation determines (the
       *  net flux the fixed velocities carry into the flow), which no
       *  Newton update could remove. */
      void
      remove_net_flux_from_residual();

      const FluidParameters &parameters;
      MPI_Comm               communicator;
      dealii::TimerOutput   &timer;

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
      /// their values at the start of the step (empty: constant over it)
      std::vector<double> fictitious_boundary_start_values;
      /// the time step the stages belong to: start time and length
      double step_start  = 0.;
      double step_length = 0.;
      /// where the parts of an articulated body meet (sorted; see
      /// NavierStokes::set_fictitious_boundary_values())
      std::vector<dealii::types::global_dof_index> joint_velocity_dofs;
      /// their DoFs, sorted
      std::vector<dealii::types::global_dof_index> prescribed_velocity_dofs;
      /// Pressure DoFs (locally owned, sorted) that no equation determines:
      /// all those of a cell whose velocities are all constrained (inside a
      /// body), and one per null mode of a cell next to a body whose free
      /// velocities do not see every pressure mode (see
      /// find_undetermined_pressure_dofs). They are decoupled: no row or
      /// column in the system, and kept at zero after every Newton update.
      std::vector<dealii::types::global_dof_index> decoupled_pressure_dofs;
      /// pockets of fluid walled off from the flow by the constraints,
      /// among them one decoupled pressure each (find_enclosed_fluid)
      unsigned int enclosed_pockets = 0;
      /// enclosed flow: whether the constant pressure is a null vector of
      /// the divergence on this mesh (not on curved cells, see
      /// constant_pressure_is_null_mode)
      bool constant_pressure_is_null = false;
      /// enclosed flow with bodies where it is: the exact null mode of the
      /// continuity rows, (DoF, value) of owned pressures
      /// (enclosed_flow_pressure_mode)
      std::vector<std::pair<dealii::types::global_dof_index, double>>
        enclosed_pressure_mode;
      /// the covered velocity DoFs that search was made for (a list that
      /// matches none after new DoFs or a moved mesh)
      std::vector<dealii::types::global_dof_index>
        decoupled_pressures_searched_for;
      /// the joint DoFs it was made for
      std::vector<dealii::types::global_dof_index> joints_searched_for;

      dealii::TrilinosWrappers::BlockSparseMatrix system_matrix;
      /// 'Velocity operator = matrix-free': the velocity block as an
      /// operator (the assembled system_matrix stays empty), the gradient
      /// B^T without constraints (a mesh quantity), and B^T with the rows
      /// of constrained velocities and the columns of decoupled pressures
      /// zeroed (rebuilt with L_p, i.e. when the constrained nodes change)
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
      BlockVector                           system_rhs;
      BlockVector                           solution;      // ghosted
      BlockVector                           old_solution;  // ghosted
      BlockVector                           mesh_velocity; // ghosted
      bool                                  has_mesh_velocity = false;
    };
  } // namespace fluid
} // namespace particulate

#endif
