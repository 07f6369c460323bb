#include <particulate/rigid/projected_gauss_seidel_solver.h>

#include <algorithm>
#include <cmath>

namespace particulate {
  namespace rigid {
    unsigned int
    ProjectedGaussSeidelSolver::solve_rows(const std::size_t begin,
                                           const std::size_t end)
    {
      const std::size_t m = end - begin;
      if (m == 0)
        return 0;

      // Contacts per dynamic body (fixed bodies couple nothing: their inverse
      // mass is zero, and skipping them keeps a floor from coupling all
      // contacts resting on it).
      std::vector<std::pair<unsigned int, unsigned int>>
        incidence; // (body, local row)
      incidence.reserve(2 * m);
      for (std::size_t i = 0; i < m; ++i)
        {
          const Row &r = rows_[begin + i];
          if (sb_[r.a].inv_m > 0.)
            incidence.emplace_back(r.a, i);
          if (sb_[r.b].inv_m > 0.)
            incidence.emplace_back(r.b, i);
        }
      std::sort(incidence.begin(), incidence.end());

      // Assemble A = J M^{-1} J^T as 3x3 blocks (eqs. 4.69-4.72).
      blocks_.assign(m, {});
      std::vector<int> slot(m, -1);
      for (std::size_t i = 0; i < m; ++i)
        {
          const Row &ri = rows_[begin + i];
          for (const unsigned int s : {ri.a, ri.b})
            {
              if (!(sb_[s].inv_m > 0.) || (s == ri.b && ri.a == ri.b))
                continue;
              const double si = s == ri.a ? -1. : 1.;
              auto         lo = std::lower_bound(incidence.begin(),
                                         incidence.end(),
                                         std::make_pair(s, 0u));
              for (auto it = lo; it != incidence.end() && it->first == s; ++it)
                {
                  const unsigned int j  = it->second;
                  const Row         &rj = rows_[begin + j];
                  const double       sj = s == rj.a ? -1. : 1.;
                  if (slot[j] < 0)
                    {
                      slot[j] = blocks_[i].size();
                      Block b;
                      b.col = j;
                      std::fill(&b.m[0][0], &b.m[0][0] + 9, 0.);
                      blocks_[i].push_back(b);
                    }
                  Block &b = blocks_[i][slot[j]];
                  for (int p = 0; p < 3; ++p)
                    for (int q = 0; q < 3; ++q)
                      {
                        const Eigen::Vector3d &ci
                          = s == ri.a ? ri.ra_x[p] : ri.rb_x[p];
                        const Eigen::Vector3d &Ij
                          = s == rj.a ? rj.ia[q] : rj.ib[q];
                        b.m[p][q] += si * sj
                                     * (sb_[s].inv_m * ri.dir[p].dot(rj.dir[q])
                                        + ci.dot(Ij));
                      }
                }
            }
          for (const Block &b : blocks_[i])
            slot[b.col] = -1;
        }

      // Right-hand side b = J u - target with the kicked velocities.
      std::vector<double> rhs(3 * m), x(3 * m), diag(3 * m);
      for (std::size_t i = 0; i < m; ++i)
        {
          const Row &r = rows_[begin + i];
          for (int p = 0; p < 3; ++p)
            {
              rhs[3 * i + p] = velocity(r, p) - (p == 0 ? r.bias : 0.);
              x[3 * i + p]   = r.lambda[p];
            }
          for (const Block &b : blocks_[i])
            if (b.col == i)
              for (int p = 0; p < 3; ++p)
                diag[3 * i + p] = b.m[p][p];
        }

      // Projected Gauss-Seidel sweeps (eq. 4.86 with the clamping of 4.84).
      unsigned int it = 0;
      for (; it < parameters.iterations; ++it)
        {
          double change = 0., size = 0.;
          for (std::size_t i = 0; i < m; ++i)
            {
              const Row &r = rows_[begin + i];
              for (int p = 0; p < 3; ++p)
                {
                  if (p > 0 && r.mu == 0.)
                    {
                      x[3 * i + p] = 0.;
                      continue;
                    }
                  double res = rhs[3 * i + p];
                  for (const Block &b : blocks_[i])
                    for (int q = 0; q < 3; ++q)
                      res += b.m[p][q] * x[3 * b.col + q];
                  double v = x[3 * i + p] - res / diag[3 * i + p];
                  if (p == 0)
                    v = std::max(v, 0.);
                  else
                    {
                      const double hi = r.mu * x[3 * i];
                      v               = std::clamp(v, -hi, hi);
                    }
                  change       = std::max(change, std::abs(v - x[3 * i + p]));
                  x[3 * i + p] = v;
                  if (p == 0)
                    size = std::max(size, v);
                }
            }
          if (change <= parameters.tolerance * size || size == 0.)
            {
              ++it;
              break;
            }
        }

      // Apply the impulses to the velocities.
      for (std::size_t i = 0; i < m; ++i)
        {
          Row &r = rows_[begin + i];
          for (int p = 0; p < 3; ++p)
            {
              r.lambda[p] = x[3 * i + p];
              if (r.lambda[p] != 0.)
                apply(r, p, r.lambda[p]);
            }
        }
      return it;
    }
  } // namespace rigid
} // namespace particulate
