#ifndef particulate_geometry_sphere_h
#define particulate_geometry_sphere_h

#include <particulate/geometry/shape.h>

namespace particulate {
  namespace geometry {

    /**
     * A ball of radius r centred at the body-frame origin; exact distance
     * |p| - r. In a 2D run a disk is a cylinder, not a sphere.
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

      ShapeKind
      kind() const override
      {
        return ShapeKind::sphere;
      }

      std::string
      name() const override
      {
        return "sphere";
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
      bounding_radius() const override
      {
        return r;
      }

      double
      volume() const override;

      /** (2/5) V r^2 on the diagonal. */
      Eigen::Matrix3d
      unit_inertia() const override;

      bool
      is_convex() const override
      {
        return true;
      }

      Eigen::Vector3d
      support(const Eigen::Vector3d &d) const override;

      double
      core_radius() const override
      {
        return r;
      }

      /** 26 points in the directions of a cube cell's neighbours. */
      std::vector<Eigen::Vector3d>
      surface_points() const override;

      /** The display triangulation: icosphere of 320 triangles. */
      TriangleMesh
      surface_mesh() const override;

    private:
      double r;
    };

  } // namespace geometry
} // namespace particulate

#endif
