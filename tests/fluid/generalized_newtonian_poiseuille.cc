// Plane Poiseuille flow of generalized-Newtonian fluids against closed
// forms. In the channel [0, 2] x [-h, h], h = 1/2, a pressure gradient
// -G along x balances the shear stress tau = G |y|, so the shear rate g
// solves mu(g) g = G |y| and u(y) = int_|y|^h g(s) ds. For these laws the
// integral has a closed form:
//  - power law mu = K g^(n-1), shear-thinning n = 1/2 and shear-thickening
//    n = 3/2: u = n/(n+1) (G/K)^(1/n) (h^((n+1)/n) - |y|^((n+1)/n));
//  - Carreau with n = 2 and mu_inf = 0 (shear-thickening): with b =
//    2 lambda G / mu_0 and C(s) = sqrt((sqrt(1 + b^2 s^2) + 1)/2),
//    u = P(h) - P(|y|), P(s) = (4/3 C^3 - 2 C) / (lambda b);
//  - Cross with n = 0 and mu_inf = 0 (shear-thinning, stress below
//    mu_0/lambda): u = Q(h) - Q(|y|), Q(s) = -(s + mu_0/(lambda G)
//    log(mu_0 - lambda G s))/lambda;
//  - a table of the thinning power law's viscosity at 10 shear rates
//    (monotone cubic in log-log, which reproduces a power law).
// The profile is given at the inflow and the outflow, the walls are
// no-slip, and the steady flow is solved by Newton's method from rest on
// refinements 2, 3 and 4. Each law must
//  - converge to the profile: L2 rate above 2.7 between the two finest
//    meshes where the profile is smooth (Q2: 3), above 1.9 for the
//    thickening power law, whose profile |y|^(5/3) at the centre limits the
//    rate to 2 + 1/6;
//  - give the pressure drop G L between x = 0.5 and 1.5 on the centreline
//    within 0.5 %;
//  - converge from rest within 30 nonlinear steps (a tolerance of 1e-11
//    relative), the thinning power law in fewer than 0.6 times the steps of
//    the fixed-point iteration: Newton's linearisation includes the
//    viscosity's derivative.
// The flow rate against the pressure drop: at twice the flow rate the
// thinning power law's pressure drop grows by 2^n = 1.414 (within 0.5 %),
// and the table gives the power law's solution (within 1e-7 relative) with
// as many Newton steps. For the Carreau and Cross laws the matrix-free
// Jacobian gives the assembled one's solution (within 1e-8 relative) in
// as many Newton steps. Writes generalized-newtonian-errors.dat and
// -profiles.dat, the series of doc/validation/generalized-newtonian.md.

