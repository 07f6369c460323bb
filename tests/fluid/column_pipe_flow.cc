// The 'column' mesh (a circular cylinder along z, the fluidized-bed column)
// carries Hagen-Poiseuille flow: in the column of radius R = 0.5 and length
// 2 (inscribed in the box [0,1] x [0,1] x [0,2]), the profile
//   u_z = 2 U (1 - rho^2 / R^2), rho the distance from the axis,
// is given at the bottom and the top (boundary ids 1 and 2; the traction-
// free outflow of the symmetric viscous form would pull on the profile),
// the mantle (id 0) is no-slip, and the zero-mean pressure is
// p = 8 mu U (1 - z) / R^2.
// The steady solution on refinements 1, 2 and 3 must
// - fill the column's volume pi R^2 L to within the mapping's error
//   (relative error below 1e-3 on the finest mesh);
// - converge to the profile at an L2 rate above 2.5 (Q2 velocities on a
//   mapped curved mantle: 3 is optimal) and to the pressure at a rate above
//   1.5, between the two finest meshes;
// - give the pressure drop between the axis points z = 0.5 and 1.5 within
//   0.5 % of 8 mu U / R^2 on the finest mesh.

#include <particulate/fluid/flow_diagnostics.h>
#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include "solution_error.h"
#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const double                     mu = 0.1, U = 1., R = 0.5, L = 2.;
  const std::string profile  = "2*(1 - ((x-0.5)^2 + (y-0.5)^2)/0.25)";
  const std::string pressure = "8*0.1*(1 - z)/0.25";

  std::vector<double> velocity_error, pressure_error;
  for (unsigned int refinements = 1; refinements <= 3; ++refinements)
    {
      const std::string text
        = "subsection Mesh\n set Type = column\n set Lower corner = 0, 0, 0\n"
          " set Upper corner = 1, 1, 2\n set Subdivisions = 1, 1, 2\n"
          " set Refinements = "
          + std::to_string(refinements)
          + "\nend\n"
            "subsection Time\n set Scheme = steady\nend\n"
            "subsection Fluid\n set Density = 1\n set Dynamic viscosity = 0.1\n"
            "end\n"
            "subsection Boundary conditions\n set No-slip = 0\n"
            " set Dirichlet velocity = 1, 2\n set Velocity = 0; 0; "
          + profile
          + "\nend\n"
            "subsection Nonlinear solver\n set Absolute tolerance = 1e-12\n"
            " set Relative tolerance = 1e-10\nend\n"
            "subsection Linear solver\n set Relative tolerance = 1e-10\nend\n";
      const auto parameters
        = testing::parameters_from_text(text, "column_pipe_flow");

      const testing::SteadyFlow<3> run(parameters);
      const auto                  &flow = run.flow;

      const double volume = GridTools::volume(run.tria, flow.get_mapping());

      FunctionParser<3> exact(4);
      exact.initialize("x,y,z", "0; 0; " + profile + "; " + pressure, {});
      const auto error
        = [&](const unsigned int first, const unsigned int last) {
            return testing::l2_error(flow, exact, first, last, 4);
          };
      velocity_error.push_back(error(0, 3));
      pressure_error.push_back(error(3, 4));
      const auto at = [&](const double z) {
        return fluid::pressure_at(flow, Point<3>(0.5, 0.5, z));
      };
      const double drop = at(0.5) - at(1.5), exact_drop = 8. * mu * U / (R * R);
      const double volume_error = volume / (M_PI * R * R * L) - 1.;
      std::cout << "refinements " << refinements << "  cells "
                << run.tria.n_global_active_cells() << "  DoFs "
                << flow.n_dofs() << "  Newton "
                << run.stats.nonlinear_iterations << "  volume error "
                << volume_error << "  ||u-u_h|| " << velocity_error.back()
                << "  ||p-p_h|| " << pressure_error.back() << "  pressure drop "
                << drop << " (exact " << exact_drop << ")" << std::endl;
      if (refinements == 3)
        {
          checker.check(std::abs(volume_error) < 1e-3,
                        "the column's volume within 1e-3");
          checker.check(std::abs(drop / exact_drop - 1.) < 0.005,
                        "the pressure drop within 0.5 %");
        }
    }

  const double rate_u = testing::last_rate(velocity_error);
  const double rate_p = testing::last_rate(pressure_error);
  std::cout << "observed rates: velocity " << rate_u << ", pressure " << rate_p
            << std::endl;
  checker.check(rate_u > 2.5, "velocity L2 rate above 2.5");
  checker.check(rate_p > 1.5, "pressure L2 rate above 1.5");
  return checker.exit_code();
}
