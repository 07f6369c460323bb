#ifndef particulate_fluid_tabulated_viscosity_h
#define particulate_fluid_tabulated_viscosity_h

#include <particulate/fluid/viscosity_model.h>

#include <memory>
#include <string>
#include <vector>

namespace particulate {
  namespace fluid {
    /** A measured flow curve: viscosities at increasing shear rates. */
    struct ViscosityTable
    {
      std::vector<double> shear_rate; ///< [1/s], strictly increasing, > 0
      std::vector<double> viscosity;  ///< [Pa s], > 0
    };

    /**
     * The table in @p filename: one pair 'shear rate [1/s]  viscosity
     * [Pa s]' per line, '#' starting a comment. At least three rows, shear
     * rates positive and strictly increasing, viscosities positive; a
     * missing file or a bad row throws std::runtime_error naming the file
     * and the line.
     */
    ViscosityTable
    read_viscosity_table(const std::string &filename);

    /**
     * A viscosity interpolated from a table by a monotone cubic in
     * log(mu) against log(gamma_dot) (Steffen's method, GSL): it passes
     * through every row, has a continuous derivative, and neither
     * overshoots nor undershoots between rows, so a monotone flow curve
     * stays monotone and a power law given at any rows is reproduced
     * exactly. Outside the table the viscosity is that of the nearest end.
     */
    class TabulatedViscosity : public ViscosityModel
    {
    public:
      explicit TabulatedViscosity(const ViscosityTable &table);
      ~TabulatedViscosity() override;

      double
      viscosity(const double shear_rate) const override;
      double
      slope_over_shear_rate(const double shear_rate) const override;
      /** The geometric mean of the table's viscosities. */
      double
      reference_viscosity() const override;
      bool
      depends_on_shear_rate() const override
      {
        return true;
      }

    private:
      /** log(mu) and its derivative by log(gamma_dot) at @p shear_rate,
       *  clamped to the table. */
      std::pair<double, double>
      log_viscosity_and_slope(const double shear_rate) const;

      /// the table's ends [1/s], where the clamping starts
      double              lowest_shear_rate = 0., highest_shear_rate = 0.;
      std::vector<double> log_shear_rate, log_viscosity;
      struct Interpolant;
      std::unique_ptr<Interpolant> interpolant;
    };
  } // namespace fluid
} // namespace particulate

#endif
