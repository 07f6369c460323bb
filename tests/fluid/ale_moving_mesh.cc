// The ALE term of fluid::NavierStokes::move_mesh(): Poiseuille flow
// u = (4 U y (1 - y), 0) in the channel [0, 2] x [0, 1] is a steady exact
// solution whatever the mesh does. The interior vertices swing up and down,
// y += a sin(2 pi t / T) sin(pi x / 2) sin(pi y) with a = 0.8 h (walls and
// ends stay put), so every velocity node crosses the profile. With the mesh
// velocity in the convection the solution stays the profile up to the
// error of the moving-mesh steps, which falls with the time step; leaving
// it out (the nodal values then simply ride along with their nodes) puts an
// error of about |w| k |du/dy| into every step that does not, which the
// test measures too and requires to be at least five times larger.

#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <cmath>
#include <iostream>

#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  /** Largest nodal velocity error against the profile after one period
   *  in steps of @p k (the mesh is then back at rest). */
  double
  run(const bool with_mesh_velocity, const double k)
  {
    const std::string text
      = "subsection Mesh\n set Type = hyper rectangle\n"
        " set Upper corner = 2, 1\n set Subdivisions = 4, 2\n"
        " set Refinements = 3\nend\n"
        "subsection Time\n set Scheme = fractional-step theta\nend\n"
        "subsection Fluid\n set Density = 1\n set Dynamic viscosity = 0.01\n"
        "end\n"
        "subsection Initial condition\n set Velocity = 4*y*(1-y); 0\nend\n"
        "subsection Boundary conditions\n set No-slip = 2, 3\n"
        " set Dirichlet velocity = 0, 1\n set Velocity = 4*y*(1-y); 0\nend\n"
        "subsection Nonlinear solver\n set Absolute tolerance = 1e-12\n"
        " set Relative tolerance = 1e-10\nend\n"
        "subsection Linear solver\n set Relative tolerance = 1e-10\nend\n";
    const auto parameters
      = testing::parameters_from_text(text, "ale_moving_mesh");
    parallel::fullydistributed::Triangulation<2> tria(MPI_COMM_WORLD);
    core::create_mesh(parameters.mesh, tria);
    const std::vector<Point<2>> rest = tria.get_vertices();
    TimerOutput                 timer(MPI_COMM_WORLD,
                      std::cout,
                      TimerOutput::never,
                      TimerOutput::wall_times);
    fluid::NavierStokes<2>      flow(parameters.fluid, tria, timer);
    flow.setup_dofs();
    flow.set_initial_condition(0.);

    const double       h = 1. / 16., a = 0.8 * h, period = 1.;
    const unsigned int n_steps = std::lround(period / k);
    const auto         zero    = flow.make_ghosted_vector();
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        const double t = (step + 1) * k;
        flow.move_mesh(
          [&]() {
            for (const auto &cell : tria.cell_iterators())
              for (const auto v : cell->vertex_indices())
                {
                  Point<2> x = rest[cell->vertex_index(v)];
                  x[1] += a * std::sin(2. * M_PI * t / period)
                          * std::sin(M_PI * x[0] / 2.) * std::sin(M_PI * x[1]);
                  cell->vertex(v) = x;
                }
          },
          k);
        if (!with_mesh_velocity)
          flow.set_mesh_velocity(zero);
        flow.advance(step * k,
                     k,
                     core::TimeParameters::Scheme::fractional_step_theta);
      }
    FunctionParser<2> exact(2);
    exact.initialize("x, y", "4*y*(1-y); 0", {});
    auto reference = flow.make_owned_vector();
    flow.interpolate_velocity(exact, reference);
    reference.block(0) -= flow.get_solution().block(0);
    return reference.block(0).linfty_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const double with_1 = run(true, 0.05), with_2 = run(true, 0.025),
               without = run(false, 0.025);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "largest nodal error after one period (U = 1): with mesh "
                 "velocity "
              << with_1 << " (k = 0.05), " << with_2 << " (k = 0.025); without "
              << without << " (k = 0.025)\n";
  // Back at rest the mesh is the undistorted one, on which Q2 holds the
  // profile exactly: what is left is the error of the moving-mesh steps,
  // first order in k (the mesh velocity is constant over a step).
  checker.check(with_2 < 0.6 * with_1,
                "the moving-mesh error falls at least at first order in k");
  checker.check(without > 5. * with_2,
                "leaving the mesh velocity out is at least five times worse");
  return checker.exit_code();
}
