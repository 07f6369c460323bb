#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/tube.h>

#include <algorithm>
#include <cmath>

namespace particulate {
  namespace geometry {

    Tube::Tube(const double inner_radius,
               const double wall_thickness,
               const double half_length)
      : ri(inner_radius)
      , w(wall_thickness)
      , hh(half_length)
    {
      if (!(inner_radius > 0.) || !(wall_thickness > 0.) || !(half_length > 0.)
          || !std::isfinite(inner_radius + wall_thickness + half_length))
        throw GeometryError("Tube: need a bore radius, a wall thickness and a "
                            "half length that are positive and finite.");
    }



    double
    Tube::signed_distance(const Eigen::Vector3d &p,
                          Eigen::Vector3d       *normal) const
    {
      const double          rho = std::hypot(p[0], p[1]);
      const Eigen::Vector3d radial
        = rho > 0. ? Eigen::Vector3d(p[0] / rho, p[1] / rho, 0.) :
                     Eigen::Vector3d::UnitX();
      // The wall's cross-section is the rectangle centred at (r_i + w/2, 0)
      // with half sides (w/2, h) in the (rho, z) half-plane.
      const double q_rho = rho - (ri + 0.5 * w), q_z = p[2];
      const double d_rho = std::abs(q_rho) - 0.5 * w, d_z = std::abs(q_z) - hh;
      const double s_rho = q_rho < 0. ? -1. : 1., s_z = q_z < 0. ? -1. : 1.;
      if (d_rho > 0. || d_z > 0.)
        {
          const double o_rho = std::max(d_rho, 0.), o_z = std::max(d_z, 0.);
          const double d = std::hypot(o_rho, o_z);
          if (normal)
            *normal
              = (s_rho * o_rho * radial + Eigen::Vector3d(0., 0., s_z * o_z))
                / d;
          return d;
        }
      if (normal)
        *normal = d_rho > d_z ? Eigen::Vector3d(s_rho * radial) :
                                Eigen::Vector3d(0., 0., s_z);
      return std::max(d_rho, d_z);
    }



    BoundingBox
    Tube::bounding_box() const
    {
      const double ro = ri + w;
      return BoundingBox(Eigen::Vector3d(-ro, -ro, -hh),
                         Eigen::Vector3d(ro, ro, hh));
    }



    double
    Tube::bounding_radius() const
    {
      return std::hypot(ri + w, hh);
    }



    double
    Tube::volume() const
    {
      const double ro = ri + w;
      return M_PI * (ro * ro - ri * ri) * 2. * hh;
    }



    Eigen::Matrix3d
    Tube::unit_inertia() const
    {
      const double V = volume(), ro = ri + w, radii = ri * ri + ro * ro;
      const double transverse = V * (3. * radii + 4. * hh * hh) / 12.;
      return Eigen::Vector3d(transverse, transverse, 0.5 * V * radii)
        .asDiagonal();
    }



    TriangleMesh
    Tube::surface_mesh() const
    {
      // Four rings of n vertices: bore bottom, bore top, outer top, outer
      // bottom; consecutive rings joined by quadrilaterals facing out of the
      // wall (into the bore, up, outwards, down).
      const int                    n  = 64;
      const double                 ro = ri + w;
      std::vector<Eigen::Vector3d> vertices;
      for (const auto &[radius, z] : {std::pair{ri, -hh},
                                      std::pair{ri, hh},
                                      std::pair{ro, hh},
                                      std::pair{ro, -hh}})
        for (int k = 0; k < n; ++k)
          {
            const double a = 2. * M_PI * k / n;
            vertices.emplace_back(radius * std::cos(a),
                                  radius * std::sin(a),
                                  z);
          }
      std::vector<std::array<int, 3>> triangles;
      for (int ring = 0; ring < 4; ++ring)
        {
          const int next = (ring + 1) % 4;
          for (int k = 0; k < n; ++k)
            {
              const int k1 = (k + 1) % n;
              const int a = ring * n + k, b = ring * n + k1;
              const int c = next * n + k1, d = next * n + k;
              triangles.push_back({a, d, c});
              triangles.push_back({a, c, b});
            }
        }
      return TriangleMesh(std::move(vertices), std::move(triangles));
    }

  } // namespace geometry
} // namespace particulate
