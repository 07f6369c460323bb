#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/torus.h>

#include <cmath>

namespace particulate {
  namespace geometry {

    Torus::Torus(const double major_radius, const double minor_radius)
      : R(major_radius)
      , r(minor_radius)
    {
      if (!(minor_radius > 0.) || !(major_radius > minor_radius)
          || !std::isfinite(major_radius))
        throw GeometryError(
          "Torus: need 0 < minor radius < major radius (a ring torus).");
    }

    double
    Torus::signed_distance(const Eigen::Vector3d &p,
                           Eigen::Vector3d       *normal) const
    {
      const double          rho = std::hypot(p[0], p[1]);
      const Eigen::Vector3d radial
        = rho > 0. ? Eigen::Vector3d(p[0] / rho, p[1] / rho, 0.) :
                     Eigen::Vector3d::UnitX();
      // Offset from the nearest point of the tube's centre circle.
      const Eigen::Vector3d q
        = (rho - R) * radial + Eigen::Vector3d(0., 0., p[2]);
      const double d = q.norm();
      if (normal)
        *normal = d > 0. ? Eigen::Vector3d(q / d) : radial;
      return d - r;
    }

    BoundingBox
    Torus::bounding_box() const
    {
      return BoundingBox(Eigen::Vector3d(-R - r, -R - r, -r),
                         Eigen::Vector3d(R + r, R + r, r));
    }

    double
    Torus::volume() const
    {
      return 2. * M_PI * M_PI * R * r * r;
    }



    Eigen::Matrix3d
    Torus::unit_inertia() const
    {
      const double V          = volume();
      const double transverse = V * (R * R / 2. + 5. / 8. * r * r);
      return Eigen::Vector3d(transverse, transverse, V * (R * R + 0.75 * r * r))
        .asDiagonal();
    }



    std::vector<Eigen::Vector3d>
    Torus::surface_points() const
    {
      std::vector<Eigen::Vector3d> points;
      for (int i = 0; i < 36; ++i)
        for (int j = 0; j < 12; ++j)
          {
            const double u = 2. * M_PI * i / 36., v = 2. * M_PI * j / 12.;
            points.emplace_back((R + r * std::cos(v)) * std::cos(u),
                                (R + r * std::cos(v)) * std::sin(u),
                                r * std::sin(v));
          }
      return points;
    }



    TriangleMesh
    Torus::surface_mesh() const
    {
      return mesh_generators::torus(R, r, 48, 24);
    }

  } // namespace geometry
} // namespace particulate
