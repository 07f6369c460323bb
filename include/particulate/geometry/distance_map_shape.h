#ifndef particulate_geometry_distance_map_shape_h
#define particulate_geometry_distance_map_shape_h

#include <particulate/geometry/distance_map.h>
#include <particulate/geometry/shape.h>

#include <memory>

namespace particulate {
  namespace geometry {

    /**
     * A shape answered by its distance map (thesis §3.4.2, §5.4.3): distance,
     * normal and inside test are O(1) trilinear lookups instead of tree
     * searches, at the accuracy of the map. This is the CPU twin of what the
     * CUDA kernels do with DistanceMapData. Outside the map's grid box every
     * point is outside.
     */
    class DistanceMapShape : public Shape
    {
    public:
      /** @param map a built distance map (shared, not copied) */
      explicit DistanceMapShape(std::shared_ptr<const DistanceMap> map);

      std::string
      name() const override
      {
        return "distance map";
      }

      double
      signed_distance(const Eigen::Vector3d &p,
                      Eigen::Vector3d       *normal = nullptr) const override;

      /** Many points at once through DistanceMap::distances(), which
       *  overlaps their memory accesses. */
      void
      signed_distances(const std::vector<Eigen::Vector3d> &points,
                       std::vector<double>                &distances,
                       std::vector<Eigen::Vector3d>       *normals
                       = nullptr) const override;

      /** Trilinear distance <= 0 inside the grid box; false outside it. */
      bool
      contains(const Eigen::Vector3d &p) const override;

      /** The same answers as contains() per point, the distances in groups
       *  through DistanceMap::distances(). */
      void
      contains_points(const Eigen::Vector3d *points,
                      std::size_t            count,
                      bool                  *inside) const override;

      /** The map's grid box. */
      BoundingBox
      bounding_box() const override;

      /** Volume estimated from the map: grid points with negative distance
       *  times h^3 [m^3] (first order in h). */
      double
      volume() const override;

      /** The map. */
      const DistanceMap &
      map() const
      {
        return *dmap;
      }

    private:
      std::shared_ptr<const DistanceMap> dmap;
    };

  } // namespace geometry
} // namespace particulate

#endif
