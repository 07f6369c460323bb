#include <particulate/fluid/viscosity_model.h>

#include <cmath>

namespace particulate {
  namespace fluid {
    std::unique_ptr<ViscosityModel>
    ViscosityModel::create(const FluidProperties &p)
    {
      if (p.viscosity_model == ViscosityModelType::carreau)
        return std::make_unique<CarreauViscosity>(
          p.dynamic_viscosity,
          p.carreau_infinite_shear_viscosity,
          p.carreau_relaxation_time,
          p.carreau_exponent);
      return std::make_unique<NewtonianViscosity>(p.dynamic_viscosity);
    }

    CarreauViscosity::CarreauViscosity(const double mu_0,
                                       const double mu_inf,
                                       const double lambda,
                                       const double n)
      : mu_0(mu_0)
      , mu_inf(mu_inf)
      , lambda(lambda)
      , n(n)
    {}

    double
    CarreauViscosity::viscosity(const double shear_rate) const
    {
      const double lg = lambda * shear_rate;
      return mu_inf + (mu_0 - mu_inf) * std::pow(1. + lg * lg, 0.5 * (n - 1.));
    }
  } // namespace fluid
} // namespace particulate
