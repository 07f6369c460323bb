#ifndef PARTICULATE_GEOMETRY_SPHERE_H
#define PARTICULATE_GEOMETRY_SPHERE_H

#include <particulate/geometry/shape.h>

namespace particulate::geometry {

  /**
   * A ball of radius r centred at the body-frame origin; exact distance
   * |p| - r.
   */
  class Sphere : public Shape
  {
  public:
    /** @param radius r > 0 [m] */
    explicit Sphere(const double radius);

    /** Radius [m]. */
    double
    radius() const
    {
      return r;
    }

    double
    signed_distance(const Eigen::Vector3d &p,
                    Eigen::Vector3d       *normal = nullptr) const override;

    /** Closed-form test, cheaper than the distance. */
    bool
    contains(const Eigen::Vector3d &p) const override;

    BoundingBox
    bounding_box() const override;

    double
    volume() const override;

  private:
    double r;
  };

} // namespace particulate::geometry

#endif
