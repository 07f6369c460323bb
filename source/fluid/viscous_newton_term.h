#ifndef particulate_fluid_viscous_newton_term_h
#define particulate_fluid_viscous_newton_term_h

// Private header of the fluid library: the part of one cell's Newton
// Jacobian that comes from a viscosity depending on the shear rate.

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * For trial phi_b e_d and test phi_a e_c (phi: the n_s scalar
     * functions of a cell), the derivative of (2 mu(g) D(u), D(v)) through
     * the shear rate g (see ViscosityModel):
     *
     *   T(c, d)[a][b] = sum_q s_q (D* grad phi_a)_c (D* grad phi_b)_d
     *
     * with s_q = theta_i 4 mu'(g)/g JxW and D* = D(u*) at the linearisation
     * point, since D*:D(phi_b e_d) = (D* grad phi_b)_d. The term is
     * symmetric and, for a stress mu(g) g that grows with g, keeps the
     * velocity block positive definite.
     */
    template <int dim>
    class ViscousNewtonTerm
    {
    public:
      explicit ViscousNewtonTerm(const unsigned int n_s)
        : n_s(n_s)
        , projected(n_s)
        , blocks(dim * dim * n_s * n_s)
      {}

      /** Start a cell. */
      void
      reset()
      {
        std::fill(blocks.begin(), blocks.end(), 0.);
      }

      /** Add quadrature point with weight @p s, D* and the gradients of
       *  the n_s scalar functions. */
      void
      add(const double                               s,
          const dealii::SymmetricTensor<2, dim>     &D_star,
          const std::vector<dealii::Tensor<1, dim>> &grad_phi)
      {
        for (unsigned int a = 0; a < n_s; ++a)
          projected[a] = D_star * grad_phi[a];
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int d = 0; d < dim; ++d)
            {
              double *block = &blocks[(c * dim + d) * n_s * n_s];
              for (unsigned int a = 0; a < n_s; ++a)
                {
                  const double left = s * projected[a][c];
                  for (unsigned int b = 0; b < n_s; ++b)
                    block[a * n_s + b] += left * projected[b][d];
                }
            }
      }

      double
      operator()(const unsigned int c,
                 const unsigned int d,
                 const unsigned int a,
                 const unsigned int b) const
      {
        return blocks[((c * dim + d) * n_s + a) * n_s + b];
      }

    private:
      unsigned int                        n_s;
      std::vector<dealii::Tensor<1, dim>> projected;
      std::vector<double>                 blocks;
    };
  } // namespace fluid
} // namespace particulate

#endif
