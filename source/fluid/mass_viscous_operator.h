#ifndef particulate_fluid_mass_viscous_operator_h
#define particulate_fluid_mass_viscous_operator_h

// Private header of the fluid library: the matrix-free operator on one
// multigrid level (used only by velocity_multigrid.cc, the one translation
// unit that pays for the matrix-free templates).

// simd.h first: it must precede every deal.II header
// clang-format off
#include "simd.h"
// clang-format on

#include <particulate/fluid/viscosity_model.h>

#include <deal.II/base/subscriptor.h>
#include <deal.II/base/table.h>
#include <deal.II/base/vectorization.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>

#include <memory>
#include <vector>


namespace particulate {
  namespace fluid {
    /**
     * The symmetric part of the velocity block of the linearised momentum
     * equation, without a matrix:
     *
     *   (A_s u, v) = c_m (u, v) + (nu (grad u + grad u^T), grad v)
     *
     * with c_m = rho/k and nu = theta_i mu (mu at the quadrature points
     * from the shear rate of the linearisation point when it depends on
     * it). The velocity multigrid approximates A_s^{-1} and leaves the
     * convection to the outer FGMRES: Chebyshev-Jacobi smoothing of the
     * full (non-symmetric) Oseen operator diverged with power-iteration
     * eigenvalue estimates and needed more than twice the FGMRES iterations
     * with Lanczos estimates (doc/performance.md).
     *
     * Q2 vector fields, 3^dim Gauss points, sum factorisation. Rows of
     * constrained DoFs (Dirichlet boundaries, and the masked DoFs inside
     * fictitious-boundary bodies on the finest level) act as the identity.
     */
    template <int dim, typename Number>
    class MassViscousOperator : public dealii::Subscriptor
    {
    public:
      using VectorType = dealii::LinearAlgebra::distributed::Vector<Number>;
      using value_type = Number;
      using VectorizedArray = SimdArray<Number>;
      using MatrixFree      = dealii::MatrixFree<dim, Number, VectorizedArray>;
      using Integrator
        = dealii::FEEvaluation<dim, 2, 3, dim, Number, VectorizedArray>;

      void
      initialize(std::shared_ptr<const MatrixFree> data);

      /**
       * The coefficients. @p velocity, the linearisation point on this
       * level's DoFs, is read only when @p viscosity_model depends on the
       * shear rate (ghost values are updated here).
       */
      void
      set_coefficients(const VectorType     &velocity,
                       const double          mass_coefficient,
                       const double          theta_implicit,
                       const ViscosityModel &viscosity_model);

      /** DoFs (this level's numbering, locally owned) whose rows act as the
       *  identity in addition to the boundary constraints. */
      void
      set_masked_dofs(const std::vector<dealii::types::global_dof_index> &dofs);

      /**
       * The inverse diagonal for the Chebyshev smoother: c_m diag(M) +
       * nu diag(K) from the mass and viscous diagonals computed once per
       * geometry (with a shear-rate dependent mu, nu is its reference
       * value here: the diagonal only scales the smoother).
       */
      const std::shared_ptr<dealii::DiagonalMatrix<VectorType>> &
      get_matrix_diagonal_inverse() const
      {
        return inverse_diagonal;
      }

      void
      vmult(VectorType &dst, const VectorType &src) const;
      void
      Tvmult(VectorType &dst, const VectorType &src) const;
      void
      vmult_add(VectorType &dst, const VectorType &src) const;
      void
      Tvmult_add(VectorType &dst, const VectorType &src) const;

      /** The cell kernel on unit-vector input, for MatrixFreeTools::
       *  compute_matrix (the coarse-level matrix). */
      void
      cell_kernel(Integrator &phi) const;

      void
      initialize_dof_vector(VectorType &vector) const
      {
        data->initialize_dof_vector(vector);
      }
      dealii::types::global_dof_index
      m() const
      {
        return data->get_vector_partitioner()->size();
      }
      dealii::types::global_dof_index
      n() const
      {
        return m();
      }

      /** A diagonal entry. PreconditionChebyshev needs it to compile; it
       *  would build its own Jacobi from it if no inverse diagonal were
       *  given. */
      Number
      el(const unsigned int row, const unsigned int col) const
      {
        AssertThrow(row == col, dealii::ExcNotImplemented());
        return Number(1.) / (*inverse_diagonal)(row, row);
      }

      std::size_t
      memory_consumption() const;

    private:
      void
      local_apply(const MatrixFree                            &data,
                  VectorType                                  &dst,
                  const VectorType                            &src,
                  const std::pair<unsigned int, unsigned int> &range) const;
      void
      quadrature_point_operation(Integrator        &phi,
                                 const unsigned int cell) const;
      void
      update_inverse_diagonal();

      std::shared_ptr<const MatrixFree> data;
      /// diag(M) and diag(K) of the unit-coefficient mass and viscous
      /// operators (geometry only)
      VectorType mass_diagonal, viscous_diagonal;
      std::shared_ptr<dealii::DiagonalMatrix<VectorType>> inverse_diagonal;

      Number mass_coefficient    = 0.;
      Number viscosity_constant  = 0.; ///< theta_i mu when mu is constant
      bool   viscosity_per_point = false;
      /// theta_i mu(gamma_dot(u*)) per cell batch and quadrature point
      dealii::Table<2, VectorizedArray> viscosity;
      /// locally owned constrained or masked rows (local indices)
      std::vector<unsigned int> identity_rows;
      std::vector<unsigned int> masked_rows;
      /// scratch of vmult_add (kept to spare an allocation per product)
      mutable std::vector<Number> kept_source, kept_destination;
    };
  } // namespace fluid
} // namespace particulate

#endif
