#ifndef particulate_geometry_box_h
#define particulate_geometry_box_h

#include <particulate/geometry/shape.h>

namespace particulate {
  namespace geometry {

    /**
     * The box [-h, h] (half extents h) centred at the body-frame origin, axes
     * along the body axes; exact signed distance, also at edges and corners.
     */
    class Box : public Shape
    {
    public:
      /** @param half_extents h, all components > 0 [m] */
      explicit Box(const Eigen::Vector3d &half_extents);

      /** Half extents [m]. */
      const Eigen::Vector3d &
      half_extents() const
      {
        return h;
      }

      ShapeKind
      kind() const override
      {
        return ShapeKind::box;
      }

      std::string
      name() const override
      {
        return "box";
      }

      double
      signed_distance(const Eigen::Vector3d &p,
                      Eigen::Vector3d       *normal = nullptr) const override;

      BoundingBox
      bounding_box() const override;

      double
      bounding_radius() const override
      {
        return h.norm();
      }

      double
      volume() const override;

      /** V (h_j^2 + h_k^2) / 3 on the diagonal. */
      Eigen::Matrix3d
      unit_inertia() const override;

      bool
      is_convex() const override
      {
        return true;
      }

      /** The corner in the octant of @p d. */
      Eigen::Vector3d
      support(const Eigen::Vector3d &d) const override;

      /** Corners, edge midpoints and face centres. */
      std::vector<Eigen::Vector3d>
      surface_points() const override;

      /** The display triangulation: twelve triangles of the six faces. */
      TriangleMesh
      surface_mesh() const override;

    private:
      Eigen::Vector3d h;
    };

  } // namespace geometry
} // namespace particulate

#endif
