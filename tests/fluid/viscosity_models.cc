// The viscosity laws and the tabulated flow curve:
//  - every law's mu'(g)/g, which the Newton linearisation uses, agrees
//    with a central difference of mu at shear rates from 1.3e-3 to 800 (to
//    1e-5 relative), and is finite at rest;
//  - a table passes through its rows (1e-13), is monotone between rows
//    where the rows are (a Carreau curve sampled at irregular shear rates,
//    checked on 2 000 points), gives a power law back exactly (1e-12) at
//    any rows, and keeps its end values beyond its ends;
//  - bad tables are refused with the file and the line: missing file,
//    shear rates not increasing, a non-positive value, a row of one number,
//    fewer than three rows.

#include <particulate/fluid/tabulated_viscosity.h>
#include <particulate/fluid/viscosity_model.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "test_utilities.h"

using namespace particulate;
using namespace particulate::fluid;

namespace {
  /** The largest relative gap between mu'/g and a central difference. */
  double
  derivative_error(const ViscosityModel &law)
  {
    double worst = 0.;
    for (double g = 1.3e-3; g < 800.; g *= 1.7)
      {
        const double step = 1e-4 * g;
        const double difference
          = (law.viscosity(g + step) - law.viscosity(g - step)) / (2. * step);
        const double slope = law.slope_over_shear_rate(g) * g;
        worst              = std::max(worst,
                         std::abs(slope - difference)
                           / std::max(std::abs(difference), 1e-12));
      }
    return worst;
  }

  ViscosityTable
  sampled(const std::vector<double>           &shear_rates,
          const std::function<double(double)> &mu)
  {
    ViscosityTable table;
    for (const double g : shear_rates)
      {
        table.shear_rate.push_back(g);
        table.viscosity.push_back(mu(g));
      }
    return table;
  }

  /** Whether reading @p text as a table fails with @p expected in the
   *  message. */
  bool
  refused(const std::string &text, const std::string &expected)
  {
    const std::string file = "viscosity_models_table.txt";
    std::ofstream(file) << text;
    try
      {
        read_viscosity_table(file);
      }
    catch (const std::runtime_error &e)
      {
        std::cout << "refused: " << e.what() << std::endl;
        return std::string(e.what()).find(expected) != std::string::npos;
      }
    return false;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;

  const CarreauViscosity thinning_carreau(1., 0.01, 2., 0.4);
  const CarreauViscosity thickening_carreau(0.1, 0., 1., 2.);
  const CrossViscosity   cross(1., 0.01, 2., 0.3);
  // mu_inf > mu_0: the bounded shear-thickening of the macro-scallop's fluid
  const CrossViscosity    thickening_cross(0.9, 22., 0.2, -1.);
  const PowerLawViscosity thinning_power(0.1, 0.5, 1e-6),
    thickening_power(0.1, 1.5, 1e-6);
  const std::vector<double> rates = {1e-3, 1e-2, 0.1, 1., 10., 100., 1e3};
  const TabulatedViscosity  carreau_table(
    sampled(rates, [&](double g) { return thinning_carreau.viscosity(g); }));
  const std::vector<std::pair<std::string, const ViscosityModel *>> laws
    = {{"Carreau n = 0.4", &thinning_carreau},
       {"Carreau n = 2", &thickening_carreau},
       {"Cross n = 0.3", &cross},
       {"Cross n = -1, thickening", &thickening_cross},
       {"power law n = 0.5", &thinning_power},
       {"power law n = 1.5", &thickening_power},
       {"table of Carreau n = 0.4", &carreau_table}};
  for (const auto &[name, law] : laws)
    {
      const double error = derivative_error(*law);
      std::cout << name << ": mu'/g against a central difference " << error
                << ", at rest " << law->slope_over_shear_rate(0.) << std::endl;
      checker.check(error < 1e-5, name + ": mu'/g is mu's derivative over g");
      checker.check(std::isfinite(law->slope_over_shear_rate(0.)),
                    name + ": mu'/g finite at rest");
    }

  // the table through its rows, and monotone between irregular rows
  const std::vector<double> irregular = {1e-3, 2e-3, 0.05, 0.06, 3., 4., 1e3};
  const auto carreau = [&](double g) { return thinning_carreau.viscosity(g); };
  const TabulatedViscosity table(sampled(irregular, carreau));
  double                   through = 0.;
  for (const double g : irregular)
    through = std::max(through, std::abs(table.viscosity(g) / carreau(g) - 1.));
  bool   monotone = true;
  double previous = table.viscosity(1e-3);
  for (unsigned int i = 1; i <= 2000; ++i)
    {
      const double mu = table.viscosity(1e-3 * std::pow(1e6, i / 2000.));
      monotone        = monotone && mu <= previous;
      previous        = mu;
    }
  std::cout << "table: through its rows to " << through
            << ", monotone between them: " << monotone << std::endl;
  checker.check(through < 1e-13, "the table passes through its rows");
  checker.check(monotone, "the table is monotone where its rows are");

  // a power law at any rows is a power law
  const auto power = [](double g) { return 0.1 * std::pow(g, -0.5); };
  const TabulatedViscosity power_table(sampled(irregular, power));
  double                   power_error = 0.;
  for (double g = 1e-3; g < 1e3; g *= 1.31)
    power_error = std::max(power_error,
                           std::abs(power_table.viscosity(g) / power(g) - 1.));
  std::cout << "table of a power law: apart " << power_error << std::endl;
  checker.check(power_error < 1e-12, "a tabulated power law is exact");
  checker.check(power_table.viscosity(1e-9) == power_table.viscosity(1e-3)
                  && power_table.viscosity(1e9) == power_table.viscosity(1e3)
                  && power_table.slope_over_shear_rate(1e9) == 0.,
                "beyond its ends the table keeps the end's viscosity");

  // bad tables
  checker.check(refused("1 1\n2 2\n2 3\n", "viscosity_models_table.txt:3"),
                "shear rates that do not increase are refused at their line");
  checker.check(refused("# g mu\n1 1\n2 -2\n3 3\n", ":3: shear rate and"),
                "a negative viscosity is refused at its line");
  checker.check(refused("1 1\n2\n3 3\n", ":2: expected two numbers"),
                "a row of one number is refused at its line");
  checker.check(refused("1 1\n2 2 2\n3 3\n", ":2: expected two numbers"),
                "a row of three numbers is refused at its line");
  checker.check(refused("1 1\nabc\n3 3\n", ":2: expected a shear rate"),
                "a row of text is refused at its line");
  checker.check(refused("1 1\n2 2\n", "at least three rows"),
                "a table of two rows is refused");
  bool missing = false;
  try
    {
      read_viscosity_table("no_such_viscosity_table.txt");
    }
  catch (const std::runtime_error &e)
    {
      missing = std::string(e.what()).find("no_such_viscosity_table.txt")
                != std::string::npos;
    }
  checker.check(missing, "a missing table is refused with its name");
  return checker.exit_code();
}
