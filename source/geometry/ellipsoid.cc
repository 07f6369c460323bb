#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_generators.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "ellipse_distance.h"
#include "shape_formulas.h"

namespace particulate {
  namespace geometry {

    namespace {
      using detail::closest_on_ellipse;

      // Closest point on the ellipsoid by the method of D. Eberly: with
      // the query y in the first octant and semi-axes sorted e0 >= e1 (>= e2),
      // the closest point is x_i = r_i y_i / (s + r_i) with
      // r_i = (e_i / e_min)^2 and s the unique root of
      // G(s) = sum (r_i z_i / (s + r_i))^2 - 1, z_i = y_i/e_i, on
      // [z_min - 1, |r z| - 1]. G is strictly decreasing there, so bisection
      // until the interval stops shrinking gives the root to machine
      // precision. Points on coordinate planes are reduced to the
      // lower-dimensional problem, the ellipse (ellipse_distance.h).

      double
      root_3d(const double r0,
              const double r1,
              const double z0,
              const double z1,
              const double z2,
              const double g)
      {
        const double n0 = r0 * z0, n1 = r1 * z1;
        double       s0 = z2 - 1.;
        double s1 = g < 0. ? 0. : std::sqrt(n0 * n0 + n1 * n1 + z2 * z2) - 1.;
        double s  = 0.;
        for (int i = 0; i < 2000; ++i)
          {
            s = 0.5 * (s0 + s1);
            if (s == s0 || s == s1)
              break;
            const double a = n0 / (s + r0), b = n1 / (s + r1),
                         c = z2 / (s + 1.);
            const double v = a * a + b * b + c * c - 1.;
            if (v > 0.)
              s0 = s;
            else if (v < 0.)
              s1 = s;
            else
              break;
          }
        return s;
      }

      // e0 >= e1 >= e2 > 0, y >= 0 componentwise: closest point x on the
      // ellipsoid.
      void
      closest_on_ellipsoid(const std::array<double, 3> &e,
                           const std::array<double, 3> &y,
                           std::array<double, 3>       &x)
      {
        if (y[2] > 0.)
          {
            if (y[1] > 0.)
              {
                if (y[0] > 0.)
                  {
                    const double z0 = y[0] / e[0], z1 = y[1] / e[1],
                                 z2 = y[2] / e[2];
                    const double g  = z0 * z0 + z1 * z1 + z2 * z2 - 1.;
                    if (g != 0.)
                      {
                        const double r0 = (e[0] / e[2]) * (e[0] / e[2]);
                        const double r1 = (e[1] / e[2]) * (e[1] / e[2]);
                        const double s  = root_3d(r0, r1, z0, z1, z2, g);
                        x[0]            = r0 * y[0] / (s + r0);
                        x[1]            = r1 * y[1] / (s + r1);
                        x[2]            = y[2] / (s + 1.);
                      }
                    else
                      x = y;
                  }
                else
                  {
                    x[0] = 0.;
                    closest_on_ellipse(e[1], e[2], y[1], y[2], x[1], x[2]);
                  }
              }
            else
              {
                x[1] = 0.;
                if (y[0] > 0.)
                  closest_on_ellipse(e[0], e[2], y[0], y[2], x[0], x[2]);
                else
                  {
                    x[0] = 0.;
                    x[2] = e[2];
                  }
              }
          }
        else
          {
            // On the plane z = 0: the closest point may leave the plane (inside
            // points near the flat middle), else it is on the equatorial
            // ellipse.
            const double denom0 = e[0] * e[0] - e[2] * e[2],
                         denom1 = e[1] * e[1] - e[2] * e[2];
            const double numer0 = e[0] * y[0], numer1 = e[1] * y[1];
            if (numer0 < denom0 && numer1 < denom1)
              {
                const double xde0 = numer0 / denom0, xde1 = numer1 / denom1;
                const double discr = 1. - xde0 * xde0 - xde1 * xde1;
                if (discr > 0.)
                  {
                    x[0] = e[0] * xde0;
                    x[1] = e[1] * xde1;
                    x[2] = e[2] * std::sqrt(discr);
                    return;
                  }
              }
            x[2] = 0.;
            closest_on_ellipse(e[0], e[1], y[0], y[1], x[0], x[1]);
          }
      }
    } // namespace

    Ellipsoid::Ellipsoid(const Eigen::Vector3d &semi_axes)
      : e(semi_axes)
    {
      if (!(semi_axes.array() > 0.).all() || !semi_axes.allFinite())
        throw GeometryError(
          "Ellipsoid: all three semi-axes must be positive finite lengths in "
          "m.");
    }

    double
    Ellipsoid::signed_distance(const Eigen::Vector3d &p,
                               Eigen::Vector3d       *normal) const
    {
      // Sort the axes decreasingly, fold p into the first octant.
      std::array<int, 3> order = {0, 1, 2};
      std::sort(order.begin(), order.end(), [&](int a, int b) {
        return e[a] > e[b];
      });
      std::array<double, 3> es, ys, xs;
      for (int i = 0; i < 3; ++i)
        {
          es[i] = e[order[i]];
          ys[i] = std::abs(p[order[i]]);
        }
      closest_on_ellipsoid(es, ys, xs);

      Eigen::Vector3d closest;
      for (int i = 0; i < 3; ++i)
        closest[order[i]] = std::copysign(xs[i], p[order[i]]);
      const double level = (p.cwiseQuotient(e)).squaredNorm() - 1.;
      const double d     = (p - closest).norm();
      if (normal)
        {
          // The outward normal of the ellipsoid at the closest point: the
          // gradient of the implicit function, parallel to p - closest.
          const Eigen::Vector3d g = closest.cwiseQuotient(e.cwiseProduct(e));
          *normal = g.norm() > 0. ? Eigen::Vector3d(g.normalized()) :
                                    Eigen::Vector3d::UnitX();
        }
      return level > 0. ? d : -d;
    }

    bool
    Ellipsoid::contains(const Eigen::Vector3d &p) const
    {
      return p.cwiseQuotient(e).squaredNorm() <= 1.;
    }

    BoundingBox
    Ellipsoid::bounding_box() const
    {
      return BoundingBox(-e, e);
    }

    double
    Ellipsoid::volume() const
    {
      return 4. / 3. * M_PI * e.prod();
    }



    Eigen::Matrix3d
    Ellipsoid::unit_inertia() const
    {
      return detail::axis_aligned_inertia(5., volume(), e);
    }



    Eigen::Vector3d
    Ellipsoid::support(const Eigen::Vector3d &d) const
    {
      const Eigen::Vector3d ed = e.cwiseProduct(d);
      const double          n  = ed.norm();
      if (!(n > 0.))
        return Eigen::Vector3d(0., 0., e[2]);
      return e.cwiseProduct(ed) / n;
    }



    std::vector<Eigen::Vector3d>
    Ellipsoid::surface_points() const
    {
      std::vector<Eigen::Vector3d> points = detail::cube_neighbour_directions();
      for (auto &p : points)
        p = e.cwiseProduct(p.normalized());
      return points;
    }



    TriangleMesh
    Ellipsoid::surface_mesh() const
    {
      TriangleMesh mesh = mesh_generators::icosphere(1., 3);
      for (auto &v : mesh.vertices)
        v = v.cwiseProduct(e);
      return mesh;
    }

  } // namespace geometry
} // namespace particulate
