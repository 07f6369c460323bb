#ifndef particulate_fluid_saddle_point_solver_h
#define particulate_fluid_saddle_point_solver_h

#include <particulate/fluid/flow_discretisation.h>
#include <particulate/fluid/run_profile.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "velocity_block_inverse.h"

namespace particulate {
  namespace fluid {
    /**
     * The linear solver of a Newton step: FGMRES on the saddle-point
     * system of a FlowDiscretisation with the block-triangular
     * preconditioner, made of the velocity block inverse ('Velocity
     * preconditioner') and a Schur complement inverse ('Schur complement
     * approximation'), and the preconditioners of L_p (ML AMG) and M_p
     * (ILU) that the latter uses.
     *
     * What it builds it keeps until told that its source changed: the
     * facade (NavierStokes) reports new Jacobians, new constrained nodes
     * and mesh motion.
     */
    template <int dim>
    class SaddlePointSolver
    {
    public:
      using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

      SaddlePointSolver(const FluidParameters            &parameters,
                        dealii::TimerOutput              &timer,
                        const dealii::ConditionalOStream &log);
      ~SaddlePointSolver();

      /** Drop everything built from the discretisation's matrices (before
       *  they are cleared for new DoFs). */
      void
      clear();

      /** The velocity block inverse for the DoFs of @p discretisation
       *  (after its distribute_dofs()). */
      void
      setup(const FlowDiscretisation<dim> &discretisation);

      /** The velocity DoF handler of the geometric multigrid (what the
       *  matrix-free operator works on), or nullptr. */
      const dealii::DoFHandler<dim> *
      velocity_dof_handler() const;

      /** A new Jacobian was assembled or linearised. */
      void
      matrix_changed();

      /** The constraints were rebuilt (the velocity DoFs inside bodies). */
      void
      set_masked_dofs(const std::vector<dealii::types::global_dof_index> &dofs);

      /** The constrained nodes changed: the masked gradient is formed
       *  again, and L_p rebuilt if the solve finds other nodes covered
       *  than those it was built with. */
      void
      pressure_operator_changed()
      {
        gradient_is_current = false;
      }

      /** Before the mesh moves: B, M_p and the lumped mass will change. */
      void
      geometry_changing();

      /** After the mesh moved by a step's ALE motion. */
      void
      mesh_moved();

      /** After the solution was carried to a freshly adapted mesh. */
      void
      mesh_replaced();

      /** Drop the kept preconditioners (at a checkpoint). */
      void
      reset();

      /**
       * Solve J @p update = rhs for the Newton step of @p stage to the
       * absolute @p tolerance; the update takes the homogeneous
       * constraints. Returns the FGMRES iterations. Throws SolverFailure.
       */
      unsigned int
      solve(const Stage             &stage,
            const double             tolerance,
            FlowDiscretisation<dim> &discretisation,
            BlockVector             &update);

      /** Inner CG solves with L_p since the start, and their iterations. */
      std::pair<unsigned long, unsigned long>
      pressure_poisson_counts() const
      {
        return {pressure_poisson_solves, pressure_poisson_iterations};
      }

      std::size_t
      memory_consumption() const;

      /** What one application of each part of the solve moves through
       *  memory on this rank, with the matrices of @p discretisation. */
      SolverTraffic
      traffic(const FlowDiscretisation<dim> &discretisation) const;

    private:
      /**
       * Where L_p, its AMG and M_p's ILU stand: missing (rebuilt before
       * the next solve), current (built on this mesh), or aged (built on
       * the mesh before one or more ALE motions, which only changed
       * values: kept as long as the velocity V-cycle is, 'Multigrid on a
       * moving mesh'). Other covered nodes or decoupled pressures rebuild them
       * in any state.
       */
      enum class SchurState
      {
        missing,
        current,
        aged
      };

      /** L_p and its AMG, M_p and its ILU. */
      void
      build_schur_ingredients(FlowDiscretisation<dim> &discretisation);

      /** Whether the Schur ingredients are built anew before a solve
       *  whose velocity block inverse is (@p velocity_is_fresh) or is not
       *  built for the current matrix and mesh. Collective. */
      bool
      schur_ingredients_need_building(const FlowDiscretisation<dim> &d,
                                      const bool velocity_is_fresh) const;

      /** How one FGMRES solve ended. */
      struct FgmresOutcome
      {
        bool         converged  = true;
        unsigned int iterations = 0;
        double       residual   = 0.;
        /// which preconditioner part gave NaN/Inf, if the residual did
        std::string non_finite_cause;
      };

      /** One FGMRES solve with the current preconditioners, stopped after
       *  @p allowed iterations. */
      FgmresOutcome
      run_fgmres(const Stage             &stage,
                 const double             tolerance,
                 const unsigned int       allowed,
                 FlowDiscretisation<dim> &discretisation,
                 BlockVector             &update);

      const FluidParameters            &parameters;
      dealii::TimerOutput              &timer;
      const dealii::ConditionalOStream &log;

      std::unique_ptr<VelocityBlockInverse<dim>> velocity_inverse;
      std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> laplace_amg;
      /// the near-null space of L_p's AMG: it depends on the mesh only
      std::vector<double> laplace_near_null_space;
      std::unique_ptr<dealii::TrilinosWrappers::PreconditionILU> mass_ilu;
      SchurState schur_state = SchurState::missing;
      /// M_p's ILU was built on the current mesh
      bool mass_ilu_is_current = false;
      /// the covered nodes and decoupled pressures L_p was built with
      typename FlowDiscretisation<dim>::PressureOperatorStructure
        structure_in_schur;
      /// the matrix-free operator's masked gradient fits mesh and constraints
      bool gradient_is_current = false;
      /// inner L_p solves and their CG iterations, summed over the run
      unsigned long pressure_poisson_solves     = 0;
      unsigned long pressure_poisson_iterations = 0;
    };
  } // namespace fluid
} // namespace particulate

#endif
