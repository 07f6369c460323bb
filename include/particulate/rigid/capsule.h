#ifndef particulate_rigid_capsule_h
#define particulate_rigid_capsule_h

#include <particulate/rigid/shape.h>

namespace particulate::rigid {
  /**
   * Capsule: the set of points within radius r of the segment from
   * (0,0,-h) to (0,0,h) in the body frame.
   */
  class Capsule : public Shape
  {
  public:
    /** @param radius Radius in m. @param half_length Half length h of the core
     * segment in m. */
    Capsule(double radius, double half_length);

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
    /** Half length of the core segment in m. */
    double half_length;
  };
} // namespace particulate::rigid

#endif
