#ifndef particulate_fluid_saddle_point_operator_h
#define particulate_fluid_saddle_point_operator_h

#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>

namespace particulate {
  namespace fluid {
    /**
     * The saddle-point operator [A B^T; B 0] of the Newton system, either
     * the assembled block matrix or the matrix-free velocity block A with
     * the assembled (and constraint-masked) gradient B^T; B is its
     * transpose in both (B = -div).
     */
    class SaddlePointOperator
    {
    public:
      using Vector        = dealii::TrilinosWrappers::MPI::Vector;
      using BlockVector   = dealii::TrilinosWrappers::MPI::BlockVector;
      using VelocityBlock = std::function<void(Vector &, const Vector &)>;

      explicit SaddlePointOperator(
        const dealii::TrilinosWrappers::BlockSparseMatrix &matrix)
        : matrix(&matrix)
      {}

      SaddlePointOperator(
        const VelocityBlock                          &velocity_block,
        const dealii::TrilinosWrappers::SparseMatrix &gradient)
        : velocity_block(velocity_block)
        , gradient(&gradient)
      {}

      /** The assembled matrix, or nullptr for the matrix-free operator. */
      const dealii::TrilinosWrappers::BlockSparseMatrix *
      assembled_matrix() const
      {
        return matrix;
      }

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
      const dealii::TrilinosWrappers::BlockSparseMatrix *matrix = nullptr;
      VelocityBlock                                      velocity_block;
      const dealii::TrilinosWrappers::SparseMatrix      *gradient = nullptr;
    };
  } // namespace fluid
} // namespace particulate

#endif
