// fluid::NavierStokes::transfer_to_moved_mesh() carries the velocity to a
// mesh whose vertices moved by more than a cell: a velocity field of degree
// at most 2 in x and y is biquadratic in the reference coordinates of any
// bilinear cell, so Q2 holds it exactly on the old and on the moved mesh,
// and it must arrive at every node of the moved mesh with its exact value
// there (to round-off) - on 2 and on 3 ranks, where many new nodes lie in
// cells of another rank (found by handing the walk to the owner of the
// ghost cell it reached, or by the global search). The mesh velocity of the
// next step is zero.

#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <iostream>

#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  /** Largest nodal error of the carried velocity against @p field. */
  double
  carried_error(const std::string &field, testing::Checker &checker)
  {
    const std::string text
      = "subsection Mesh\n set Type = hyper rectangle\n"
        " set Upper corner = 2, 1\n set Subdivisions = 4, 2\n"
        " set Refinements = 3\nend\n"
        "subsection Initial condition\n set Velocity = "
        + field + "\nend\n";
    const auto parameters
      = testing::parameters_from_text(text, "mesh_transfer");
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

    // interior vertices move by up to 0.15 (2.4 cells of h = 1/16); the
    // boundary stays put
    flow.transfer_to_moved_mesh([&]() {
      for (const auto &cell : tria.cell_iterators())
        for (const auto v : cell->vertex_indices())
          {
            Point<2>     x = rest[cell->vertex_index(v)];
            const double s = std::sin(M_PI * x[0] / 2.) * std::sin(M_PI * x[1]);
            x[0] += 0.15 * s;
            x[1] += 0.05 * s;
            cell->vertex(v) = x;
          }
    });

    FunctionParser<2> exact(2);
    exact.initialize("x, y", field, {});
    const auto         &fe = flow.get_fe();
    const Quadrature<2> nodes(fe.base_element(0).get_unit_support_points());
    FEValues<2>         fe_values(flow.get_mapping(),
                          fe,
                          nodes,
                          update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    const auto                          &u     = flow.get_solution();
    double                               error = 0.;
    for (const auto &cell : flow.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int k = 0; k < nodes.size(); ++k)
            for (unsigned int c = 0; c < 2; ++c)
              error
                = std::max(error,
                           std::abs(
                             u(dofs[fe.component_to_system_index(c, k)])
                             - exact.value(fe_values.quadrature_point(k), c)));
        }
    error = Utilities::MPI::max(error, MPI_COMM_WORLD);

    const auto *w = flow.get_mesh_velocity();
    checker.check(w && w->linfty_norm() == 0.,
                  field + ": no mesh velocity in the next step");
    return error;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  for (const std::string field :
       {"1 + 2*x - y; 0.5*x + 3*y", "4*y*(1-y) + x*y; x*(2-x) - y*y"})
    {
      const double error = carried_error(field, checker);
      char         what[200];
      std::snprintf(what,
                    sizeof(what),
                    "%s carried exactly: largest nodal error %.2e",
                    field.c_str(),
                    error);
      checker.check(error < 1e-12, what);
    }
  return checker.exit_code();
}
