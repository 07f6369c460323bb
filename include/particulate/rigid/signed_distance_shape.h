#ifndef particulate_rigid_signed_distance_shape_h
#define particulate_rigid_signed_distance_shape_h

#include <particulate/rigid/shape.h>

namespace particulate::rigid {
  /**
   * Base class of shapes that are known only through a signed distance
   * function, typically a triangulated surface with a precomputed distance
   * map (thesis §3.4.2, Algorithm 5). The geometry module derives from this
   * class; the rigid engine needs only what is declared here:
   * signed_distance(), gradient(), bounding_radius(), surface_points() (the
   * mesh vertices, tested against the partner's distance function in the
   * narrow phase) and the mass properties, which a mesh computes once by
   * integration (thesis Algorithm 6) and passes to the constructor.
   */
  class SignedDistanceShape : public Shape
  {
  public:
    /**
     * @param volume Volume in m^3 (> 0).
     * @param unit_density_inertia Principal moments for density 1 about the
     * centre of mass in kg m^2 per (kg/m^3); the implementation must express
     * its distance function in that principal frame.
     * @param bounding_radius Radius in m of a sphere about the centre of
     * mass that contains the shape.
     */
    SignedDistanceShape(double                 volume,
                        const Eigen::Vector3d &unit_density_inertia,
                        double                 bounding_radius);

    ShapeType
    type() const override
    {
      return ShapeType::signed_distance;
    }
    std::string
    name() const override
    {
      return "signed distance";
    }
    double
    volume() const override
    {
      return volume_;
    }
    Eigen::Vector3d
    unit_density_inertia() const override
    {
      return inertia_;
    }
    double
    bounding_radius() const override
    {
      return bounding_radius_;
    }
    bool
    is_convex() const override
    {
      return false;
    }

  private:
    double          volume_;
    Eigen::Vector3d inertia_;
    double          bounding_radius_;
  };
} // namespace particulate::rigid

#endif
