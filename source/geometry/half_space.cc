#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/half_space.h>

#include <cmath>
#include <limits>

namespace particulate {
  namespace geometry {

    HalfSpace::HalfSpace(const Eigen::Vector3d &normal, const double offset)
      : n(normal)
      , c(offset)
    {
      const double length = normal.norm();
      if (!(length > 0.) || !std::isfinite(length) || !std::isfinite(offset))
        throw GeometryError(
          "HalfSpace: the normal must be a finite non-zero vector and the offset "
          "finite.");
      n /= length;
    }

    double
    HalfSpace::signed_distance(const Eigen::Vector3d &p,
                               Eigen::Vector3d       *normal) const
    {
      if (normal)
        *normal = n;
      return n.dot(p) - c;
    }

    BoundingBox
    HalfSpace::bounding_box() const
    {
      const double inf = std::numeric_limits<double>::infinity();
      BoundingBox  box(Eigen::Vector3d::Constant(-inf),
                      Eigen::Vector3d::Constant(inf));
      // An axis-aligned half-space is bounded on one side.
      for (int d = 0; d < 3; ++d)
        if (std::abs(n[d]) == 1.)
          (n[d] > 0. ? box.upper[d] : box.lower[d]) = c * n[d];
      return box;
    }

    double
    HalfSpace::volume() const
    {
      return std::numeric_limits<double>::infinity();
    }

  } // namespace geometry
} // namespace particulate
