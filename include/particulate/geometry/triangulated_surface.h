#ifndef particulate_geometry_triangulated_surface_h
#define particulate_geometry_triangulated_surface_h

#include <particulate/geometry/shape.h>
#include <particulate/geometry/triangle_mesh.h>

#include <memory>

namespace particulate {
  namespace geometry {

    /**
     * A solid bounded by a closed triangulated surface (thesis §3.4: complex
     * shapes as surface triangulations), with distances from CGAL's AABB tree.
     *
     * - signed_distance(): the unsigned distance is CGAL's closest-point query;
     *   the sign comes from the angle-weighted pseudo-normal of the closest
     *   feature (face, edge or vertex; Bærentzen and Aanæs, IEEE TVCG 11,
     *   2005), which is exact for closed, consistently oriented, manifold
     *   surfaces and costs no more than the distance itself.
     * - contains(): CGAL's Side_of_triangle_mesh (ray parity with exact
     *   predicates and re-shooting on degenerate hits), the robust reference.
     *
     * The mesh must bound a solid (see read_surface_mesh / check_surface_mesh):
     * the constructor checks closedness, manifoldness and orientation (not
     * self-intersections, which read_surface_mesh does) and throws otherwise.
     */
    class TriangulatedSurface : public Shape
    {
    public:
      /**
       * @param mesh closed, outward-oriented surface in the body frame [m]
       * @throw GeometryError if the mesh does not bound a solid
       */
      explicit TriangulatedSurface(const TriangleMesh &mesh);
      ~TriangulatedSurface() override;

      std::string
      name() const override
      {
        return "surface mesh";
      }
      TriangulatedSurface(TriangulatedSurface &&) noexcept;
      TriangulatedSurface &
      operator=(TriangulatedSurface &&) noexcept;

      double
      signed_distance(const Eigen::Vector3d &p,
                      Eigen::Vector3d       *normal = nullptr) const override;

      /** Uses each point's closest point as the AABB-tree search hint for the
       *  next one. */
      void
      signed_distances(const std::vector<Eigen::Vector3d> &points,
                       std::vector<double>                &distances,
                       std::vector<Eigen::Vector3d>       *normals
                       = nullptr) const override;

      /** Exact side-of-mesh test (CGAL::Side_of_triangle_mesh); points on the
       *  surface count as inside. */
      bool
      contains(const Eigen::Vector3d &p) const override;

      /** The unsigned distance alone (CGAL closest-point query) [m]. */
      double
      unsigned_distance(const Eigen::Vector3d &p) const;

      /** CGAL's closest point on the surface to @p p [m]. */
      Eigen::Vector3d
      closest_point(const Eigen::Vector3d &p) const override;

      BoundingBox
      bounding_box() const override;

      /** Enclosed volume by the divergence theorem [m^3]. */
      double
      volume() const override;

      /** Exact centroid of the polyhedron (compute_mass_properties) [m]. */
      Eigen::Vector3d
      centroid() const override;

      /** Exact inertia of the polyhedron for unit density about its centroid,
       *  in the mesh's frame [m^5]. */
      Eigen::Matrix3d
      unit_inertia() const override;

      /** The mesh vertices. */
      std::vector<Eigen::Vector3d>
      surface_points() const override;

      /** The display triangulation: the surface mesh itself. */
      TriangleMesh
      surface_mesh() const override;

      /** The surface this shape was built from. */
      const TriangleMesh &
      mesh() const;

    private:
      struct Impl;
      std::unique_ptr<Impl> impl;
    };

  } // namespace geometry
} // namespace particulate

#endif
