#ifndef particulate_rigid_ellipsoid_h
#define particulate_rigid_ellipsoid_h

#include <particulate/rigid/shape.h>

namespace particulate::rigid {
  /**
   * Solid ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 <= 1 in the body frame. The
   * signed distance is exact (Eberly's root bisection for the closest point).
   */
  class Ellipsoid : public Shape
  {
  public:
    /** @param semi_axes Semi-axes a, b, c in m (all > 0). */
    explicit Ellipsoid(const Eigen::Vector3d &semi_axes);

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

    /** Semi-axes in m. */
    Eigen::Vector3d semi_axes;
  };
} // namespace particulate::rigid

#endif
