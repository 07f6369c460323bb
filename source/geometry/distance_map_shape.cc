#include <particulate/geometry/distance_map_shape.h>
#include <particulate/geometry/geometry_error.h>

#include <algorithm>

namespace particulate {
  namespace geometry {

    DistanceMapShape::DistanceMapShape(std::shared_ptr<const DistanceMap> map)
      : dmap(std::move(map))
    {
      if (!dmap || dmap->n_points()[0] == 0)
        throw GeometryError("DistanceMapShape: the distance map is missing or "
                            "empty; build it first.");
    }

    double
    DistanceMapShape::signed_distance(const Eigen::Vector3d &p,
                                      Eigen::Vector3d       *normal) const
    {
      return dmap->distance(p, normal);
    }

    void
    DistanceMapShape::signed_distances(
      const std::vector<Eigen::Vector3d> &points,
      std::vector<double>                &distances,
      std::vector<Eigen::Vector3d>       *normals) const
    {
      distances.resize(points.size());
      if (normals)
        normals->resize(points.size());
      dmap->distances(points.data(),
                      points.size(),
                      distances.data(),
                      normals ? normals->data() : nullptr);
    }

    bool
    DistanceMapShape::contains(const Eigen::Vector3d &p) const
    {
      return dmap->covers(p) && dmap->distance(p) <= 0.;
    }

    void
    DistanceMapShape::contains_points(const Eigen::Vector3d *points,
                                      const std::size_t      count,
                                      bool                  *inside) const
    {
      // Groups small enough that their distances stay in the L1 cache.
      constexpr std::size_t group = 256;
      double                d[group];
      const BoundingBox     box = dmap->grid_box(); // covers() per point
      for (std::size_t first = 0; first < count; first += group)
        {
          const std::size_t m = std::min(group, count - first);
          dmap->distances(points + first, m, d);
          for (std::size_t q = 0; q < m; ++q)
            inside[first + q] = box.contains(points[first + q]) && d[q] <= 0.;
        }
    }

    BoundingBox
    DistanceMapShape::bounding_box() const
    {
      return dmap->grid_box();
    }

    double
    DistanceMapShape::volume() const
    {
      const auto &n     = dmap->n_points();
      std::size_t count = 0;
      for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i)
            count += dmap->value(i, j, k) < 0.;
      const double h = dmap->spacing();
      return static_cast<double>(count) * h * h * h;
    }

  } // namespace geometry
} // namespace particulate
