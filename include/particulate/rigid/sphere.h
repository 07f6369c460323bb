#ifndef particulate_rigid_sphere_h
#define particulate_rigid_sphere_h

#include <particulate/rigid/shape.h>

namespace particulate::rigid {
  /**
   * Solid sphere of radius r centred at the body origin.
   */
  class Sphere : public Shape
  {
  public:
    /** @param radius Sphere radius in m (> 0). */
    explicit Sphere(double radius);

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
    double
    core_radius() const override
    {
      return radius;
    }

    /** Radius in m. */
    double radius;
  };
} // namespace particulate::rigid

#endif
