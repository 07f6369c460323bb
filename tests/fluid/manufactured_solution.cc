// Optimal convergence of the Q2/P1disc discretisation for the steady
// Navier-Stokes equations with a manufactured solution on the unit square:
//   u = (sin^2(pi x) sin(2 pi y), -sin(2 pi x) sin^2(pi y)),  p = cos(pi x)
//   cos(pi y)
// (divergence free, zero on the boundary, zero-mean pressure). The body force
// f = (u.grad)u - nu Lap u + grad p / rho is given to the solver as a .prm
// expression, so the test also exercises the input path. Expected rates:
// velocity L2 ~ h^3, pressure L2 ~ h^2.

#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/numerics/vector_tools.h>

#include "solution_error.h"
#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  const std::string u1 = "sin(pi*x)^2*sin(2*pi*y)";
  const std::string u2 = "-sin(2*pi*x)*sin(pi*y)^2";
  const std::string p  = "cos(pi*x)*cos(pi*y)";
  // derivatives of u, written out by hand (see the header comment)
  const std::string u1x = "pi*sin(2*pi*x)*sin(2*pi*y)";
  const std::string u1y = "2*pi*sin(pi*x)^2*cos(2*pi*y)";
  const std::string u2x = "-2*pi*cos(2*pi*x)*sin(pi*y)^2";
  const std::string u2y = "-pi*sin(2*pi*x)*sin(2*pi*y)";
  const std::string lap_u1
    = "(2*pi^2*cos(2*pi*x)*sin(2*pi*y) - 4*pi^2*sin(pi*x)^2*sin(2*pi*y))";
  const std::string lap_u2
    = "(4*pi^2*sin(2*pi*x)*sin(pi*y)^2 - 2*pi^2*sin(2*pi*x)*cos(2*pi*y))";

  std::string
  body_force()
  {
    const std::string f1 = "(" + u1 + ")*(" + u1x + ") + (" + u2 + ")*(" + u1y
                           + ") - nu*" + lap_u1 + " - pi*sin(pi*x)*cos(pi*y)";
    const std::string f2 = "(" + u1 + ")*(" + u2x + ") + (" + u2 + ")*(" + u2y
                           + ") - nu*" + lap_u2 + " - pi*cos(pi*x)*sin(pi*y)";
    return f1 + "; " + f2;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const double                     nu = 0.1;

  std::vector<double> velocity_error, pressure_error;
  for (unsigned int refinements = 1; refinements <= 5; ++refinements)
    {
      const std::string text
        = "subsection Mesh\n set Type = hyper rectangle\n"
          " set Subdivisions = 2, 2\n set Refinements = "
          + std::to_string(refinements)
          + "\nend\n"
            "subsection Time\n set Scheme = steady\nend\n"
            "subsection Fluid\n set Density = 1\n set Dynamic viscosity = "
          + std::to_string(nu) + "\n set Body force = " + body_force()
          + "\n set Body force constants = nu = " + std::to_string(nu)
          + "\nend\n"
            "subsection Boundary conditions\n set No-slip = 0, 1, 2, 3\nend\n"
            "subsection Nonlinear solver\n set Absolute tolerance = 1e-12\n"
            " set Relative tolerance = 1e-12\nend\n"
            "subsection Linear solver\n set Relative tolerance = 1e-8\nend\n";
      const auto parameters
        = testing::parameters_from_text(text, "manufactured_solution");

      const testing::SteadyFlow<2> run(parameters);
      const auto                  &flow = run.flow;

      FunctionParser<2> exact(3);
      exact.initialize("x,y", u1 + ";" + u2 + ";" + p, {{"pi", M_PI}});
      const auto error
        = [&](const unsigned int first, const unsigned int last) {
            return testing::l2_error(flow, exact, first, last, 5);
          };
      velocity_error.push_back(error(0, 2));
      pressure_error.push_back(error(2, 3));
      std::cout << "h = 1/" << (2 << refinements) << "  DoFs " << flow.n_dofs()
                << "  Newton " << run.stats.nonlinear_iterations
                << "  ||u-u_h|| " << velocity_error.back() << "  ||p-p_h|| "
                << pressure_error.back() << std::endl;
    }

  // rates between the two finest levels (the coarsest are pre-asymptotic)
  const double rate_u = testing::last_rate(velocity_error);
  const double rate_p = testing::last_rate(pressure_error);
  std::cout << "observed rates: velocity " << rate_u << ", pressure " << rate_p
            << std::endl;
  checker.check(rate_u > 2.8 && rate_u < 3.3,
                "velocity L2 rate " + std::to_string(rate_u)
                  + " in (2.8, 3.3)");
  checker.check(rate_p > 1.8 && rate_p < 2.5,
                "pressure L2 rate " + std::to_string(rate_p)
                  + " in (1.8, 2.5)");
  return checker.exit_code();
}
