// The velocity block of the Jacobian as small matrix products
// (source/fluid/velocity_jacobian_kernel.cc) against the formula summed
// entry by entry, for random shape-function data and weights in 2D and 3D:
//
//   J(c, d)[a][b] = sum_q delta_cd [ m phi_a phi_b + phi_a (beta . grad phi_b)
//                                    + nu grad phi_a . grad phi_b ]
//                        + nu d_d phi_a d_c phi_b + N(c, d) phi_a phi_b
//
// Both sum the same products in different orders, so they agree to
// round-off (1e-13 of the largest entry); a wrong or missing term (the
// transposed viscous part, an off-diagonal Newton entry, the advection)
// is off by O(1) of it.

#include "../../source/fluid/velocity_jacobian_kernel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {
  template <int dim>
  bool
  check(const unsigned int seed)
  {
    using Kernel = particulate::fluid::VelocityJacobianKernel<dim>;
    constexpr unsigned int                 n_s = Kernel::n_s;
    const unsigned int                     n_q = dim == 2 ? 9 : 27;
    std::mt19937                           random(seed);
    std::uniform_real_distribution<double> uniform(-1., 1.);

    // phi[q][b], gradient[q][e][b], weights per q
    std::vector<std::vector<double>> phi(n_q, std::vector<double>(n_s));
    std::vector<std::vector<std::vector<double>>> gradient(
      n_q,
      std::vector<std::vector<double>>(dim, std::vector<double>(n_s)));
    std::vector<double>              mass(n_q), viscosity(n_q);
    std::vector<std::vector<double>> advection(n_q, std::vector<double>(dim)),
      newton(n_q, std::vector<double>(dim * dim));
    Kernel kernel(n_q);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        for (unsigned int b = 0; b < n_s; ++b)
          {
            phi[q][b] = uniform(random);
            for (unsigned int e = 0; e < dim; ++e)
              gradient[q][e][b] = uniform(random);
          }
        mass[q]      = 1. + uniform(random);
        viscosity[q] = 1. + uniform(random);
        for (auto &value : advection[q])
          value = uniform(random);
        for (auto &value : newton[q])
          value = uniform(random);
        const double *rows[dim];
        for (unsigned int e = 0; e < dim; ++e)
          rows[e] = gradient[q][e].data();
        kernel.set_quadrature_point(q,
                                    phi[q].data(),
                                    rows,
                                    mass[q],
                                    viscosity[q],
                                    advection[q].data(),
                                    newton[q].data());
      }
    kernel.compute();

    double largest = 0., difference = 0.;
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int a = 0; a < n_s; ++a)
          for (unsigned int b = 0; b < n_s; ++b)
            {
              double expected = 0.;
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  double value
                    = viscosity[q] * gradient[q][d][a] * gradient[q][c][b]
                      + newton[q][c * dim + d] * phi[q][a] * phi[q][b];
                  if (c == d)
                    {
                      double advect_b = 0., grad_dot = 0.;
                      for (unsigned int e = 0; e < dim; ++e)
                        {
                          advect_b += advection[q][e] * gradient[q][e][b];
                          grad_dot += gradient[q][e][a] * gradient[q][e][b];
                        }
                      value += mass[q] * phi[q][a] * phi[q][b]
                               + phi[q][a] * advect_b + viscosity[q] * grad_dot;
                    }
                  expected += value;
                }
              largest = std::max(largest, std::abs(expected));
              difference
                = std::max(difference, std::abs(kernel(c, d, a, b) - expected));
            }
    const bool passed = difference <= 1e-13 * largest;
    std::printf("%s: %dD, largest entry %.3e, largest difference %.3e "
                "(limit 1e-13 of it)\n",
                passed ? "PASS" : "FAIL",
                dim,
                largest,
                difference);
    return passed;
  }
} // namespace

int
main()
{
  bool passed = true;
  for (const unsigned int seed : {1u, 2u})
    {
      passed &= check<2>(seed);
      passed &= check<3>(seed);
    }
  return passed ? 0 : 1;
}
