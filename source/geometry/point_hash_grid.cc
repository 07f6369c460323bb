#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/point_hash_grid.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace particulate {
  namespace geometry {

    PointHashGrid::PointHashGrid(std::vector<Eigen::Vector3d> points,
                                 const double                 cell_size)
      : pts(std::move(points))
    {
      if (!(cell_size >= 0.) || !std::isfinite(cell_size))
        throw GeometryError("PointHashGrid: the cell size must be >= 0 (0 = "
                            "automatic).");
      if (pts.size() >= std::size_t(4294967295u))
        throw GeometryError("PointHashGrid: more than 2^32 - 1 points.");
      for (const auto &p : pts)
        {
          if (!p.allFinite())
            throw GeometryError("PointHashGrid: a point has a NaN or infinite "
                                "coordinate.");
          box.extend(p);
        }
      if (pts.empty())
        return;
      if (cell_size > 0.)
        h = cell_size;
      else
        {
          // About two points per cell if the points filled their box.
          const Eigen::Vector3d e
            = box.extent().cwiseMax(1e-12 * (1. + box.extent().maxCoeff()));
          h = std::cbrt(2. * e.prod() / static_cast<double>(pts.size()));
          h = std::max(h, e.maxCoeff() / 2097151.);
        }
      // The 21-bit cell coordinates must cover the box.
      if (box.extent().maxCoeff() / h >= 2097151.)
        throw GeometryError(
          "PointHashGrid: the cell size is too small for the "
          "extent of the points (more than 2^21 cells along a "
          "side); use a larger cell size.");

      // Sort (cell key, point id) pairs: contiguous, no indirection, and the
      // id breaks ties so the order is deterministic.
      std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(pts.size());
      for (std::size_t i = 0; i < pts.size(); ++i)
        keyed[i]
          = {key(coord(pts[i][0], 0), coord(pts[i][1], 1), coord(pts[i][2], 2)),
             static_cast<std::uint32_t>(i)};
      std::sort(keyed.begin(), keyed.end());
      order.resize(pts.size());
      for (std::size_t i = 0; i < pts.size(); ++i)
        order[i] = keyed[i].second;
      std::size_t n_cells = 0;
      for (std::size_t q = 0; q < keyed.size(); ++q)
        n_cells += (q == 0 || keyed[q].first != keyed[q - 1].first);
      cells.reserve(n_cells);
      cell_keys.reserve(n_cells);
      for (std::uint32_t q = 0; q < keyed.size();)
        {
          std::uint32_t e = q;
          while (e < keyed.size() && keyed[e].first == keyed[q].first)
            ++e;
          cells.emplace(keyed[q].first, Range{q, e});
          cell_keys.push_back(keyed[q].first);
          q = e;
        }
    }

  } // namespace geometry
} // namespace particulate
