#ifndef particulate_rigid_half_space_h
#define particulate_rigid_half_space_h

#include <particulate/rigid/shape.h>

namespace particulate::rigid {
  /**
   * Solid half-space {p : n . p <= offset} in the body frame: a wall or a
   * floor. It is unbounded, so a body carrying it must be fixed. The outward
   * normal n points into the free space.
   */
  class HalfSpace : public Shape
  {
  public:
    /**
     * @param normal Outward normal (into the free space), need not be unit.
     * @param offset Signed distance in m of the boundary plane from the
     * body origin along the normal.
     */
    HalfSpace(const Eigen::Vector3d &normal, double offset);

    ShapeType
    type() const override;
    std::string
    name() const override;
    double
    volume() const override;
    Eigen::Vector3d
    unit_density_inertia() const override;
    double
    bounding_radius() const override;
    bool
    is_bounded() const override
    {
      return false;
    }
    double
    signed_distance(const Eigen::Vector3d &p_body) const override;
    Eigen::Vector3d
    gradient(const Eigen::Vector3d &p_body) const override;
    bool
    is_convex() const override
    {
      return false;
    }

    /** Unit outward normal in the body frame. */
    Eigen::Vector3d normal;
    /** Plane offset in m along the normal. */
    double offset;
  };
} // namespace particulate::rigid

#endif
