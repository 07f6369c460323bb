#include <particulate/geometry/elliptic_cylinder.h>
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_generators.h>

#include <cmath>

#include "ellipse_distance.h"
#include "shape_formulas.h"

namespace particulate {
  namespace geometry {

    EllipticCylinder::EllipticCylinder(const double semi_axis_x,
                                       const double semi_axis_y,
                                       const double half_height)
      : a(semi_axis_x)
      , b(semi_axis_y)
      , hh(half_height)
    {
      if (!(semi_axis_x > 0.) || !(semi_axis_y > 0.) || !(half_height > 0.)
          || !std::isfinite(semi_axis_x) || !std::isfinite(semi_axis_y)
          || !std::isfinite(half_height))
        throw GeometryError("EllipticCylinder: both semi-axes and the half "
                            "height must be positive finite lengths in m.");
    }

    double
    EllipticCylinder::signed_distance(const Eigen::Vector3d &p,
                                      Eigen::Vector3d       *normal) const
    {
      // The exact signed distance dr of (x, y) to the ellipse, then, as for
      // the circular cylinder, the 2D box distance in the (dr, |z|) half-plane
      // with the caps: this is exact because the closest point of the solid
      // lies on the side, on a cap or on the rim over the closest point of the
      // ellipse. Eberly's routine wants e0 >= e1 and the first quadrant.
      const bool   swap = b > a;
      const double e0 = swap ? b : a, e1 = swap ? a : b;
      const double y0 = std::abs(p[swap ? 1 : 0]),
                   y1 = std::abs(p[swap ? 0 : 1]);
      double x0, x1;
      detail::closest_on_ellipse(e0, e1, y0, y1, x0, x1);
      const double cx = std::copysign(swap ? x1 : x0, p[0]);
      const double cy = std::copysign(swap ? x0 : x1, p[1]);

      const double qx = p[0] / a, qy = p[1] / b;
      const double level = qx * qx + qy * qy - 1.;
      const double d2    = std::hypot(p[0] - cx, p[1] - cy);
      const double dr    = level > 0. ? d2 : -d2;
      const double dz    = std::abs(p[2]) - hh;

      // Outward normal of the ellipse at the closest point (the gradient of
      // the implicit function, parallel to (x, y) - closest).
      Eigen::Vector3d radial(cx / (a * a), cy / (b * b), 0.);
      radial.normalize();
      const Eigen::Vector3d axial(0., 0., p[2] < 0. ? -1. : 1.);
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

    bool
    EllipticCylinder::contains(const Eigen::Vector3d &p) const
    {
      const double qx = p[0] / a, qy = p[1] / b;
      return qx * qx + qy * qy <= 1. && std::abs(p[2]) <= hh;
    }

    BoundingBox
    EllipticCylinder::bounding_box() const
    {
      return BoundingBox(Eigen::Vector3d(-a, -b, -hh),
                         Eigen::Vector3d(a, b, hh));
    }

    double
    EllipticCylinder::volume() const
    {
      return 2. * M_PI * a * b * hh;
    }



    Eigen::Matrix3d
    EllipticCylinder::unit_inertia() const
    {
      // Per unit area the ellipse has second moments a^2 / 4 (x) and b^2 / 4
      // (y); the axial one of the prism is L^2 / 12.
      const double V = volume(), L = 2. * hh;
      const double axial = L * L / 12.;
      return Eigen::Vector3d(V * (b * b / 4. + axial),
                             V * (a * a / 4. + axial),
                             V * (a * a + b * b) / 4.)
        .asDiagonal();
    }



    Eigen::Vector3d
    EllipticCylinder::support(const Eigen::Vector3d &d) const
    {
      // Over the ellipse (a cos t, b sin t), d . x is largest at
      // (cos t, sin t) = (a d_x, b d_y) / |(a d_x, b d_y)|.
      const double    ax = a * d[0], by = b * d[1];
      const double    n = std::hypot(ax, by);
      Eigen::Vector3d s(0., 0., d[2] >= 0. ? hh : -hh);
      if (n > 0.)
        {
          s[0] = a * ax / n;
          s[1] = b * by / n;
        }
      return s;
    }



    std::vector<Eigen::Vector3d>
    EllipticCylinder::surface_points() const
    {
      return detail::elliptic_prism_surface_points(a, b, hh);
    }



    TriangleMesh
    EllipticCylinder::surface_mesh() const
    {
      return mesh_generators::elliptic_prism(a, b, hh, 48);
    }

  } // namespace geometry
} // namespace particulate
