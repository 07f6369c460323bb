#ifndef particulate_geometry_elliptic_cylinder_h
#define particulate_geometry_elliptic_cylinder_h

#include <particulate/geometry/shape.h>

#include <algorithm>
#include <cmath>

namespace particulate {
  namespace geometry {

    /**
     * A solid right cylinder over the ellipse (x/a)^2 + (y/b)^2 <= 1, extending
     * from z = -h to z = h (half height h), centred at the origin with flat
     * caps; exact signed distance including the rims. The ellipse distance is
     * D. Eberly's exact closest point (as for Ellipsoid), combined with the cap
     * distance as for Cylinder, so queries in the plane z = 0 give the exact 2D
     * ellipse distance: an ellipse of a 2D run is an elliptic cylinder along z
     * (of unit depth, h = 0.5).
     *
     * It has no dedicated kind (ShapeKind's numbering is part of the
     * checkpoint format): as a convex `general` shape the narrow phase meets it
     * through its support function (GJK/EPA, convex-plane fan).
     */
    class EllipticCylinder : public Shape
    {
    public:
      /**
       * @param semi_axis_x a > 0, semi-axis of the ellipse along body x [m]
       * @param semi_axis_y b > 0, semi-axis of the ellipse along body y [m]
       * @param half_height h > 0 [m]
       */
      EllipticCylinder(const double semi_axis_x,
                       const double semi_axis_y,
                       const double half_height);

      /** Semi-axes (a, b) of the cross-section along body x and y [m]. */
      Eigen::Vector2d
      semi_axes() const
      {
        return Eigen::Vector2d(a, b);
      }

      /** Half the length along the axis [m]. */
      double
      half_height() const
      {
        return hh;
      }

      /** `general`: see the class documentation. */
      ShapeKind
      kind() const override
      {
        return ShapeKind::general;
      }

      std::string
      name() const override
      {
        return "elliptic cylinder";
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
        return std::hypot(std::max(a, b), hh);
      }

      double
      volume() const override;

      /** V (b^2 / 4 + L^2 / 12) about x, V (a^2 / 4 + L^2 / 12) about y and
       *  V (a^2 + b^2) / 4 about z, with L = 2h. */
      Eigen::Matrix3d
      unit_inertia() const override;

      bool
      is_convex() const override
      {
        return true;
      }

      /** (a^2 d_x, b^2 d_y) / |(a d_x, b d_y)| on the rim of the cap that
       *  faces d (the cap centre if d is along the axis). */
      Eigen::Vector3d
      support(const Eigen::Vector3d &d) const override;

      /** 16 points around each rim and the middle ellipse (equal steps of the
       *  parametric angle), and the two cap centres. */
      std::vector<Eigen::Vector3d>
      surface_points() const override;

      /** The display triangulation: prism of 48 sides with its caps. */
      TriangleMesh
      surface_mesh() const override;

    private:
      double a;
      double b;
      double hh;
    };

  } // namespace geometry
} // namespace particulate

#endif
