#include <particulate/rigid/material.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace particulate {
  namespace rigid {
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
  } // namespace rigid
} // namespace particulate
