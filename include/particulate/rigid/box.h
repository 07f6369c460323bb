#ifndef particulate_rigid_box_h
#define particulate_rigid_box_h

#include <particulate/rigid/shape.h>

namespace particulate::rigid {
  /**
   * Solid rectangular box centred at the body origin with its edges along
   * the body axes.
   */
  class Box : public Shape
  {
  public:
    /** @param half_extents Half edge lengths along x, y, z in m (all > 0). */
    explicit Box(const Eigen::Vector3d &half_extents);

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
    double
    signed_distance(const Eigen::Vector3d &p_body) const override;
    Eigen::Vector3d
    gradient(const Eigen::Vector3d &p_body) const override;
    bool
    is_convex() const override
    {
      return true;
    }
    Eigen::Vector3d
    support(const Eigen::Vector3d &d_body) const override;
    std::vector<Eigen::Vector3d>
    surface_points() const override;

    /** Half edge lengths in m. */
    Eigen::Vector3d half_extents;
  };
} // namespace particulate::rigid

#endif
