#ifndef PARTICULATE_GEOMETRY_BOX_H
#define PARTICULATE_GEOMETRY_BOX_H

#include <particulate/geometry/shape.h>

namespace particulate::geometry {

  /**
   * The box [-h, h] (half extents h) centred at the body-frame origin, axes
   * along the body axes; exact signed distance, also at edges and corners.
   */
  class Box : public Shape
  {
  public:
    /** @param half_extents h, all components > 0 [m] */
    explicit Box(const Eigen::Vector3d &half_extents);

    /** Half extents [m]. */
    const Eigen::Vector3d &
    half_extents() const
    {
      return h;
    }

    double
    signed_distance(const Eigen::Vector3d &p,
                    Eigen::Vector3d       *normal = nullptr) const override;

    BoundingBox
    bounding_box() const override;

    double
    volume() const override;

  private:
    Eigen::Vector3d h;
  };

} // namespace particulate::geometry

#endif
