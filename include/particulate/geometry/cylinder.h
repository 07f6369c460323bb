#ifndef PARTICULATE_GEOMETRY_CYLINDER_H
#define PARTICULATE_GEOMETRY_CYLINDER_H

#include <particulate/geometry/shape.h>

namespace particulate::geometry {

  /**
   * A solid circular cylinder around the body z axis, radius r, extending
   * from z = -h to z = h (half height h), centred at the origin; exact signed
   * distance including the rims.
   */
  class Cylinder : public Shape
  {
  public:
    /**
     * @param radius r > 0 [m]
     * @param half_height h > 0 [m]
     */
    Cylinder(const double radius, const double half_height);

    double
    signed_distance(const Eigen::Vector3d &p,
                    Eigen::Vector3d       *normal = nullptr) const override;

    BoundingBox
    bounding_box() const override;

    double
    volume() const override;

  private:
    double r;
    double hh;
  };

} // namespace particulate::geometry

#endif
