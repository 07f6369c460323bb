#ifndef particulate_rigid_cylinder_h
#define particulate_rigid_cylinder_h

#include <particulate/rigid/shape.h>

namespace particulate::rigid {
  /**
   * Solid circular cylinder centred at the body origin, axis along body z.
   */
  class Cylinder : public Shape
  {
  public:
    /** @param radius Radius in m. @param half_height Half the length along z in
     * m. */
    Cylinder(double radius, double half_height);

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

    /** Radius in m. */
    double radius;
    /** Half length along the axis in m. */
    double half_height;
  };
} // namespace particulate::rigid

#endif
