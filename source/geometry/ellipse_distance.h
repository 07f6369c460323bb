#ifndef particulate_geometry_ellipse_distance_h
#define particulate_geometry_ellipse_distance_h

// The exact closest point on an ellipse, which the ellipsoid (on its
// principal planes) and the elliptic cylinder (its cross-section) share
// (private to the module).

#include <algorithm>
#include <cmath>

namespace particulate {
  namespace geometry {
    namespace detail {

      // Closest point on the ellipse by the method of D. Eberly ("Distance from
      // a point to an ellipse, an ellipsoid, or a hyperellipsoid", Geometric
      // Tools, 2013): with the query y in the first quadrant and semi-axes
      // e0 >= e1, the closest point is x_i = r_i y_i / (s + r_i) with
      // r_0 = (e0 / e1)^2, r_1 = 1 and s the unique root of
      // G(s) = sum (r_i z_i / (s + r_i))^2 - 1, z_i = y_i/e_i, on
      // [z_1 - 1, |r z| - 1]. G is strictly decreasing there, so bisection
      // until the interval stops shrinking gives the root to machine precision.

      /** The root s of G for r0 = (e0/e1)^2, z = (z0, z1) and g = |z|^2 - 1. */
      inline double
      root_2d(const double r0, const double z0, const double z1, const double g)
      {
        const double n0 = r0 * z0;
        double       s0 = z1 - 1., s1 = g < 0. ? 0. : std::hypot(n0, z1) - 1.;
        double       s = 0.;
        for (int i = 0; i < 2000; ++i)
          {
            s = 0.5 * (s0 + s1);
            if (s == s0 || s == s1)
              break;
            const double a = n0 / (s + r0), b = z1 / (s + 1.);
            const double v = a * a + b * b - 1.;
            if (v > 0.)
              s0 = s;
            else if (v < 0.)
              s1 = s;
            else
              break;
          }
        return s;
      }

      /** e0 >= e1 > 0, y0, y1 >= 0: closest point (x0, x1) on the ellipse
       *  (x0/e0)^2 + (x1/e1)^2 = 1 to (y0, y1), inside or outside. */
      inline void
      closest_on_ellipse(const double e0,
                         const double e1,
                         const double y0,
                         const double y1,
                         double      &x0,
                         double      &x1)
      {
        if (y1 > 0.)
          {
            if (y0 > 0.)
              {
                const double z0 = y0 / e0, z1 = y1 / e1;
                const double g = z0 * z0 + z1 * z1 - 1.;
                if (g != 0.)
                  {
                    const double r0 = (e0 / e1) * (e0 / e1);
                    const double s  = root_2d(r0, z0, z1, g);
                    x0              = r0 * y0 / (s + r0);
                    x1              = y1 / (s + 1.);
                  }
                else
                  {
                    x0 = y0;
                    x1 = y1;
                  }
              }
            else
              {
                x0 = 0.;
                x1 = e1;
              }
          }
        else
          {
            // On the major axis: inside, beyond the centre of curvature of the
            // vertex, the closest point leaves the axis.
            const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
            if (numer0 < denom0)
              {
                const double xde0 = numer0 / denom0;
                x0                = e0 * xde0;
                x1 = e1 * std::sqrt(std::max(0., 1. - xde0 * xde0));
              }
            else
              {
                x0 = e0;
                x1 = 0.;
              }
          }
      }

    } // namespace detail
  }   // namespace geometry
} // namespace particulate

#endif
