#ifndef particulate_geometry_ellipsoid_h
#define particulate_geometry_ellipsoid_h

#include <particulate/geometry/shape.h>

namespace particulate {
  namespace geometry {

    /**
     * The ellipsoid (x/a)^2 + (y/b)^2 + (z/c)^2 <= 1 centred at the origin with
     * semi-axes along the body axes. The distance is the exact Euclidean one,
     * by D. Eberly's method ("Distance from a point to an ellipse, an
     * ellipsoid, or a hyperellipsoid", Geometric Tools, 2013): the closest
     * point solves a monotone scalar equation whose root bisection brackets to
     * machine precision, inside and outside.
     */
    class Ellipsoid : public Shape
    {
    public:
      /** @param semi_axes (a, b, c), all > 0 [m] */
      explicit Ellipsoid(const Eigen::Vector3d &semi_axes);

      /** Semi-axes (a, b, c) [m]. */
      const Eigen::Vector3d &
      semi_axes() const
      {
        return e;
      }

      ShapeKind
      kind() const override
      {
        return ShapeKind::ellipsoid;
      }

      std::string
      name() const override
      {
        return "ellipsoid";
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
        return e.maxCoeff();
      }

      double
      volume() const override;

      /** V (b^2 + c^2) / 5 and its permutations on the diagonal. */
      Eigen::Matrix3d
      unit_inertia() const override;

      bool
      is_convex() const override
      {
        return true;
      }

      /** e^2 d / |e d| (componentwise products). */
      Eigen::Vector3d
      support(const Eigen::Vector3d &d) const override;

      /** The 26 cube-neighbour directions scaled onto the surface. */
      std::vector<Eigen::Vector3d>
      surface_points() const override;

      /** The display triangulation: icosphere of 1280 triangles scaled by the
       * semi-axes. */
      TriangleMesh
      surface_mesh() const override;

    private:
      Eigen::Vector3d e;
    };

  } // namespace geometry
} // namespace particulate

#endif
