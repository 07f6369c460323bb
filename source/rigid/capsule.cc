#include <particulate/rigid/capsule.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace particulate::rigid {
  Capsule::Capsule(const double r, const double h)
    : radius(r)
    , half_length(h)
  {
    if (!(r > 0.) || !(h >= 0.) || !std::isfinite(r) || !std::isfinite(h))
      throw std::invalid_argument(
        "rigid::Capsule: the radius must be positive and the half length of "
        "the core segment non-negative (m).");
  }
  ShapeType
  Capsule::type() const
  {
    return ShapeType::capsule;
  }
  std::string
  Capsule::name() const
  {
    return "capsule";
  }
  double
  Capsule::volume() const
  {
    return M_PI * radius * radius * (2. * half_length + 4. / 3. * radius);
  }
  Eigen::Vector3d
  Capsule::unit_density_inertia() const
  {
    // Cylinder of length L plus two hemispheres whose centroids sit 3r/8
    // beyond the cylinder ends (parallel-axis theorem).
    const double r = radius, L = 2. * half_length;
    const double mc = M_PI * r * r * L, ms = 4. / 3. * M_PI * r * r * r;
    const double iz = mc * r * r / 2. + ms * 0.4 * r * r;
    const double ix = mc * (L * L / 12. + r * r / 4.)
                      + ms * (0.4 * r * r + L * L / 4. + 3. * L * r / 8.);
    return Eigen::Vector3d(ix, ix, iz);
  }
  double
  Capsule::bounding_radius() const
  {
    return half_length + radius;
  }
  double
  Capsule::signed_distance(const Eigen::Vector3d &p) const
  {
    const Eigen::Vector3d c(0.,
                            0.,
                            std::clamp(p[2], -half_length, half_length));
    return (p - c).norm() - radius;
  }
  Eigen::Vector3d
  Capsule::gradient(const Eigen::Vector3d &p) const
  {
    const Eigen::Vector3d c(0.,
                            0.,
                            std::clamp(p[2], -half_length, half_length));
    const Eigen::Vector3d d = p - c;
    const double          n = d.norm();
    return n > 0. ? Eigen::Vector3d(d / n) : Eigen::Vector3d::UnitX();
  }
  Eigen::Vector3d
  Capsule::support(const Eigen::Vector3d &d) const
  {
    const double    n = d.norm();
    Eigen::Vector3d s(0., 0., d[2] >= 0. ? half_length : -half_length);
    if (n > 0.)
      s += radius / n * d;
    return s;
  }
  std::vector<Eigen::Vector3d>
  Capsule::surface_points() const
  {
    std::vector<Eigen::Vector3d> pts;
    for (int k = 0; k < 12; ++k)
      {
        const double a = 2. * M_PI * k / 12.;
        for (double z : {-half_length, 0., half_length})
          pts.emplace_back(radius * std::cos(a), radius * std::sin(a), z);
      }
    pts.emplace_back(0., 0., half_length + radius);
    pts.emplace_back(0., 0., -half_length - radius);
    return pts;
  }
} // namespace particulate::rigid
