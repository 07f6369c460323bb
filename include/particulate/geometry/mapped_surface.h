#ifndef particulate_geometry_mapped_surface_h
#define particulate_geometry_mapped_surface_h

#include <particulate/geometry/distance_map.h>
#include <particulate/geometry/distance_map_shape.h>
#include <particulate/geometry/triangulated_surface.h>

#include <memory>

namespace particulate {
  namespace geometry {

    /**
     * A body of any shape as the coupled solver uses it (thesis §3.4.2,
     * §5.4): a closed surface mesh for what must be exact, and the mesh's
     * distance map for every query that runs per point and per step.
     *
     * - Exact, from the polyhedron: volume, centroid, inertia, the bounding
     *   box, the vertices the narrow phase tests against a partner, and the
     *   triangulation written for ParaView.
     * - Through the map (O(1) trilinear lookups): signed distance, normal,
     *   closest point and containment, so that contacts, the fictitious
     *   boundary's node marking, its forces and the mesh deformation all see
     *   the same surface. Beyond the map's grid box (its margin around the
     *   body) the distance is the exact surface's and every point is
     *   outside.
     *
     * Both are given in the same body frame; a dynamic body needs it to be
     * the principal frame (see load_mesh_body()).
     */
    class MappedSurface : public Shape
    {
    public:
      /**
       * @param surface the exact surface in the body frame
       * @param map the distance map of that surface, covering its bounding
       *   box with a margin
       * @throw GeometryError if either is missing or the map does not cover
       *   the surface's bounding box
       */
      MappedSurface(std::shared_ptr<const TriangulatedSurface> surface,
                    std::shared_ptr<const DistanceMap>         map);

      std::string
      name() const override
      {
        return "surface mesh";
      }

      /** The map's interpolated distance and normal within its grid box;
       *  the exact surface's beyond it. */
      double
      signed_distance(const Eigen::Vector3d &p,
                      Eigen::Vector3d       *normal = nullptr) const override;

      void
      signed_distances(const std::vector<Eigen::Vector3d> &points,
                       std::vector<double>                &distances,
                       std::vector<Eigen::Vector3d>       *normals
                       = nullptr) const override;

      /** The map's inside test (distance <= 0 within its grid box). */
      bool
      contains(const Eigen::Vector3d &p) const override;

      void
      contains_points(const Eigen::Vector3d *points,
                      std::size_t            count,
                      bool                  *inside) const override;

      /** The surface's own box (tighter than the map's grid box). */
      BoundingBox
      bounding_box() const override;

      double
      volume() const override;

      Eigen::Vector3d
      centroid() const override;

      Eigen::Matrix3d
      unit_inertia() const override;

      /** The mesh vertices. */
      std::vector<Eigen::Vector3d>
      surface_points() const override;

      /** The surface mesh itself. */
      TriangleMesh
      surface_mesh() const override;

      /** The exact surface. */
      const TriangulatedSurface &
      surface() const
      {
        return *surface_;
      }

      /** The distance map. */
      const DistanceMap &
      map() const
      {
        return lookup.map();
      }

      /** The distance map, shared (e.g. to upload it once). */
      const std::shared_ptr<const DistanceMap> &
      shared_map() const
      {
        return map_;
      }

    private:
      std::shared_ptr<const TriangulatedSurface> surface_;
      std::shared_ptr<const DistanceMap>         map_;
      DistanceMapShape                           lookup;
    };

  } // namespace geometry
} // namespace particulate

#endif
