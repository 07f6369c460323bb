#ifndef particulate_fluid_velocity_multigrid_h
#define particulate_fluid_velocity_multigrid_h

#include <particulate/fluid/viscosity_model.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * Geometric multigrid for the velocity block of the Navier-Stokes
     * system: one V-cycle approximates A^{-1} inside the block
     * preconditioner, in place of the algebraic multigrid of the assembled
     * block.
     *
     * - The levels are those of the coarse mesh's uniform refinement (the
     *   fully distributed triangulation carries them, see
     *   core::create_mesh); the velocity lives on a DoF handler of its own
     *   (Q2^dim), numbered like the velocity block of the system so that
     *   vectors are exchanged by a copy.
     * - Every level applies the symmetric part of the velocity block,
     *   rho/k M + theta_i mu (grad + grad^T), without a matrix
     *   (MassViscousOperator, single precision: the V-cycle only has to
     *   approximate); the convection is left to the outer FGMRES. With a
     *   shear-rate dependent viscosity the linearisation point is
     *   interpolated from the fine mesh to every level.
     * - Smoother: a Chebyshev polynomial around the (mass + viscous)
     *   diagonal, eigenvalues from a few Lanczos steps. Coarse level: a
     *   Chebyshev polynomial of higher degree as an approximate inverse
     *   when the level operator is well conditioned (mass-dominated), else
     *   its matrix, computed from the same cell kernel, solved by CG with
     *   ML AMG (Settings::coarse_solver).
     * - Dirichlet boundaries are zero on all levels; free-slip planes (which
     *   must be normal to a coordinate axis) fix the normal component; DoFs
     *   inside fictitious-boundary bodies act as identity rows on the finest
     *   level (set_masked_dofs()).
     */
    template <int dim>
    class VelocityMultigrid
    {
    public:
      /** How the coarse level is solved (see velocity_multigrid.cc). */
      enum class CoarseSolve
      {
        automatic, ///< Chebyshev when its degree is small, else CG + AMG
        chebyshev,
        cg_amg
      };

      struct Settings
      {
        /// boundary ids where the velocity is prescribed
        std::vector<unsigned int> dirichlet_ids;
        /// boundary ids of free-slip planes
        std::vector<unsigned int> free_slip_ids;
        /// Chebyshev degree of the smoother (pre- and post-smoothing)
        unsigned int smoother_degree = 4;
        CoarseSolve  coarse_solver   = CoarseSolve::automatic;
      };

      /**
       * @p system_dofs: the (velocity, pressure) DoF handler, numbered with
       * the velocity block first (it and @p mapping must outlive this
       * object); @p owned_velocity its locally owned velocity DoFs.
       */
      VelocityMultigrid(const dealii::DoFHandler<dim> &system_dofs,
                        const dealii::IndexSet        &owned_velocity,
                        const dealii::Mapping<dim>    &mapping,
                        const Settings                &settings,
                        dealii::TimerOutput           &timer);
      ~VelocityMultigrid();

      /** Recompute the geometric data after the mesh vertices moved (the
       *  mesh's cells and DoFs unchanged). */
      void
      update_geometry();

      /**
       * The stage's coefficients, rho/k (0 for steady flow) and theta_i;
       * @p velocity (velocity block layout, locally owned entries) is the
       * linearisation point, read only for a shear-rate dependent
       * viscosity. Nothing is rebuilt when the coefficients are those of
       * the last call and the viscosity is constant.
       */
      void
      set_linearisation(const dealii::TrilinosWrappers::MPI::Vector &velocity,
                        const double          mass_coefficient,
                        const double          theta_implicit,
                        const ViscosityModel &viscosity_model);

      /**
       * Drop the kept V-cycles (one per set of stage coefficients): the
       * next set_linearisation() builds afresh, with the masked DoFs of
       * then. A run does this at every checkpoint, so that it computes what
       * a run restarted there computes.
       */
      void
      forget_linearisations();

      /** Velocity DoFs (system numbering, locally relevant) that are
       *  constrained in addition to the boundary conditions: the nodes
       *  inside fictitious-boundary bodies. */
      void
      set_masked_dofs(const std::vector<dealii::types::global_dof_index> &dofs);

      /** One V-cycle: dst ~ A^{-1} src (velocity block layout). */
      void
      vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
            const dealii::TrilinosWrappers::MPI::Vector &src) const;

      /** The Q2^dim velocity DoF handler, numbered like the velocity block
       *  of the system (the matrix-free outer operator works on it too). */
      const dealii::DoFHandler<dim> &
      get_dof_handler() const;

      /** Bytes held by this rank (operators, transfer, coarse matrix). */
      std::size_t
      memory_consumption() const;

      /** Bytes one V-cycle of the active hierarchy moves through memory at
       *  least on this rank: on every level above the coarse one the level
       *  operator's data and two vectors for each of the 2 d + 1 products
       *  of its smoothing (degree d, before and after) and residual, and
       *  the transfer's data twice (restriction and prolongation). The
       *  coarse solve is not counted. */
      double
      bytes_per_vcycle() const;

    private:
      struct Implementation;
      std::unique_ptr<Implementation> implementation;
    };
  } // namespace fluid
} // namespace particulate

#endif
