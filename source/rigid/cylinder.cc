#include <particulate/rigid/cylinder.h>

#include <cmath>
#include <stdexcept>

namespace particulate::rigid {
  Cylinder::Cylinder(const double r, const double h)
    : radius(r)
    , half_height(h)
  {
    if (!(r > 0.) || !(h > 0.) || !std::isfinite(r) || !std::isfinite(h))
      throw std::invalid_argument(
        "rigid::Cylinder: radius and half height must be positive finite "
        "lengths in m.");
  }
  ShapeType
  Cylinder::type() const
  {
    return ShapeType::cylinder;
  }
  std::string
  Cylinder::name() const
  {
    return "cylinder";
  }
  double
  Cylinder::volume() const
  {
    return M_PI * radius * radius * 2. * half_height;
  }
  Eigen::Vector3d
  Cylinder::unit_density_inertia() const
  {
    const double m = volume(), L = 2. * half_height;
    const double ix = m * (3. * radius * radius + L * L) / 12.;
    return Eigen::Vector3d(ix, ix, 0.5 * m * radius * radius);
  }
  double
  Cylinder::bounding_radius() const
  {
    return std::hypot(radius, half_height);
  }
  double
  Cylinder::signed_distance(const Eigen::Vector3d &p) const
  {
    const double dr = std::hypot(p[0], p[1]) - radius;
    const double dz = std::abs(p[2]) - half_height;
    return std::hypot(std::max(dr, 0.), std::max(dz, 0.))
           + std::min(std::max(dr, dz), 0.);
  }
  Eigen::Vector3d
  Cylinder::gradient(const Eigen::Vector3d &p) const
  {
    const double    rho = std::hypot(p[0], p[1]);
    const double    dr = rho - radius, dz = std::abs(p[2]) - half_height;
    Eigen::Vector3d er = rho > 0. ?
                           Eigen::Vector3d(p[0] / rho, p[1] / rho, 0.) :
                           Eigen::Vector3d::UnitX();
    Eigen::Vector3d ez(0., 0., p[2] >= 0. ? 1. : -1.);
    if (dr > 0. && dz > 0.)
      return (dr * er + dz * ez).normalized();
    return dr > dz ? er : ez;
  }
  Eigen::Vector3d
  Cylinder::support(const Eigen::Vector3d &d) const
  {
    const double    rho = std::hypot(d[0], d[1]);
    Eigen::Vector3d s(0., 0., d[2] >= 0. ? half_height : -half_height);
    if (rho > 0.)
      {
        s[0] = radius * d[0] / rho;
        s[1] = radius * d[1] / rho;
      }
    return s;
  }
  std::vector<Eigen::Vector3d>
  Cylinder::surface_points() const
  {
    std::vector<Eigen::Vector3d> pts;
    for (int k = 0; k < 16; ++k)
      {
        const double a = 2. * M_PI * k / 16.;
        for (double z : {-half_height, 0., half_height})
          pts.emplace_back(radius * std::cos(a), radius * std::sin(a), z);
      }
    pts.emplace_back(0., 0., half_height);
    pts.emplace_back(0., 0., -half_height);
    return pts;
  }
} // namespace particulate::rigid