#include <particulate/fluid/flow_diagnostics.h>
#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "solution_error.h"
#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  const double h = 0.5;

  /** A law, its subsection Fluid entries, its pressure gradient G and its
   *  closed-form u(y) as a muparser expression. */
  struct Law
  {
    std::string name;
    std::string fluid;
    double      G;
    std::string profile;
    double      minimum_rate;
  };

  std::string
  number(const double x)
  {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
  }

  Law
  power_law(const double n, const double K, const double G)
  {
    const double a = (n + 1.) / n;
    const double c = n / (n + 1.) * std::pow(G / K, 1. / n);
    return {"power law n = " + number(n),
            " set Viscosity model = power law\n set Consistency = " + number(K)
              + "\n set Power-law index = " + number(n)
              + "\n set Minimum shear rate = 1e-6\n",
            G,
            number(c) + "*(" + number(std::pow(h, a)) + " - abs(y)^" + number(a)
              + ")",
            n < 1. ? 2.7 : 1.9};
  }

  Law
  carreau_thickening(const double mu_0, const double lambda, const double G)
  {
    const double      b = 2. * lambda * G / mu_0;
    const std::string C = [&](const std::string &s) {
      return "sqrt((sqrt(1 + " + number(b * b) + "*" + s + "^2) + 1)/2)";
    }("abs(y)");
    const double Ch = std::sqrt((std::sqrt(1. + b * b * h * h) + 1.) / 2.);
    const double Ph = (4. / 3. * Ch * Ch * Ch - 2. * Ch) / (lambda * b);
    return {
      "Carreau n = 2",
      " set Viscosity model = Carreau\n set Dynamic viscosity = " + number(mu_0)
        + "\n set Relaxation time = " + number(lambda)
        + "\n set Power-law index = 2\n set Infinite-shear viscosity = 0\n",
      G,
      number(Ph) + " - (4/3*" + C + "^3 - 2*" + C + ")/" + number(lambda * b),
      2.7};
  }

  Law
  cross_thinning(const double mu_0, const double lambda, const double G)
  {
    const auto Q = [&](const std::string &s) {
      return "(-(" + s + ") - " + number(mu_0 / (lambda * G)) + "*log("
             + number(mu_0) + " - " + number(lambda * G) + "*" + s + "))/"
             + number(lambda);
    };
    return {
      "Cross n = 0",
      " set Viscosity model = Cross\n set Dynamic viscosity = " + number(mu_0)
        + "\n set Relaxation time = " + number(lambda)
        + "\n set Power-law index = 0\n set Infinite-shear viscosity = 0\n",
      G,
      Q(number(h)) + " - " + Q("abs(y)"),
      2.7};
  }

  std::string
  case_text(const Law         &law,
            const unsigned int refinements,
            const double       scale,
            const std::string &extra)
  {
    return "subsection Mesh\n set Type = hyper rectangle\n"
           " set Lower corner = 0, -0.5\n set Upper corner = 2, 0.5\n"
           " set Subdivisions = 2, 1\n set Refinements = "
           + std::to_string(refinements)
           + "\nend\n"
             "subsection Time\n set Scheme = steady\nend\n"
             "subsection Fluid\n set Density = 1\n"
           + law.fluid
           + "end\n"
             "subsection Boundary conditions\n set No-slip = 2, 3\n"
             " set Dirichlet velocity = 0, 1\n set Velocity = "
           + number(scale) + "*(" + law.profile
           + "); 0\nend\n"
             "subsection Nonlinear solver\n set Absolute tolerance = 1e-12\n"
             " set Relative tolerance = 1e-11\n set Maximum iterations = 30\n"
             "end\n"
             "subsection Linear solver\n set Relative tolerance = 1e-10\nend\n"
           + extra;
  }

  /** Velocity L2 error, pressure drop and Newton steps of one run. */
  struct Result
  {
    double                             error;
    double                             drop;
    unsigned int                       newton;
    TrilinosWrappers::MPI::BlockVector solution;
    /// u_x and the closed form at profile_points() across x = 1
    std::vector<std::pair<double, double>> profile;
  };

  /** Where the profiles are sampled: 41 points across the channel. */
  std::vector<double>
  profile_points()
  {
    std::vector<double> y;
    for (unsigned int i = 0; i <= 40; ++i)
      y.push_back(-h + 2. * h * i / 40.);
    return y;
  }

  Result
  solve(const Law         &law,
        const unsigned int refinements,
        const double       scale = 1.,
        const std::string &extra = "")
  {
    const auto parameters
      = testing::parameters_from_text(case_text(law, refinements, scale, extra),
                                      "generalized_newtonian");
    const testing::SteadyFlow<2> run(parameters);
    FunctionParser<2>            exact(3);
    exact.initialize("x,y", number(scale) + "*(" + law.profile + "); 0; 0", {});
    const auto at = [&](const double x) {
      return fluid::pressure_at(run.flow, Point<2>(x, 0.));
    };
    std::vector<std::pair<double, double>> profile;
    for (const double y : profile_points())
      {
        const Point<2> point(1., y);
        Vector<double> value(3);
        VectorTools::point_value(run.flow.get_mapping(),
                                 run.flow.get_dof_handler(),
                                 run.flow.get_solution(),
                                 point,
                                 value);
        profile.emplace_back(value[0], exact.value(point, 0));
      }
    return {testing::l2_error(run.flow, exact, 0, 2, 5),
            at(0.5) - at(1.5),
            run.stats.nonlinear_iterations,
            run.flow.get_solution(),
            profile};
  }

  double
  relative_difference(const TrilinosWrappers::MPI::BlockVector &a,
                      const TrilinosWrappers::MPI::BlockVector &b)
  {
    TrilinosWrappers::MPI::BlockVector d(a);
    d -= b;
    return d.l2_norm() / b.l2_norm();
  }

  /** The thinning power law's viscosity at 10 shear rates, 1e-6 to 1e3. */
  std::string
  write_power_law_table(const double n, const double K)
  {
    const std::string file = "generalized_newtonian_table.txt";
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ofstream out(file);
        out.precision(17);
        out << "# shear rate [1/s]  viscosity [Pa s]\n";
        for (int e = -6; e <= 3; ++e)
          out << std::pow(10., e) << "  " << K * std::pow(10., e * (n - 1.))
              << "\n";
      }
    MPI_Barrier(MPI_COMM_WORLD);
    return file;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;

  const Law              thinning = power_law(0.5, 0.1, 0.5);
  const std::vector<Law> laws     = {thinning,
                                     power_law(1.5, 0.1, 1.2),
                                     carreau_thickening(0.1, 1., 1.),
                                     cross_thinning(0.1, 1., 0.16)};
  // the series doc/validation/generalized-newtonian.md draws
  std::ofstream errors_series("generalized-newtonian-errors.dat");
  errors_series << "# law  cells across the channel  velocity L2 error  "
                   "Newton steps\n";
  std::vector<Result> finest;
  for (const Law &law : laws)
    {
      std::vector<double> errors;
      Result              result;
      for (unsigned int refinements = 2; refinements <= 4; ++refinements)
        {
          result = solve(law, refinements);
          errors.push_back(result.error);
          errors_series << '"' << law.name << "\"  " << (1u << refinements)
                        << "  " << result.error << "  " << result.newton
                        << "\n";
          std::cout << law.name << "  refinements " << refinements
                    << "  Newton " << result.newton << "  ||u-u_h|| "
                    << result.error << "  pressure drop " << result.drop
                    << " (exact " << law.G << ")" << std::endl;
        }
      const double rate = testing::last_rate(errors);
      std::cout << law.name << ": velocity L2 rate " << rate << std::endl;
      checker.check(rate > law.minimum_rate,
                    law.name + ": velocity L2 rate above "
                      + number(law.minimum_rate));
      checker.check(std::abs(result.drop / law.G - 1.) < 0.005,
                    law.name + ": pressure drop within 0.5 %");
      finest.push_back(result);
    }
  const Result &thinning_finest = finest.front();
  std::ofstream profiles("generalized-newtonian-profiles.dat");
  profiles << "# y, then u_x at x = 1 on 16 cells across and the closed form "
              "for each law:";
  for (const Law &law : laws)
    profiles << " \"" << law.name << '"';
  profiles << "\n";
  for (unsigned int i = 0; i < profile_points().size(); ++i)
    {
      profiles << profile_points()[i];
      for (const Result &result : finest)
        profiles << "  " << result.profile[i].first << "  "
                 << result.profile[i].second;
      profiles << "\n";
    }

  // Newton against the fixed-point iteration (mu frozen at the iterate)
  const Result fixed_point
    = solve(thinning,
            4,
            1.,
            "subsection Nonlinear solver\n set Method = fixed point\n"
            " set Maximum iterations = 100\nend\n");
  std::cout << "power law n = 0.5, refinements 4: Newton "
            << thinning_finest.newton << " steps, fixed point "
            << fixed_point.newton << std::endl;
  checker.check(thinning_finest.newton < 0.6 * fixed_point.newton,
                "Newton takes fewer than 0.6 times the fixed point's steps");

  // twice the flow rate: the pressure drop grows by 2^n
  const Result doubled = solve(thinning, 4, 2.);
  const double growth  = doubled.drop / thinning_finest.drop;
  std::cout << "power law n = 0.5 at twice the flow rate: pressure drop x"
            << growth << " (2^n = " << std::sqrt(2.) << "), Newton "
            << doubled.newton << std::endl;
  checker.check(std::abs(growth / std::sqrt(2.) - 1.) < 0.005,
                "twice the flow rate: pressure drop x 2^n within 0.5 %");

  // the same law as a table
  Law tabulated   = thinning;
  tabulated.fluid = " set Viscosity model = table\n set Viscosity table = "
                    + write_power_law_table(0.5, 0.1) + "\n";
  const Result table = solve(tabulated, 4);
  const double table_difference
    = relative_difference(table.solution, thinning_finest.solution);
  std::cout << "table of the power law: Newton " << table.newton
            << ", solution apart " << table_difference << std::endl;
  checker.check(table_difference < 1e-7,
                "the tabulated power law gives the power law's solution");
  checker.check(table.newton == thinning_finest.newton,
                "the tabulated power law takes as many Newton steps");

  // the matrix-free Jacobian against the assembled one, both
  // preconditioned by the geometric multigrid (whose V-cycle does not
  // carry the thinning power law's steady flow from rest: FGMRES stalls
  // there with either operator, as it does not with the default AMG)
  for (unsigned int i = 2; i < laws.size(); ++i)
    {
      const auto with = [&](const std::string &op) {
        return solve(laws[i],
                     4,
                     1.,
                     "subsection Linear solver\n set Velocity operator = " + op
                       + "\n set Velocity preconditioner = geometric "
                         "multigrid\nend\n");
      };
      const Result assembled = with("assembled"), free = with("matrix-free");
      const double difference
        = relative_difference(free.solution, assembled.solution);
      std::cout << laws[i].name << ", geometric multigrid: Newton "
                << assembled.newton << " assembled, " << free.newton
                << " matrix-free, solutions apart " << difference << std::endl;
      checker.check(difference < 1e-8,
                    laws[i].name
                      + ": the matrix-free Jacobian gives the assembled "
                        "one's solution");
      checker.check(free.newton == assembled.newton,
                    laws[i].name
                      + ": the matrix-free Jacobian takes as many Newton "
                        "steps");
    }
  return checker.exit_code();
}
