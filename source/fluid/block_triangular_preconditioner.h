#ifndef particulate_fluid_block_triangular_preconditioner_h
#define particulate_fluid_block_triangular_preconditioner_h

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include "saddle_point_operator.h"
#include "schur_complement.h"
#include "velocity_block_inverse.h"

namespace particulate {
  namespace fluid {
    /**
     * Upper block-triangular preconditioner P = [A B^T; 0 -S] of the
     * saddle-point system, with S = B A^{-1} B^T (B = -div):
     *   x_p = -S^{-1} r_p,   x_u = A^{-1} (r_u - B^T x_p),
     * A^{-1} and S^{-1} each replaced by an approximation behind its
     * interface.
     */
    template <int dim>
    class BlockTriangularPreconditioner
    {
    public:
      using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;

      BlockTriangularPreconditioner(
        const SaddlePointOperator       &system,
        const VelocityBlockInverse<dim> &velocity_inverse,
        const SchurComplementInverse    &schur_inverse,
        const dealii::IndexSet          &owned_velocity,
        const MPI_Comm                   communicator,
        dealii::TimerOutput             &timer)
        : system(system)
        , velocity_inverse(velocity_inverse)
        , schur_inverse(schur_inverse)
        , timer(timer)
        , tmp_u(owned_velocity, communicator)
      {}

      void
      vmult(BlockVector &dst, const BlockVector &src) const
      {
        {
          dealii::TimerOutput::Scope scope(timer,
                                           "fluid: Schur complement solves");
          schur_inverse.vmult(dst.block(1), src.block(1));
        }
        system.apply_gradient(tmp_u, dst.block(1));
        tmp_u.sadd(-1., src.block(0));
        dealii::TimerOutput::Scope scope(timer,
                                         "fluid: velocity preconditioner");
        velocity_inverse.vmult(dst.block(0), tmp_u);
      }

    private:
      const SaddlePointOperator                    &system;
      const VelocityBlockInverse<dim>              &velocity_inverse;
      const SchurComplementInverse                 &schur_inverse;
      dealii::TimerOutput                          &timer;
      mutable dealii::TrilinosWrappers::MPI::Vector tmp_u;
    };
  } // namespace fluid
} // namespace particulate

#endif
