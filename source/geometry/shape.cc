#include <particulate/geometry/shape.h>

namespace particulate::geometry {

  bool
  Shape::contains(const Eigen::Vector3d &p) const
  {
    return signed_distance(p) <= 0.;
  }

  void
  Shape::contains_points(const Eigen::Vector3d *points,
                         const std::size_t      count,
                         bool                  *inside) const
  {
    for (std::size_t i = 0; i < count; ++i)
      inside[i] = contains(points[i]);
  }

  void
  Shape::signed_distances(const std::vector<Eigen::Vector3d> &points,
                          std::vector<double>                &distances,
                          std::vector<Eigen::Vector3d>       *normals) const
  {
    distances.resize(points.size());
    if (normals)
      normals->resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      distances[i]
        = signed_distance(points[i], normals ? &(*normals)[i] : nullptr);
  }

} // namespace particulate::geometry
