#include <particulate/rigid/sphere_neighbour_search.h>

#include <algorithm>
#include <cmath>

namespace particulate {
  namespace rigid {
    SphereNeighbourSearch::SphereNeighbourSearch(
      const std::vector<Eigen::Vector3d> &x,
      const std::vector<double>          &radius,
      const double                        extra)
    {
      const std::size_t n = x.size();
      order_.resize(n);
      if (n == 0)
        return;
      Eigen::Vector3d lo = x[0], hi = x[0];
      double          r_max = 0.;
      for (std::size_t i = 0; i < n; ++i)
        {
          lo    = lo.cwiseMin(x[i]);
          hi    = hi.cwiseMax(x[i]);
          r_max = std::max(r_max, radius[i]);
        }
      // One cutoff wide, but at most 2^20 cells per axis so that the cell
      // numbers fit in 64 bits however far a sphere strays.
      double cell
        = std::max(2. * r_max + extra, (hi - lo).maxCoeff() / 1048576.);
      if (!(cell > 0.))
        cell = 1.;
      std::int64_t dims[3];
      for (int d = 0; d < 3; ++d)
        dims[d] = std::int64_t((hi[d] - lo[d]) / cell) + 1;
      auto coordinate = [&](const Eigen::Vector3d &p, const int d) {
        return std::clamp<std::int64_t>(std::int64_t((p[d] - lo[d]) / cell),
                                        0,
                                        dims[d] - 1);
      };

      // Sort by (cell, old index): the spatial order.
      std::vector<std::pair<std::int64_t, unsigned int>> keyed(n);
      for (std::size_t i = 0; i < n; ++i)
        keyed[i]
          = {(coordinate(x[i], 2) * dims[1] + coordinate(x[i], 1)) * dims[0]
               + coordinate(x[i], 0),
             static_cast<unsigned int>(i)};
      std::sort(keyed.begin(), keyed.end());
      struct Cell
      {
        std::int64_t  key;
        std::uint32_t begin, end;
      };
      std::vector<Cell> cells;
      for (std::size_t k = 0; k < n; ++k)
        {
          order_[k] = keyed[k].second;
          if (cells.empty() || cells.back().key != keyed[k].first)
            cells.push_back({keyed[k].first,
                             static_cast<std::uint32_t>(k),
                             static_cast<std::uint32_t>(k + 1)});
          else
            cells.back().end = k + 1;
        }

      std::vector<Eigen::Vector3d> y(n);
      std::vector<double>          s(n);
      for (std::size_t k = 0; k < n; ++k)
        {
          y[k] = x[order_[k]];
          s[k] = radius[order_[k]];
        }
      pairs_.clear();
      pairs_.reserve(4 * n);
      auto test = [&](const std::uint32_t k, const std::uint32_t l) {
        const double c = s[k] + s[l] + extra;
        if ((y[l] - y[k]).squaredNorm() <= c * c)
          pairs_.emplace_back(k, l);
      };
      for (const Cell &c : cells)
        {
          for (std::uint32_t k = c.begin; k < c.end; ++k)
            for (std::uint32_t l = k + 1; l < c.end; ++l)
              test(k, l);
          const std::int64_t ix = c.key % dims[0],
                             iy = (c.key / dims[0]) % dims[1],
                             iz = c.key / (dims[0] * dims[1]);
          // The 13 neighbours that come later in cell order, so that every
          // pair of cells is visited once and every pair has first < second.
          for (int dz = 0; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx)
                {
                  if (dz == 0 && (dy < 0 || (dy == 0 && dx <= 0)))
                    continue;
                  const std::int64_t jx = ix + dx, jy = iy + dy, jz = iz + dz;
                  if (jx < 0 || jx >= dims[0] || jy < 0 || jy >= dims[1]
                      || jz >= dims[2])
                    continue;
                  const std::int64_t key = (jz * dims[1] + jy) * dims[0] + jx;
                  const auto         it
                    = std::lower_bound(cells.begin(),
                                       cells.end(),
                                       key,
                                       [](const Cell &a, const std::int64_t b) {
                                         return a.key < b;
                                       });
                  if (it == cells.end() || it->key != key)
                    continue;
                  for (std::uint32_t k = c.begin; k < c.end; ++k)
                    for (std::uint32_t l = it->begin; l < it->end; ++l)
                      test(k, l);
                }
        }
    }
  } // namespace rigid
} // namespace particulate
