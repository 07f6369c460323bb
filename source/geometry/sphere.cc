#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/sphere.h>

#include <cmath>

namespace particulate::geometry {

  Sphere::Sphere(const double radius)
    : r(radius)
  {
    if (!(radius > 0.) || !std::isfinite(radius))
      throw GeometryError("Sphere: the radius must be positive and finite.");
  }

  double
  Sphere::signed_distance(const Eigen::Vector3d &p,
                          Eigen::Vector3d       *normal) const
  {
    const double d = p.norm();
    if (normal)
      *normal = d > 0. ? Eigen::Vector3d(p / d) : Eigen::Vector3d::UnitX();
    return d - r;
  }

  bool
  Sphere::contains(const Eigen::Vector3d &p) const
  {
    return p.squaredNorm() <= r * r;
  }

  BoundingBox
  Sphere::bounding_box() const
  {
    return BoundingBox(Eigen::Vector3d::Constant(-r),
                       Eigen::Vector3d::Constant(r));
  }

  double
  Sphere::volume() const
  {
    return 4. / 3. * M_PI * r * r * r;
  }

} // namespace particulate::geometry
