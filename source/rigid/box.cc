#include <particulate/rigid/box.h>

#include <stdexcept>

namespace particulate::rigid {
  Box::Box(const Eigen::Vector3d &e)
    : half_extents(e)
  {
    if (!(e.minCoeff() > 0.) || !e.allFinite())
      throw std::invalid_argument(
        "rigid::Box: all three half extents must be positive finite lengths "
        "in m (note: half, not full, edge lengths).");
  }
  ShapeType
  Box::type() const
  {
    return ShapeType::box;
  }
  std::string
  Box::name() const
  {
    return "box";
  }
  double
  Box::volume() const
  {
    return 8. * half_extents.prod();
  }
  Eigen::Vector3d
  Box::unit_density_inertia() const
  {
    const Eigen::Vector3d s = half_extents.cwiseAbs2();
    return volume() / 3.
           * Eigen::Vector3d(s[1] + s[2], s[0] + s[2], s[0] + s[1]);
  }
  double
  Box::bounding_radius() const
  {
    return half_extents.norm();
  }
  double
  Box::signed_distance(const Eigen::Vector3d &p) const
  {
    const Eigen::Vector3d q = p.cwiseAbs() - half_extents;
    return q.cwiseMax(0.).norm() + std::min(q.maxCoeff(), 0.);
  }
  Eigen::Vector3d
  Box::gradient(const Eigen::Vector3d &p) const
  {
    const Eigen::Vector3d q = p.cwiseAbs() - half_extents;
    Eigen::Vector3d       g;
    if (q.maxCoeff() > 0.)
      g = q.cwiseMax(0.).normalized();
    else
      {
        int i;
        q.maxCoeff(&i);
        g    = Eigen::Vector3d::Zero();
        g[i] = 1.;
      }
    for (int i = 0; i < 3; ++i)
      if (p[i] < 0.)
        g[i] = -g[i];
    return g;
  }
  Eigen::Vector3d
  Box::support(const Eigen::Vector3d &d) const
  {
    return Eigen::Vector3d(d[0] >= 0. ? half_extents[0] : -half_extents[0],
                           d[1] >= 0. ? half_extents[1] : -half_extents[1],
                           d[2] >= 0. ? half_extents[2] : -half_extents[2]);
  }
  std::vector<Eigen::Vector3d>
  Box::surface_points() const
  {
    // Corners, edge midpoints and face centres.
    std::vector<Eigen::Vector3d> pts;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int k = -1; k <= 1; ++k)
          if (i != 0 || j != 0 || k != 0)
            pts.push_back(half_extents.cwiseProduct(Eigen::Vector3d(i, j, k)));
    return pts;
  }
} // namespace particulate::rigid
