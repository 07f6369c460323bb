#ifndef particulate_fluid_viscosity_model_h
#define particulate_fluid_viscosity_model_h

#include <particulate/fluid/fluid_parameters.h>

#include <memory>

namespace particulate {
  namespace fluid {
    /**
     * The dynamic viscosity as a function of the shear rate
     * gamma_dot = sqrt(2 D(u):D(u)). The assembly asks only this interface,
     * so a generalized-Newtonian law plugs in without touching the loops.
     *
     * The Newton linearisation of the viscous stress 2 mu(gamma_dot) D(u)
     * in the direction du is
     *
     *   2 mu D(du) + 4 (mu'(gamma_dot) / gamma_dot) (D(u):D(du)) D(u),
     *
     * since d gamma_dot = 2 D(u):D(du) / gamma_dot: the law supplies mu and
     * mu'/gamma_dot, which stays finite at gamma_dot = 0 for the smooth
     * laws and multiplies |D(u)|^2 where it does not.
     */
    class ViscosityModel
    {
    public:
      virtual ~ViscosityModel() = default;

      /** mu(gamma_dot) [Pa s]. */
      virtual double
      viscosity(const double shear_rate) const = 0;

      /** mu'(gamma_dot) / gamma_dot [Pa s^3], 0 at gamma_dot = 0 where the
       *  limit is not finite (the Newton term vanishes with D(u) there). */
      virtual double
      slope_over_shear_rate(const double shear_rate) const = 0;

      /** A representative viscosity for preconditioning [Pa s]. */
      virtual double
      reference_viscosity() const = 0;

      /** False for Newtonian fluids: the assembly can skip gamma_dot. */
      virtual bool
      depends_on_shear_rate() const = 0;

      /** Build the model selected in subsection `Fluid` (a table is read
       *  from its file; std::runtime_error names the file and line of a
       *  bad one). */
      static std::unique_ptr<ViscosityModel>
      create(const FluidProperties &properties);
    };

    /** Constant viscosity. */
    class NewtonianViscosity : public ViscosityModel
    {
    public:
      explicit NewtonianViscosity(const double mu)
        : mu(mu)
      {}
      double
      viscosity(const double) const override
      {
        return mu;
      }
      double
      slope_over_shear_rate(const double) const override
      {
        return 0.;
      }
      double
      reference_viscosity() const override
      {
        return mu;
      }
      bool
      depends_on_shear_rate() const override
      {
        return false;
      }

    private:
      double mu;
    };

    /**
     * A law between a zero-shear plateau mu_0 and an infinite-shear one
     * mu_inf, with a relaxation time lambda and an index n: what Carreau
     * and Cross share.
     */
    class PlateauViscosity : public ViscosityModel
    {
    public:
      PlateauViscosity(const double mu_0,
                       const double mu_inf,
                       const double lambda,
                       const double n)
        : mu_0(mu_0)
        , mu_inf(mu_inf)
        , lambda(lambda)
        , n(n)
      {}
      double
      reference_viscosity() const override
      {
        return mu_0;
      }
      bool
      depends_on_shear_rate() const override
      {
        return true;
      }

    protected:
      double mu_0, mu_inf, lambda, n;
    };

    /**
     * Carreau law mu = mu_inf + (mu_0 - mu_inf)(1 + (lambda g)^2)^((n-1)/2):
     * shear-thinning for n < 1, shear-thickening for n > 1.
     */
    class CarreauViscosity : public PlateauViscosity
    {
    public:
      using PlateauViscosity::PlateauViscosity;
      double
      viscosity(const double shear_rate) const override;
      double
      slope_over_shear_rate(const double shear_rate) const override;
    };

    /**
     * Cross law mu = mu_inf + (mu_0 - mu_inf) / (1 + (lambda g)^(1-n)),
     * n < 1: between its two plateaus the viscosity falls like g^(n-1)
     * where mu_inf < mu_0 (shear-thinning), and rises to mu_inf where
     * mu_inf > mu_0 (a shear-thickening fluid with a bounded viscosity;
     * n = -1 makes it a smooth function of g^2).
     */
    class CrossViscosity : public PlateauViscosity
    {
    public:
      using PlateauViscosity::PlateauViscosity;
      double
      viscosity(const double shear_rate) const override;
      double
      slope_over_shear_rate(const double shear_rate) const override;
    };

    /**
     * Power law mu = K max(g, g_min)^(n-1). The floor g_min keeps mu
     * finite at rest for n < 1 and positive for n > 1; below it the
     * viscosity is constant.
     */
    class PowerLawViscosity : public ViscosityModel
    {
    public:
      PowerLawViscosity(const double consistency,
                        const double n,
                        const double minimum_shear_rate);
      double
      viscosity(const double shear_rate) const override;
      double
      slope_over_shear_rate(const double shear_rate) const override;
      /** K, the viscosity at a shear rate of 1/s. */
      double
      reference_viscosity() const override
      {
        return consistency;
      }
      bool
      depends_on_shear_rate() const override
      {
        return true;
      }

    private:
      double consistency, n, minimum_shear_rate;
    };
  } // namespace fluid
} // namespace particulate

#endif
