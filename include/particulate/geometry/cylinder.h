#ifndef particulate_geometry_cylinder_h
#define particulate_geometry_cylinder_h

#include <particulate/geometry/shape.h>

#include <cmath>

namespace particulate {
  namespace geometry {

    /**
     * A solid circular cylinder around the body z axis, radius r, extending
     * from z = -h to z = h (half height h), centred at the origin, with flat
     * caps; exact signed distance including the rims. A disk of a 2D run is a
     * cylinder along z.
     */
    class Cylinder : public Shape
    {
    public:
      /**
       * @param radius r > 0 [m]
       * @param half_height h > 0 [m]
       */
      Cylinder(const double radius, const double half_height);

      /** Radius [m]. */
      double
      radius() const
      {
        return r;
      }

      /** Half the length along the axis [m]. */
      double
      half_height() const
      {
        return hh;
      }

      ShapeKind
      kind() const override
      {
        return ShapeKind::cylinder;
      }

      std::string
      name() const override
      {
        return "cylinder";
      }

      double
      signed_distance(const Eigen::Vector3d &p,
                      Eigen::Vector3d       *normal = nullptr) const override;

      BoundingBox
      bounding_box() const override;

      double
      bounding_radius() const override
      {
        return std::hypot(r, hh);
      }

      double
      volume() const override;

      /** V (3 r^2 + L^2) / 12 about the transverse axes, V r^2 / 2 about z. */
      Eigen::Matrix3d
      unit_inertia() const override;

      bool
      is_convex() const override
      {
        return true;
      }

      Eigen::Vector3d
      support(const Eigen::Vector3d &d) const override;

      /** 16 points around each rim and the middle circle, and the two cap
       *  centres. */
      std::vector<Eigen::Vector3d>
      surface_points() const override;

      /** The display triangulation: prism of 48 sides with its caps. */
      TriangleMesh
      surface_mesh() const override;

    private:
      double r;
      double hh;
    };

  } // namespace geometry
} // namespace particulate

#endif
