#ifndef PARTICULATE_GEOMETRY_TORUS_H
#define PARTICULATE_GEOMETRY_TORUS_H

#include <particulate/geometry/shape.h>

namespace particulate::geometry {

  /**
   * A ring torus around the body z axis: tube of radius r whose centre circle
   * has radius R > r in the plane z = 0; exact distance
   * sqrt((sqrt(x^2 + y^2) - R)^2 + z^2) - r. Used for exact comparisons with
   * a non-convex solid.
   */
  class Torus : public Shape
  {
  public:
    /**
     * @param major_radius R [m]
     * @param minor_radius r, 0 < r < R [m]
     */
    Torus(const double major_radius, const double minor_radius);

    double
    signed_distance(const Eigen::Vector3d &p,
                    Eigen::Vector3d       *normal = nullptr) const override;

    BoundingBox
    bounding_box() const override;

    double
    volume() const override;

  private:
    double R;
    double r;
  };

} // namespace particulate::geometry

#endif
