#include <particulate/geometry/shape.h>

namespace particulate::geometry {

bool
Shape::contains(const Eigen::Vector3d &p) const
{
  return signed_distance(p) <= 0.;
}

} // namespace particulate::geometry
