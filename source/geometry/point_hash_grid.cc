#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/point_hash_grid.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace particulate::geometry {

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
      throw GeometryError("PointHashGrid: the cell size is too small for the "
                          "extent of the points (more than 2^21 cells along a "
                          "side); use a larger cell size.");

    std::vector<std::uint64_t> keys(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i)
      keys[i]
        = key(coord(pts[i][0], 0), coord(pts[i][1], 1), coord(pts[i][2], 2));
    order.resize(pts.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                       return keys[a] < keys[b];
                     });
    cells.reserve(pts.size() / 2 + 1);
    for (std::uint32_t q = 0; q < order.size();)
      {
        std::uint32_t e = q;
        while (e < order.size() && keys[order[e]] == keys[order[q]])
          ++e;
        cells.emplace(keys[order[q]], Range{q, e});
        cell_keys.push_back(keys[order[q]]);
        q = e;
      }
  }

} // namespace particulate::geometry
