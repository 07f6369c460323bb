#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/sphere.h>

#include <cmath>

#include "shape_formulas.h"

namespace particulate {
  namespace geometry {

    Sphere::Sphere(const double radius)
      : r(radius)
    {
      if (!(radius > 0.) || !std::isfinite(radius))
        throw GeometryError("Sphere: the radius must be a positive finite "
                            "length in m, got "
                            + std::to_string(radius) + ".");
    }



    double
    Sphere::signed_distance(const Eigen::Vector3d &p,
                            Eigen::Vector3d       *normal) const
    {
      const double d = p.norm();
      if (normal)
        *normal = d > 0. ? Eigen::Vector3d(p / d) : Eigen::Vector3d::UnitZ();
      return d - r;
    }



    bool
    Sphere::contains(const Eigen::Vector3d &p) const
    {
      return p.squaredNorm() <= r * r;
    }



    BoundingBox
    Sphere::bounding_box() const
    {
      return BoundingBox(Eigen::Vector3d::Constant(-r),
                         Eigen::Vector3d::Constant(r));
    }



    double
    Sphere::volume() const
    {
      return 4. / 3. * M_PI * r * r * r;
    }



    Eigen::Matrix3d
    Sphere::unit_inertia() const
    {
      return Eigen::Matrix3d::Identity() * (0.4 * volume() * r * r);
    }



    Eigen::Vector3d
    Sphere::support(const Eigen::Vector3d &d) const
    {
      const double n = d.norm();
      return n > 0. ? Eigen::Vector3d(r / n * d) : Eigen::Vector3d(0., 0., r);
    }



    std::vector<Eigen::Vector3d>
    Sphere::surface_points() const
    {
      std::vector<Eigen::Vector3d> points = detail::cube_neighbour_directions();
      for (auto &p : points)
        p = r * p.normalized();
      return points;
    }



    TriangleMesh
    Sphere::surface_mesh() const
    {
      return mesh_generators::icosphere(r, 2);
    }

  } // namespace geometry
} // namespace particulate
