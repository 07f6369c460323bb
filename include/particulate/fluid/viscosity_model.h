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
     * The Newton linearisation treats mu as frozen at the current iterate
     * (a Picard step in mu), which keeps the Jacobian's sparsity and is
     * exact for Newtonian fluids.
     */
    class ViscosityModel
    {
    public:
      virtual ~ViscosityModel() = default;

      /** mu(gamma_dot) [Pa s]. */
      virtual double
      viscosity(const double shear_rate) const = 0;

      /** A representative viscosity for preconditioning [Pa s]. */
      virtual double
      reference_viscosity() const = 0;

      /** False for Newtonian fluids: the assembly can skip gamma_dot. */
      virtual bool
      depends_on_shear_rate() const = 0;

      /** Build the model selected in subsection `Fluid`. */
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
     * Carreau law mu = mu_inf + (mu_0 - mu_inf)(1 + (lambda g)^2)^((n-1)/2).
     */
    class CarreauViscosity : public ViscosityModel
    {
    public:
      CarreauViscosity(const double mu_0,
                       const double mu_inf,
                       const double lambda,
                       const double n);
      double
      viscosity(const double shear_rate) const override;
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

    private:
      double mu_0, mu_inf, lambda, n;
    };
  } // namespace fluid
} // namespace particulate

#endif
