#include <particulate/geometry/capsule.h>
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_generators.h>

#include <algorithm>
#include <cmath>

namespace particulate {
  namespace geometry {

    Capsule::Capsule(const double radius, const double half_length)
      : r(radius)
      , hl(half_length)
    {
      if (!(radius > 0.) || !(half_length >= 0.) || !std::isfinite(radius)
          || !std::isfinite(half_length))
        throw GeometryError(
          "Capsule: the radius must be a positive and the half length of the "
          "core segment a non-negative finite length in m.");
    }



    double
    Capsule::signed_distance(const Eigen::Vector3d &p,
                             Eigen::Vector3d       *normal) const
    {
      const Eigen::Vector3d core(0., 0., std::clamp(p[2], -hl, hl));
      const Eigen::Vector3d d = p - core;
      const double          n = d.norm();
      if (normal)
        *normal = n > 0. ? Eigen::Vector3d(d / n) : Eigen::Vector3d::UnitX();
      return n - r;
    }



    BoundingBox
    Capsule::bounding_box() const
    {
      return BoundingBox(Eigen::Vector3d(-r, -r, -hl - r),
                         Eigen::Vector3d(r, r, hl + r));
    }



    double
    Capsule::volume() const
    {
      return M_PI * r * r * (2. * hl + 4. / 3. * r);
    }



    Eigen::Matrix3d
    Capsule::unit_inertia() const
    {
      const double L        = 2. * hl;
      const double cylinder = M_PI * r * r * L,
                   ball     = 4. / 3. * M_PI * r * r * r;
      const double axial    = cylinder * r * r / 2. + ball * 0.4 * r * r;
      const double transverse
        = cylinder * (L * L / 12. + r * r / 4.)
          + ball * (0.4 * r * r + L * L / 4. + 3. * L * r / 8.);
      return Eigen::Vector3d(transverse, transverse, axial).asDiagonal();
    }



    Eigen::Vector3d
    Capsule::support(const Eigen::Vector3d &d) const
    {
      const double    n = d.norm();
      Eigen::Vector3d s(0., 0., d[2] >= 0. ? hl : -hl);
      if (n > 0.)
        s += r / n * d;
      return s;
    }



    std::vector<Eigen::Vector3d>
    Capsule::surface_points() const
    {
      std::vector<Eigen::Vector3d> points;
      for (int k = 0; k < 12; ++k)
        {
          const double a = 2. * M_PI * k / 12.;
          for (const double z : {-hl, 0., hl})
            points.emplace_back(r * std::cos(a), r * std::sin(a), z);
        }
      points.emplace_back(0., 0., hl + r);
      points.emplace_back(0., 0., -hl - r);
      return points;
    }



    TriangleMesh
    Capsule::surface_mesh() const
    {
      return mesh_generators::capsule(r, hl, 32);
    }

  } // namespace geometry
} // namespace particulate
