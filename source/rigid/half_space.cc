#include <particulate/rigid/half_space.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace particulate::rigid {
  HalfSpace::HalfSpace(const Eigen::Vector3d &n, const double off)
    : normal(n)
    , offset(off)
  {
    if (!(n.norm() > 0.) || !n.allFinite() || !std::isfinite(off))
      throw std::invalid_argument(
        "rigid::HalfSpace: the normal must be a non-zero finite vector and "
        "the offset a finite length in m.");
    normal.normalize();
  }
  ShapeType
  HalfSpace::type() const
  {
    return ShapeType::half_space;
  }
  std::string
  HalfSpace::name() const
  {
    return "half-space";
  }
  double
  HalfSpace::volume() const
  {
    return std::numeric_limits<double>::infinity();
  }
  Eigen::Vector3d
  HalfSpace::unit_density_inertia() const
  {
    return Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  }
  double
  HalfSpace::bounding_radius() const
  {
    return std::numeric_limits<double>::infinity();
  }
  double
  HalfSpace::signed_distance(const Eigen::Vector3d &p) const
  {
    return normal.dot(p) - offset;
  }
  Eigen::Vector3d
  HalfSpace::gradient(const Eigen::Vector3d &) const
  {
    return normal;
  }
} // namespace particulate::rigid
