#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mapped_surface.h>

namespace particulate {
  namespace geometry {

    MappedSurface::MappedSurface(
      std::shared_ptr<const TriangulatedSurface> surface,
      std::shared_ptr<const DistanceMap>         map)
      : surface_(std::move(surface))
      , map_(std::move(map))
      , lookup(map_)
    {
      if (!surface_)
        throw GeometryError("MappedSurface: no surface given.");
      const BoundingBox box = surface_->bounding_box();
      if (!map_->grid_box().contains(box.lower)
          || !map_->grid_box().contains(box.upper))
        throw GeometryError("MappedSurface: the distance map does not cover "
                            "the surface; build it over the surface's "
                            "bounding box.");
    }

    double
    MappedSurface::signed_distance(const Eigen::Vector3d &p,
                                   Eigen::Vector3d       *normal) const
    {
      // Beyond the map the exact (slower) surface answers: the map would
      // give only a bound there, and a large partner's centre (a sphere's,
      // in the narrow phase) can lie that far out.
      if (!map_->covers(p))
        return surface_->signed_distance(p, normal);
      return lookup.signed_distance(p, normal);
    }

    void
    MappedSurface::signed_distances(const std::vector<Eigen::Vector3d> &points,
                                    std::vector<double>          &distances,
                                    std::vector<Eigen::Vector3d> *normals) const
    {
      lookup.signed_distances(points, distances, normals);
      for (std::size_t i = 0; i < points.size(); ++i)
        if (!map_->covers(points[i]))
          distances[i]
            = surface_->signed_distance(points[i],
                                        normals ? &(*normals)[i] : nullptr);
    }

    bool
    MappedSurface::contains(const Eigen::Vector3d &p) const
    {
      return lookup.contains(p);
    }

    void
    MappedSurface::contains_points(const Eigen::Vector3d *points,
                                   const std::size_t      count,
                                   bool                  *inside) const
    {
      lookup.contains_points(points, count, inside);
    }

    BoundingBox
    MappedSurface::bounding_box() const
    {
      return surface_->bounding_box();
    }

    double
    MappedSurface::volume() const
    {
      return surface_->volume();
    }

    Eigen::Vector3d
    MappedSurface::centroid() const
    {
      return surface_->centroid();
    }

    Eigen::Matrix3d
    MappedSurface::unit_inertia() const
    {
      return surface_->unit_inertia();
    }

    std::vector<Eigen::Vector3d>
    MappedSurface::surface_points() const
    {
      return surface_->surface_points();
    }

    TriangleMesh
    MappedSurface::surface_mesh() const
    {
      return surface_->surface_mesh();
    }

  } // namespace geometry
} // namespace particulate
