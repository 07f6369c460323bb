// simd.h first: it switches deal.II's SIMD arrays back on for this file
#include "simd.h"
//
#include "velocity_jacobian_kernel.h"

namespace particulate {
  namespace fluid {
    namespace {
      constexpr unsigned int
      n_weights(const unsigned int dim)
      {
        return 2 + dim + dim * dim; // m, nu, beta, N
      }

      /**
       * block[a][b] = sum_k left[a][k] right[k][b] for all n_rows test
       * functions a (a multiple of 3) and the `stride` trial columns, on
       * tiles of 3 rows times all columns held in registers.
       */
      template <unsigned int stride>
      void
      tiled_product(const double      *left,
                    const double      *right,
                    const unsigned int n_rows,
                    const unsigned int n_terms,
                    double            *block)
      {
        using Simd                    = SimdArray<double>;
        constexpr unsigned int lanes  = Simd::size();
        constexpr unsigned int chunks = stride / lanes;
        constexpr unsigned int tile   = 3;
        static_assert(stride % lanes == 0, "rows must fill whole registers");
        for (unsigned int a0 = 0; a0 < n_rows; a0 += tile)
          {
            Simd sum[tile][chunks];
            for (unsigned int t = 0; t < tile; ++t)
              for (unsigned int j = 0; j < chunks; ++j)
                sum[t][j] = 0.;
            const double *left_0 = left + a0 * n_terms;
            const double *left_1 = left_0 + n_terms;
            const double *left_2 = left_1 + n_terms;
            for (unsigned int k = 0; k < n_terms; ++k)
              {
                const double *right_k = right + k * stride;
                Simd          r[chunks];
                for (unsigned int j = 0; j < chunks; ++j)
                  r[j].load(right_k + j * lanes);
                const Simd l_0 = left_0[k], l_1 = left_1[k], l_2 = left_2[k];
                for (unsigned int j = 0; j < chunks; ++j)
                  {
                    sum[0][j] += l_0 * r[j];
                    sum[1][j] += l_1 * r[j];
                    sum[2][j] += l_2 * r[j];
                  }
              }
            for (unsigned int t = 0; t < tile; ++t)
              for (unsigned int j = 0; j < chunks; ++j)
                sum[t][j].store(block + (a0 + t) * stride + j * lanes);
          }
      }
    } // namespace



    template <int dim>
    VelocityJacobianKernel<dim>::VelocityJacobianKernel(
      const unsigned int n_quadrature_points)
      : n_q(n_quadrature_points)
      , left(n_s * n_q * n_features)
      , left_off_diagonal(dim * n_s * n_q * 2)
      , right_functions(n_q * n_features * stride, 0.)
      , weights(n_q * n_weights(dim))
      , right(n_q * n_features * stride, 0.)
      , blocks(dim * dim * n_s * stride)
    {}



    template <int dim>
    void
    VelocityJacobianKernel<dim>::set_quadrature_point(
      const unsigned int   q,
      const double        *phi,
      const double *const *gradient,
      const double         mass,
      const double         viscosity,
      const double        *advection,
      const double        *newton)
    {
      double *functions = &right_functions[q * n_features * stride];
      for (unsigned int b = 0; b < n_s; ++b)
        functions[b] = phi[b];
      for (unsigned int e = 0; e < dim; ++e)
        for (unsigned int b = 0; b < n_s; ++b)
          functions[(1 + e) * stride + b] = gradient[e][b];
      for (unsigned int a = 0; a < n_s; ++a)
        {
          double *row = &left[(a * n_q + q) * n_features];
          row[0]      = phi[a];
          for (unsigned int e = 0; e < dim; ++e)
            row[1 + e] = gradient[e][a];
          for (unsigned int d = 0; d < dim; ++d)
            {
              double *pair = &left_off_diagonal[((d * n_s + a) * n_q + q) * 2];
              pair[0]      = phi[a];
              pair[1]      = gradient[d][a];
            }
        }
      double *w = &weights[q * n_weights(dim)];
      w[0]      = mass;
      w[1]      = viscosity;
      for (unsigned int e = 0; e < dim; ++e)
        w[2 + e] = advection[e];
      for (unsigned int i = 0; i < dim * dim; ++i)
        w[2 + dim + i] = newton[i];
    }



    template <int dim>
    void
    VelocityJacobianKernel<dim>::compute()
    {
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int d = 0; d < dim; ++d)
          {
            double *block = &blocks[(c * dim + d) * n_s * stride];
            if (c == d)
              {
                // k = (q, feature): the test function's phi pairs with
                // the mass, advection and Newton terms, its derivative e
                // with the viscous ones (twice for e = c: grad phi_a .
                // grad phi_b and d_c phi_a d_c phi_b)
                for (unsigned int q = 0; q < n_q; ++q)
                  {
                    const double *w  = &weights[q * n_weights(dim)];
                    const double  m  = w[0] + w[2 + dim + c * dim + c];
                    const double  nu = w[1];
                    const double *f = &right_functions[q * n_features * stride];
                    double       *r = &right[q * n_features * stride];
                    for (unsigned int b = 0; b < n_s; ++b)
                      {
                        double value = m * f[b];
                        for (unsigned int e = 0; e < dim; ++e)
                          value += w[2 + e] * f[(1 + e) * stride + b];
                        r[b] = value;
                      }
                    for (unsigned int e = 0; e < dim; ++e)
                      for (unsigned int b = 0; b < n_s; ++b)
                        r[(1 + e) * stride + b]
                          = (e == c ? 2. : 1.) * nu * f[(1 + e) * stride + b];
                  }
                tiled_product<stride>(left.data(),
                                      right.data(),
                                      n_s,
                                      n_q * n_features,
                                      block);
              }
            else
              {
                // k = (q, phi or d_d phi): N_q(c, d) phi_a phi_b and
                // nu_q d_d phi_a d_c phi_b
                for (unsigned int q = 0; q < n_q; ++q)
                  {
                    const double *w = &weights[q * n_weights(dim)];
                    const double *f = &right_functions[q * n_features * stride];
                    double       *r = &right[q * 2 * stride];
                    const double  newton_cd = w[2 + dim + c * dim + d];
                    for (unsigned int b = 0; b < n_s; ++b)
                      {
                        r[b]          = newton_cd * f[b];
                        r[stride + b] = w[1] * f[(1 + c) * stride + b];
                      }
                  }
                tiled_product<stride>(&left_off_diagonal[d * n_s * n_q * 2],
                                      right.data(),
                                      n_s,
                                      n_q * 2,
                                      block);
              }
          }
    }

    template class VelocityJacobianKernel<2>;
    template class VelocityJacobianKernel<3>;
  } // namespace fluid
} // namespace particulate
