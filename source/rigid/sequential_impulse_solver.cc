#include <particulate/rigid/sequential_impulse_solver.h>

#include <cmath>

namespace particulate {
  namespace rigid {
    unsigned int
    SequentialImpulseSolver::solve_rows(const std::size_t begin,
                                        const std::size_t end)
    {
      // Warm start: apply last step's impulses first.
      for (std::size_t i = begin; i < end; ++i)
        for (int k = 0; k < 3; ++k)
          if (rows_[i].lambda[k] != 0.)
            apply(rows_[i], k, rows_[i].lambda[k]);

      unsigned int it = 0;
      for (; it < parameters.iterations; ++it)
        {
          double change = 0., size = 0.;
          for (std::size_t i = begin; i < end; ++i)
            {
              Row &r = rows_[i];
              // Friction: both tangents at once, clamped to the circular cone
              // of radius mu * lambda_n (eq. 4.103).
              if (r.mu > 0.)
                {
                  const double v1 = velocity(r, 1), v2 = velocity(r, 2);
                  double       l1  = r.lambda[1] - v1 / r.k[1];
                  double       l2  = r.lambda[2] - v2 / r.k[2];
                  const double lim = r.mu * r.lambda[0];
                  const double len = std::hypot(l1, l2);
                  if (len > lim)
                    {
                      const double s = len > 0. ? lim / len : 0.;
                      l1 *= s;
                      l2 *= s;
                    }
                  const double d1 = l1 - r.lambda[1], d2 = l2 - r.lambda[2];
                  apply(r, 1, d1);
                  apply(r, 2, d2);
                  r.lambda[1] = l1;
                  r.lambda[2] = l2;
                  change
                    = std::max(change, std::max(std::abs(d1), std::abs(d2)));
                }
              // Normal: v_n >= bias, lambda_n >= 0.
              const double vn = velocity(r, 0);
              const double ln
                = std::max(r.lambda[0] - (vn - r.bias) / r.k[0], 0.);
              const double dn = ln - r.lambda[0];
              apply(r, 0, dn);
              r.lambda[0] = ln;
              change      = std::max(change, std::abs(dn));
              size        = std::max(size, ln);
            }
          if (change <= parameters.tolerance * size || size == 0.)
            {
              ++it;
              break;
            }
        }
      return it;
    }
  } // namespace rigid
} // namespace particulate
