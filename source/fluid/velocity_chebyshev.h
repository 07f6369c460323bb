#ifndef particulate_fluid_velocity_chebyshev_h
#define particulate_fluid_velocity_chebyshev_h

#include <deal.II/lac/precondition.h>

#include "velocity_block_inverse.h"

namespace particulate {
  namespace fluid {
    /**
     * A Jacobi-Chebyshev polynomial as approximate inverse of the assembled
     * velocity block A, rebuilt with every matrix (its set-up is a few CG
     * steps).
     *
     * The polynomial spans the eigenvalue range of D^{-1} A (D the diagonal
     * of A) that a few CG (Lanczos) steps estimate; with smoothing range 0
     * it uses the estimated smallest eigenvalue, so it acts as an
     * approximate inverse, not a smoother. When the mass term dominates,
     * D^{-1} A has a condition number near that of the Jacobi-scaled Q2
     * mass matrix (2.5^dim), whatever the mesh size.
     */
    template <int dim>
    class VelocityChebyshev : public VelocityBlockInverse<dim>
    {
    public:
      VelocityChebyshev(const unsigned int      degree,
                        const dealii::IndexSet &owned_velocity,
                        const MPI_Comm          communicator,
                        dealii::TimerOutput    &timer);

      bool
      prepare(const VelocityLinearisation &a) override;
      void
      rebuild(const VelocityLinearisation &a) override;
      void
      vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
            const dealii::TrilinosWrappers::MPI::Vector &src) const override;
      void
      record_solve(const unsigned int, const bool) override
      {}
      unsigned int
      reference_iterations() const override
      {
        return 0;
      }
      void
      matrix_changed() override
      {
        reset();
      }
      void
      reset() override
      {
        chebyshev.reset();
      }
      std::size_t
      memory_consumption() const override
      {
        return 0;
      }
      /** One product with the velocity block per degree. */
      double
      bytes_per_application(const double operator_bytes) const override
      {
        return degree * operator_bytes;
      }

    private:
      /** Multiplication by the inverse diagonal of a Trilinos matrix
       *  (deal.II's DiagonalMatrix cannot be sized from one in 9.4). */
      struct Jacobi
      {
        dealii::TrilinosWrappers::MPI::Vector inverse_diagonal;

        void
        vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
              const dealii::TrilinosWrappers::MPI::Vector &src) const
        {
          dst = src;
          dst.scale(inverse_diagonal);
        }
      };
      using Chebyshev
        = dealii::PreconditionChebyshev<dealii::TrilinosWrappers::SparseMatrix,
                                        dealii::TrilinosWrappers::MPI::Vector,
                                        Jacobi>;

      const unsigned int         degree;
      const dealii::IndexSet     owned_velocity;
      const MPI_Comm             communicator;
      dealii::TimerOutput       &timer;
      std::unique_ptr<Chebyshev> chebyshev;
    };
  } // namespace fluid
} // namespace particulate

#endif
