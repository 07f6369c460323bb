#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/shape.h>

#include <cmath>
#include <limits>

namespace particulate {
  namespace geometry {

    Eigen::Vector3d
    Shape::closest_point(const Eigen::Vector3d &p) const
    {
      Eigen::Vector3d n;
      const double    d = signed_distance(p, &n);
      return p - d * n;
    }



    bool
    Shape::contains(const Eigen::Vector3d &p) const
    {
      return signed_distance(p) <= 0.;
    }



    void
    Shape::contains_points(const Eigen::Vector3d *points,
                           const std::size_t      count,
                           bool                  *inside) const
    {
      for (std::size_t i = 0; i < count; ++i)
        inside[i] = contains(points[i]);
    }



    void
    Shape::signed_distances(const std::vector<Eigen::Vector3d> &points,
                            std::vector<double>                &distances,
                            std::vector<Eigen::Vector3d>       *normals) const
    {
      distances.resize(points.size());
      if (normals)
        normals->resize(points.size());
      for (std::size_t i = 0; i < points.size(); ++i)
        distances[i]
          = signed_distance(points[i], normals ? &(*normals)[i] : nullptr);
    }



    double
    Shape::bounding_radius() const
    {
      if (!is_bounded())
        return std::numeric_limits<double>::infinity();
      const BoundingBox box = bounding_box();
      return box.lower.cwiseAbs().cwiseMax(box.upper.cwiseAbs()).norm();
    }



    Eigen::Matrix3d
    Shape::unit_inertia() const
    {
      throw GeometryError("The shape '" + name()
                          + "' does not know its inertia, so it can only be a "
                            "fixed body; give a surface mesh or an analytic "
                            "shape for a body that moves.");
    }



    Eigen::Vector3d
    Shape::support(const Eigen::Vector3d &) const
    {
      throw GeometryError("The shape '" + name()
                          + "' is not convex and bounded, so it has no support "
                            "function; the narrow phase must use its signed "
                            "distance instead.");
    }



    TriangleMesh
    Shape::surface_mesh() const
    {
      if (!is_bounded())
        return {};
      // Start from the sphere inscribed in the bounding box about the centroid
      // (inside the region where a distance map answers) and step each vertex
      // along the normal by its distance until it sits on the surface.
      const BoundingBox     box = bounding_box();
      const Eigen::Vector3d c   = centroid();
      const double radius = (box.upper - c).cwiseMin(c - box.lower).minCoeff();
      const double tolerance = 1e-12 * bounding_radius();
      TriangleMesh mesh      = mesh_generators::icosphere(radius, 3);
      for (auto &v : mesh.vertices)
        {
          v += c;
          for (int step = 0; step < 16; ++step)
            {
              Eigen::Vector3d normal;
              const double    d = signed_distance(v, &normal);
              v -= d * normal;
              if (std::abs(d) <= tolerance)
                break;
            }
        }
      return mesh;
    }

  } // namespace geometry
} // namespace particulate
