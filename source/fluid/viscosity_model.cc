#include <particulate/fluid/tabulated_viscosity.h>
#include <particulate/fluid/viscosity_model.h>

#include <algorithm>
#include <cmath>

namespace particulate {
  namespace fluid {
    std::unique_ptr<ViscosityModel>
    ViscosityModel::create(const FluidProperties &p)
    {
      switch (p.viscosity_model)
        {
          case ViscosityModelType::carreau:
            return std::make_unique<CarreauViscosity>(
              p.dynamic_viscosity,
              p.infinite_shear_viscosity,
              p.relaxation_time,
              p.power_law_index);
          case ViscosityModelType::cross:
            return std::make_unique<CrossViscosity>(p.dynamic_viscosity,
                                                    p.infinite_shear_viscosity,
                                                    p.relaxation_time,
                                                    p.power_law_index);
          case ViscosityModelType::power_law:
            return std::make_unique<PowerLawViscosity>(p.consistency,
                                                       p.power_law_index,
                                                       p.minimum_shear_rate);
          case ViscosityModelType::table:
            return std::make_unique<TabulatedViscosity>(
              read_viscosity_table(p.viscosity_table));
          case ViscosityModelType::newtonian:
            break;
        }
      return std::make_unique<NewtonianViscosity>(p.dynamic_viscosity);
    }



    double
    CarreauViscosity::viscosity(const double shear_rate) const
    {
      const double lg = lambda * shear_rate;
      return mu_inf + (mu_0 - mu_inf) * std::pow(1. + lg * lg, 0.5 * (n - 1.));
    }

    double
    CarreauViscosity::slope_over_shear_rate(const double shear_rate) const
    {
      // mu' = (mu_0 - mu_inf) (n - 1) lambda^2 g (1 + (lambda g)^2)^((n-3)/2)
      const double lg = lambda * shear_rate;
      return (mu_0 - mu_inf) * (n - 1.) * lambda * lambda
             * std::pow(1. + lg * lg, 0.5 * (n - 3.));
    }



    double
    CrossViscosity::viscosity(const double shear_rate) const
    {
      return mu_inf
             + (mu_0 - mu_inf) / (1. + std::pow(lambda * shear_rate, 1. - n));
    }

    double
    CrossViscosity::slope_over_shear_rate(const double shear_rate) const
    {
      // mu' = -(mu_0 - mu_inf) m (lambda g)^m / (g (1 + (lambda g)^m)^2):
      // mu'/g grows like g^(m-2) at rest, where D(u) = 0 cancels it
      if (shear_rate == 0.)
        return 0.;
      const double m     = 1. - n;
      const double power = std::pow(lambda * shear_rate, m);
      return -(mu_0 - mu_inf) * m * power
             / (shear_rate * shear_rate * (1. + power) * (1. + power));
    }



    PowerLawViscosity::PowerLawViscosity(const double consistency,
                                         const double n,
                                         const double minimum_shear_rate)
      : consistency(consistency)
      , n(n)
      , minimum_shear_rate(minimum_shear_rate)
    {}

    double
    PowerLawViscosity::viscosity(const double shear_rate) const
    {
      return consistency
             * std::pow(std::max(shear_rate, minimum_shear_rate), n - 1.);
    }

    double
    PowerLawViscosity::slope_over_shear_rate(const double shear_rate) const
    {
      if (shear_rate <= minimum_shear_rate)
        return 0.;
      return consistency * (n - 1.) * std::pow(shear_rate, n - 3.);
    }
  } // namespace fluid
} // namespace particulate
