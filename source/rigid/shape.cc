#include <particulate/rigid/material.h>
#include <particulate/rigid/shape.h>
#include <particulate/rigid/signed_distance_shape.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace particulate::rigid {
  Eigen::Vector3d
  Shape::gradient(const Eigen::Vector3d &p) const
  {
    // Central differences with a step relative to the body size, so the
    // estimate is scale invariant.
    const double h = 1.e-6 * std::max(1.e-3, std::min(1.e3, bounding_radius()));
    Eigen::Vector3d g;
    for (int i = 0; i < 3; ++i)
      {
        Eigen::Vector3d e = Eigen::Vector3d::Zero();
        e[i]              = h;
        g[i] = (signed_distance(p + e) - signed_distance(p - e)) / (2. * h);
      }
    const double n = g.norm();
    return n > 0. ? Eigen::Vector3d(g / n) : Eigen::Vector3d::UnitZ();
  }



  Eigen::Vector3d
  Shape::support(const Eigen::Vector3d &) const
  {
    throw std::logic_error("rigid::Shape::support(): the shape '" + name()
                           + "' is not convex and bounded, so it has no "
                             "support function; the narrow phase must use "
                             "its signed distance instead.");
  }



  SignedDistanceShape::SignedDistanceShape(const double           volume,
                                           const Eigen::Vector3d &inertia,
                                           const double bounding_radius)
    : volume_(volume)
    , inertia_(inertia)
    , bounding_radius_(bounding_radius)
  {
    if (!(volume > 0.) || !(bounding_radius > 0.) || !(inertia.minCoeff() > 0.))
      throw std::invalid_argument(
        "rigid::SignedDistanceShape: volume, bounding radius and principal "
        "moments of inertia must all be positive; compute them from the "
        "closed surface mesh before constructing the shape.");
  }



  void
  Material::check() const
  {
    auto fail = [this](const std::string &what) {
      throw std::invalid_argument("rigid::Material '" + name + "': " + what);
    };
    if (!(density > 0.))
      fail("density must be positive (kg/m^3).");
    if (!(restitution >= 0. && restitution <= 1.))
      fail("restitution must lie in [0, 1].");
    if (!(static_friction >= 0.) || !(dynamic_friction >= 0.))
      fail("friction coefficients must be non-negative.");
    if (dynamic_friction > static_friction + 1.e-15)
      fail("the dynamic friction coefficient must not exceed the static one "
           "(Coulomb model, thesis eqs. 4.34-4.35).");
    if (!(dem_stiffness > 0.) || !(dem_tangential_stiffness >= 0.))
      fail("DEM stiffnesses must be positive (N/m).");
  }



  Material
  Material::combine(const Material &a, const Material &b)
  {
    Material m;
    m.name             = a.name + "/" + b.name;
    m.density          = 0.5 * (a.density + b.density);
    m.restitution      = std::min(a.restitution, b.restitution);
    m.static_friction  = std::sqrt(a.static_friction * b.static_friction);
    m.dynamic_friction = std::sqrt(a.dynamic_friction * b.dynamic_friction);
    m.dem_stiffness    = 1. / (1. / a.dem_stiffness + 1. / b.dem_stiffness);
    const double kt_a  = a.dem_tangential_stiffness,
                 kt_b  = b.dem_tangential_stiffness;
    m.dem_tangential_stiffness
      = (kt_a > 0. && kt_b > 0.) ? 1. / (1. / kt_a + 1. / kt_b) : 0.;
    return m;
  }
} // namespace particulate::rigid
