#ifndef particulate_fluid_velocity_multigrid_inverse_h
#define particulate_fluid_velocity_multigrid_inverse_h

#include <particulate/fluid/velocity_multigrid.h>

#include "velocity_block_inverse.h"

namespace particulate {
  namespace fluid {
    /**
     * One geometric-multigrid V-cycle (VelocityMultigrid) as the velocity
     * block inverse, linearised at the iterate of the last Jacobian.
     *
     * On a moving mesh ('Multigrid on a moving mesh = keep') the V-cycle of
     * the old geometry serves until FGMRES needs markedly more iterations
     * than with a fresh one (kept_preconditioner_is_worn); the fresh count
     * is the median of the last five solves with a V-cycle of the geometry
     * they solved on, robust against the odd hard solve (a start from rest,
     * a re-solve after a kept V-cycle failed) and the odd easy one (the
     * last Newton step of a stage).
     */
    template <int dim>
    class VelocityMultigridInverse : public VelocityBlockInverse<dim>
    {
    public:
      VelocityMultigridInverse(
        std::unique_ptr<VelocityMultigrid<dim>> multigrid,
        const dealii::IndexSet                 &owned_velocity,
        const MPI_Comm                          communicator,
        const MultigridOnMovingMesh             on_moving_mesh,
        const dealii::ConditionalOStream       &log);

      bool
      prepare(const VelocityLinearisation &a) override;
      void
      rebuild(const VelocityLinearisation &a) override;
      void
      vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
            const dealii::TrilinosWrappers::MPI::Vector &src) const override;
      void
      record_solve(const unsigned int iterations, const bool fresh) override;
      unsigned int
      reference_iterations() const override
      {
        return fresh_iterations;
      }
      void
      matrix_changed() override
      {
        is_linearised = false;
      }
      void
      reset() override;
      void
      mesh_moved() override;
      void
      mesh_replaced() override
      {
        refresh_geometry();
      }
      void
      set_masked_dofs(
        const std::vector<dealii::types::global_dof_index> &dofs) override
      {
        multigrid->set_masked_dofs(dofs);
      }
      const dealii::DoFHandler<dim> *
      velocity_dof_handler() const override
      {
        return &multigrid->get_dof_handler();
      }
      std::size_t
      memory_consumption() const override
      {
        return multigrid->memory_consumption();
      }
      double
      bytes_per_application(const double) const override
      {
        return multigrid->bytes_per_vcycle();
      }

    private:
      void
      linearise(const VelocityLinearisation &a);
      /** Rebuild the V-cycle's geometry for the current vertex positions
       *  (linearised anew by the next solve). */
      void
      refresh_geometry();

      std::unique_ptr<VelocityMultigrid<dim>> multigrid;
      const dealii::IndexSet                  owned_velocity;
      const MPI_Comm                          communicator;
      const MultigridOnMovingMesh             on_moving_mesh;
      const dealii::ConditionalOStream       &log;
      bool                                    is_linearised = false;
      /// the mesh moved since the V-cycle's geometry was built
      bool geometry_is_stale = false;
      /// FGMRES iterations of the last (up to five) fresh solves
      std::vector<unsigned int> recent_fresh_iterations;
      /// their median
      unsigned int fresh_iterations = 0;
    };
  } // namespace fluid
} // namespace particulate

#endif
