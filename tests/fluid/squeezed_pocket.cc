// Prescribed velocities that squeeze a pocket of fluid, as bodies moving
// towards each other around it do (source/fluid/enclosed_fluid.cc): in a
// closed box of 8 x 8 cells the velocities of a ring of cells around the
// middle 2 x 2 block are prescribed, pointing into the block on the ring's
// inner edge and zero elsewhere. No velocity field is divergence-free in
// the block; with the pocket's pressure decoupled in one cell the step
// converges (without it the linear solver stalls), and the fluid outside
// the ring stays at rest. On two ranks the block straddles the partition
// boundary.
//
// The same without a pocket: the block itself prescribed, its velocities
// pointing out of it, is a source in the closed box. The fixed velocities
// carry a net flux into the flow, which no velocity field could take up;
// with that part removed from the continuity residual along the flow's
// undetermined pressure mode (source/fluid/flow_pressure_mode.h) the step
// converges (without it the linear solver stalls).

#include <particulate/core/mesh.h>
#include <particulate/fluid/navier_stokes.h>
#include <particulate/fluid/solver_failure.h>

#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <functional>
#include <iostream>

#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  /** Cell (i, j) of the 8 x 8 grid that holds @p c. */
  std::pair<int, int>
  cell_of(const Point<2> &c)
  {
    return {int(c[0] * 8), int(c[1] * 8)};
  }

  bool
  in_ring(const Point<2> &c)
  {
    const auto [i, j] = cell_of(c);
    return i >= 2 && i <= 5 && j >= 2 && j <= 5
           && (i == 2 || i == 5 || j == 2 || j == 5);
  }

  bool
  in_block(const Point<2> &c)
  {
    const auto [i, j] = cell_of(c);
    return i >= 3 && i <= 4 && j >= 3 && j <= 4;
  }

  /** Out of the box's centre. */
  Tensor<1, 2>
  spreading(const Point<2> &x)
  {
    return x - Point<2>(0.5, 0.5);
  }

  /** On the block's closure: towards the box's centre; zero elsewhere. */
  Tensor<1, 2>
  squeezing(const Point<2> &x)
  {
    Tensor<1, 2> u;
    if (std::abs(x[0] - 0.5) <= 0.125 + 1e-12
        && std::abs(x[1] - 0.5) <= 0.125 + 1e-12)
      u = Point<2>(0.5, 0.5) - x;
    return u;
  }

  struct Outcome
  {
    bool         converged = true;
    unsigned int pockets   = 0;
    /// largest speed in the cells outside the middle 4 x 4
    double largest_outside = 0.;
  };

  /** One backward-Euler step with the velocities of the cells that
   *  @p prescribed selects set to @p velocity. */
  Outcome
  step(const std::function<bool(const Point<2> &)>         &prescribed,
       const std::function<Tensor<1, 2>(const Point<2> &)> &velocity)
  {
    const auto parameters = testing::parameters_from_text(
      "subsection Mesh\n set Type = hyper rectangle\n"
      " set Subdivisions = 8, 8\n set Refinements = 0\nend\n"
      "subsection Fluid\n set Density = 1\n set Dynamic viscosity = 0.1\nend\n"
      "subsection Boundary conditions\n set No-slip = 0, 1, 2, 3\nend\n"
      "subsection Linear solver\n set Maximum iterations = 300\nend\n",
      "squeezed_pocket");
    parallel::fullydistributed::Triangulation<2> tria(MPI_COMM_WORLD);
    core::create_mesh(parameters.mesh, tria);
    TimerOutput            timer(MPI_COMM_WORLD,
                      std::cout,
                      TimerOutput::never,
                      TimerOutput::wall_times);
    fluid::NavierStokes<2> flow(parameters.fluid, tria, timer);
    flow.setup_dofs();
    flow.set_initial_condition(0.);

    const auto         &fe = flow.get_fe();
    const Quadrature<2> support(fe.base_element(0).get_unit_support_points());
    FEValues<2>         fe_values(flow.get_mapping(),
                          fe,
                          support,
                          update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<std::pair<types::global_dof_index, double>> values;
    for (const auto &cell : flow.get_dof_handler().active_cell_iterators())
      if (!cell->is_artificial() && prescribed(cell->center()))
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto [component, node] = fe.system_to_component_index(i);
              if (component < 2)
                values.emplace_back(dofs[i],
                                    velocity(fe_values.quadrature_point(
                                      node))[component]);
            }
        }
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    flow.set_fictitious_boundary_values(values);

    Outcome outcome;
    try
      {
        flow.advance(0., 0.01, core::TimeParameters::Scheme::backward_euler);
      }
    catch (const fluid::SolverFailure &failure)
      {
        outcome.converged = false;
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::cout << failure.what() << '\n';
      }
    outcome.pockets = flow.n_enclosed_pockets();
    for (const auto &cell : flow.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Point<2> c = cell->center();
          if (std::abs(c[0] - 0.5) < 0.25 && std::abs(c[1] - 0.5) < 0.25)
            continue;
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            if (fe.system_to_component_index(i).first < 2)
              outcome.largest_outside
                = std::max(outcome.largest_outside,
                           std::abs(flow.get_solution()[dofs[i]]));
        }
    outcome.largest_outside
      = Utilities::MPI::max(outcome.largest_outside, MPI_COMM_WORLD);
    return outcome;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;

  const Outcome squeezed = step(in_ring, squeezing);
  checker.check(squeezed.pockets == 1,
                "one pocket found (" + std::to_string(squeezed.pockets) + ")");
  checker.check(squeezed.converged, "the step converges");
  checker.check(squeezed.largest_outside < 1e-6,
                "the fluid outside the ring stays at rest (largest speed "
                  + std::to_string(squeezed.largest_outside) + ")");

  const Outcome source = step(in_block, spreading);
  checker.check(source.pockets == 0,
                "a source: no pocket (" + std::to_string(source.pockets) + ")");
  checker.check(source.converged, "a source: the step converges");
  return checker.exit_code();
}
