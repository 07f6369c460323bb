#ifndef particulate_geometry_torus_h
#define particulate_geometry_torus_h

#include <particulate/geometry/shape.h>

namespace particulate {
  namespace geometry {

    /**
     * A ring torus around the body z axis: tube of radius r whose centre circle
     * has radius R > r in the plane z = 0; exact distance
     * sqrt((sqrt(x^2 + y^2) - R)^2 + z^2) - r. Used for exact comparisons with
     * a non-convex solid.
     */
    class Torus : public Shape
    {
    public:
      /**
       * @param major_radius R [m]
       * @param minor_radius r, 0 < r < R [m]
       */
      Torus(const double major_radius, const double minor_radius);

      std::string
      name() const override
      {
        return "torus";
      }

      double
      signed_distance(const Eigen::Vector3d &p,
                      Eigen::Vector3d       *normal = nullptr) const override;

      BoundingBox
      bounding_box() const override;

      double
      bounding_radius() const override
      {
        return R + r;
      }

      double
      volume() const override;

      /** V (R^2/2 + 5r^2/8) about the transverse axes, V (R^2 + 3r^2/4)
       *  about z. */
      Eigen::Matrix3d
      unit_inertia() const override;

      /** 36 x 12 points on a grid of the two angles. */
      std::vector<Eigen::Vector3d>
      surface_points() const override;

      /** The display triangulation: 48 x 24 quadrilaterals, split. */
      TriangleMesh
      surface_mesh() const override;

    private:
      double R;
      double r;
    };

  } // namespace geometry
} // namespace particulate

#endif
