#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_generators.h>

#include <cmath>

#include "shape_formulas.h"

namespace particulate {
  namespace geometry {

    Cylinder::Cylinder(const double radius, const double half_height)
      : r(radius)
      , hh(half_height)
    {
      if (!(radius > 0.) || !(half_height > 0.) || !std::isfinite(radius)
          || !std::isfinite(half_height))
        throw GeometryError(
          "Cylinder: radius and half height must be positive and finite.");
    }

    double
    Cylinder::signed_distance(const Eigen::Vector3d &p,
                              Eigen::Vector3d       *normal) const
    {
      // In the (rho, |z|) half-plane the cylinder is the rectangle
      // [0, r] x [0, hh]; its signed distance is the 2D box distance.
      const double          rho = std::hypot(p[0], p[1]);
      const Eigen::Vector3d radial
        = rho > 0. ? Eigen::Vector3d(p[0] / rho, p[1] / rho, 0.) :
                     Eigen::Vector3d::UnitX();
      const Eigen::Vector3d axial(0., 0., p[2] < 0. ? -1. : 1.);
      const double          dr = rho - r, dz = std::abs(p[2]) - hh;
      if (dr > 0. && dz > 0.)
        {
          const double d = std::hypot(dr, dz);
          if (normal)
            *normal = (dr * radial + dz * axial) / d;
          return d;
        }
      if (normal)
        *normal = dr > dz ? radial : axial;
      return std::max(dr, dz);
    }

    BoundingBox
    Cylinder::bounding_box() const
    {
      return BoundingBox(Eigen::Vector3d(-r, -r, -hh),
                         Eigen::Vector3d(r, r, hh));
    }

    double
    Cylinder::volume() const
    {
      return 2. * M_PI * r * r * hh;
    }



    Eigen::Matrix3d
    Cylinder::unit_inertia() const
    {
      const double V = volume(), L = 2. * hh;
      const double transverse = V * (3. * r * r + L * L) / 12.;
      return Eigen::Vector3d(transverse, transverse, 0.5 * V * r * r)
        .asDiagonal();
    }



    Eigen::Vector3d
    Cylinder::support(const Eigen::Vector3d &d) const
    {
      const double    rho = std::hypot(d[0], d[1]);
      Eigen::Vector3d s(0., 0., d[2] >= 0. ? hh : -hh);
      if (rho > 0.)
        {
          s[0] = r * d[0] / rho;
          s[1] = r * d[1] / rho;
        }
      return s;
    }



    std::vector<Eigen::Vector3d>
    Cylinder::surface_points() const
    {
      return detail::elliptic_prism_surface_points(r, r, hh);
    }



    TriangleMesh
    Cylinder::surface_mesh() const
    {
      return mesh_generators::elliptic_prism(r, r, hh, 48);
    }

  } // namespace geometry
} // namespace particulate
