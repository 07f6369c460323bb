#include <particulate/fluid/tabulated_viscosity.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include <gsl/gsl_interp.h>

namespace particulate {
  namespace fluid {
    namespace {
      [[noreturn]] void
      fail(const std::string &where, const std::string &what)
      {
        throw std::runtime_error(where + ": " + what);
      }

      /** The two numbers of a table row, or false for a line without
       *  any (blank or comment only). */
      bool
      read_row(std::string line, const std::string &where, double &x, double &y)
      {
        line = line.substr(0, line.find('#'));
        std::istringstream in(line);
        std::string        extra;
        if (!(in >> x))
          {
            if (line.find_first_not_of(" \t\r") != std::string::npos)
              fail(where,
                   "expected a shear rate [1/s] and a viscosity [Pa s], "
                   "found '"
                     + line + "'");
            return false;
          }
        if (!(in >> y) || (in >> extra))
          fail(where,
               "expected two numbers, a shear rate [1/s] and a viscosity "
               "[Pa s], found '"
                 + line + "'");
        return true;
      }
    } // namespace



    ViscosityTable
    read_viscosity_table(const std::string &filename)
    {
      std::ifstream in(filename);
      if (!in)
        fail(filename,
             "cannot read the viscosity table (a relative path starts at the "
             "case file's folder)");
      ViscosityTable table;
      std::string    line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          const std::string where = filename + ":" + std::to_string(number);
          double            x, y;
          if (!read_row(line, where, x, y))
            continue;
          if (!(x > 0.) || !(y > 0.) || !std::isfinite(x) || !std::isfinite(y))
            fail(where,
                 "shear rate and viscosity must be positive and finite "
                 "(the table is interpolated in their logarithms)");
          if (!table.shear_rate.empty() && !(x > table.shear_rate.back()))
            fail(where, "the shear rates must increase from row to row");
          table.shear_rate.push_back(x);
          table.viscosity.push_back(y);
        }
      if (table.shear_rate.size() < 3)
        fail(filename,
             "a viscosity table needs at least three rows (shear rate, "
             "viscosity); it has "
               + std::to_string(table.shear_rate.size()));
      return table;
    }



    struct TabulatedViscosity::Interpolant
    {
      gsl_interp *steffen = nullptr;
      ~Interpolant()
      {
        gsl_interp_free(steffen);
      }
    };



    TabulatedViscosity::TabulatedViscosity(const ViscosityTable &table)
      : interpolant(std::make_unique<Interpolant>())
    {
      if (table.shear_rate.size() != table.viscosity.size()
          || table.shear_rate.size()
               < gsl_interp_type_min_size(gsl_interp_steffen))
        throw std::runtime_error("a viscosity table needs at least three "
                                 "rows of shear rate and viscosity");
      lowest_shear_rate  = table.shear_rate.front();
      highest_shear_rate = table.shear_rate.back();
      for (unsigned int i = 0; i < table.shear_rate.size(); ++i)
        {
          log_shear_rate.push_back(std::log(table.shear_rate[i]));
          log_viscosity.push_back(std::log(table.viscosity[i]));
        }
      interpolant->steffen
        = gsl_interp_alloc(gsl_interp_steffen, log_shear_rate.size());
      gsl_interp_init(interpolant->steffen,
                      log_shear_rate.data(),
                      log_viscosity.data(),
                      log_shear_rate.size());
    }

    TabulatedViscosity::~TabulatedViscosity() = default;

    std::pair<double, double>
    TabulatedViscosity::log_viscosity_and_slope(const double shear_rate) const
    {
      // beyond the ends (and at rest) the end's viscosity, with slope 0;
      // the clamp also keeps GSL from its out-of-range error handler
      if (!(shear_rate > lowest_shear_rate))
        return {log_viscosity.front(), 0.};
      if (shear_rate >= highest_shear_rate)
        return {log_viscosity.back(), 0.};
      const double x = std::log(shear_rate);
      // no accelerator: the evaluation stays free of shared state
      return {gsl_interp_eval(interpolant->steffen,
                              log_shear_rate.data(),
                              log_viscosity.data(),
                              x,
                              nullptr),
              gsl_interp_eval_deriv(interpolant->steffen,
                                    log_shear_rate.data(),
                                    log_viscosity.data(),
                                    x,
                                    nullptr)};
    }

    double
    TabulatedViscosity::viscosity(const double shear_rate) const
    {
      return std::exp(log_viscosity_and_slope(shear_rate).first);
    }

    double
    TabulatedViscosity::slope_over_shear_rate(const double shear_rate) const
    {
      // mu = exp(f(log g)): mu' = mu f'(log g) / g
      const auto [log_mu, slope] = log_viscosity_and_slope(shear_rate);
      if (slope == 0.)
        return 0.;
      return std::exp(log_mu) * slope / (shear_rate * shear_rate);
    }

    double
    TabulatedViscosity::reference_viscosity() const
    {
      return std::exp(
        std::accumulate(log_viscosity.begin(), log_viscosity.end(), 0.)
        / log_viscosity.size());
    }
  } // namespace fluid
} // namespace particulate
