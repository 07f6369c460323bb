#include <particulate/rigid/ellipsoid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace particulate::rigid {
  namespace {
    /**
     * Closest point on the ellipsoid with semi-axes @p e to the point @p y,
     * both in the body frame. Uses the parametrisation x_i = e_i^2 y_i /
     * (t + e_i^2) and finds the root t of sum (e_i y_i / (t + e_i^2))^2 = 1
     * in (-e_min^2, inf) by bisection (Eberly, "Distance from a point to an
     * ellipse, an ellipsoid, or a hyperellipsoid"). Coordinates that vanish
     * along the shortest axis are nudged off zero, which keeps the root
     * bracket valid at a cost of ~1e-12 relative accuracy.
     */
    Eigen::Vector3d
    closest_point(const Eigen::Vector3d &e, Eigen::Vector3d y)
    {
      const double emin = e.minCoeff();
      for (int i = 0; i < 3; ++i)
        if (std::abs(y[i]) < 1.e-12 * emin)
          y[i] = (y[i] >= 0. ? 1.e-12 : -1.e-12) * emin;
      auto f = [&](const double t) {
        double s = 0.;
        for (int i = 0; i < 3; ++i)
          {
            const double r = e[i] * y[i] / (t + e[i] * e[i]);
            s += r * r;
          }
        return s - 1.;
      };
      double lo = -emin * emin, hi = (e.cwiseProduct(y)).norm();
      hi = std::max(hi, 0.) + 1.e-300;
      while (f(hi) > 0.)
        hi *= 2.;
      for (int it = 0; it < 200; ++it)
        {
          const double mid = 0.5 * (lo + hi);
          if (mid == lo || mid == hi)
            break;
          (f(mid) > 0. ? lo : hi) = mid;
        }
      const double    t = 0.5 * (lo + hi);
      Eigen::Vector3d x;
      for (int i = 0; i < 3; ++i)
        x[i] = e[i] * e[i] * y[i] / (t + e[i] * e[i]);
      return x;
    }
  } // namespace

  Ellipsoid::Ellipsoid(const Eigen::Vector3d &a)
    : semi_axes(a)
  {
    if (!(a.minCoeff() > 0.) || !a.allFinite())
      throw std::invalid_argument(
        "rigid::Ellipsoid: all three semi-axes must be positive finite "
        "lengths in m.");
  }
  ShapeType
  Ellipsoid::type() const
  {
    return ShapeType::ellipsoid;
  }
  std::string
  Ellipsoid::name() const
  {
    return "ellipsoid";
  }
  double
  Ellipsoid::volume() const
  {
    return 4. / 3. * M_PI * semi_axes.prod();
  }
  Eigen::Vector3d
  Ellipsoid::unit_density_inertia() const
  {
    const Eigen::Vector3d s = semi_axes.cwiseAbs2();
    return volume() / 5.
           * Eigen::Vector3d(s[1] + s[2], s[0] + s[2], s[0] + s[1]);
  }
  double
  Ellipsoid::bounding_radius() const
  {
    return semi_axes.maxCoeff();
  }
  double
  Ellipsoid::signed_distance(const Eigen::Vector3d &p) const
  {
    const double level = p.cwiseQuotient(semi_axes).squaredNorm();
    const double d     = (p - closest_point(semi_axes, p)).norm();
    return level < 1. ? -d : d;
  }
  Eigen::Vector3d
  Ellipsoid::gradient(const Eigen::Vector3d &p) const
  {
    // The outward normal at the closest point is parallel to x / e^2, and
    // the gradient of the distance is constant along that normal line.
    const Eigen::Vector3d x = closest_point(semi_axes, p);
    return x.cwiseQuotient(semi_axes.cwiseAbs2()).normalized();
  }
  Eigen::Vector3d
  Ellipsoid::support(const Eigen::Vector3d &d) const
  {
    const Eigen::Vector3d ed = semi_axes.cwiseProduct(d);
    const double          n  = ed.norm();
    if (!(n > 0.))
      return Eigen::Vector3d(0., 0., semi_axes[2]);
    return semi_axes.cwiseProduct(ed) / n;
  }
  std::vector<Eigen::Vector3d>
  Ellipsoid::surface_points() const
  {
    std::vector<Eigen::Vector3d> pts;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int k = -1; k <= 1; ++k)
          if (i != 0 || j != 0 || k != 0)
            pts.push_back(
              semi_axes.cwiseProduct(Eigen::Vector3d(i, j, k).normalized()));
    return pts;
  }
} // namespace particulate::rigid
