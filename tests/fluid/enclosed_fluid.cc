// Fluid walled off from the flow (source/fluid/enclosed_fluid.cc): on the
// unit square in 8 x 8 cells, the velocities of a ring of cells around the
// middle 2 x 2 block are fixed, as a body's covered nodes would be.
// - a closed ring: one pocket, the block, and one pressure decoupled there,
//   a constant mode (on two ranks the block and the ring straddle the
//   partition boundary, so the pocket must be joined across it);
// - the ring with one cell left out: the block's free nodes reach the
//   outside through that cell, no pocket;
// - nothing fixed: no pocket.

#include "../../source/fluid/enclosed_fluid.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  enum class Ring
  {
    closed,
    open,
    none
  };

  /** Whether cell (i, j) of the 8 x 8 grid has its velocities fixed. */
  bool
  fixed_cell(const Ring ring, const int i, const int j)
  {
    if (ring == Ring::none || i < 2 || i > 5 || j < 2 || j > 5)
      return false;
    if (ring == Ring::open && i == 5 && j == 3)
      return false;
    return i == 2 || i == 5 || j == 2 || j == 5;
  }

  struct Found
  {
    unsigned int n_pockets = 0, n_pinned = 0, n_pinned_in_block = 0,
                 n_pinned_constant = 0;
  };

  Found
  find(const Ring ring)
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_cube(tria, 8, 0., 1.);
    const FESystem<2> fe(FE_Q<2>(2), 2, FE_DGP<2>(1), 1);
    DoFHandler<2>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);

    const auto cell_index = [](const auto &cell) {
      return std::make_pair(int(cell->center()[0] * 8),
                            int(cell->center()[1] * 8));
    };
    AffineConstraints<double> constraints(
      DoFTools::extract_locally_relevant_dofs(dof_handler));
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          const auto [i, j] = cell_index(cell);
          if (!fixed_cell(ring, i, j))
            continue;
          cell->get_dof_indices(dofs);
          for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
            if (fe.system_to_component_index(k).first < 2
                && !constraints.is_constrained(dofs[k]))
              constraints.add_line(dofs[k]);
        }
    constraints.close();

    const fluid::EnclosedFluid enclosed
      = fluid::find_enclosed_fluid(dof_handler,
                                   constraints,
                                   {},
                                   MPI_COMM_WORLD);
    Found found;
    found.n_pockets = enclosed.n_pockets;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          const auto [i, j] = cell_index(cell);
          for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
            if (std::binary_search(enclosed.pinned_pressures.begin(),
                                   enclosed.pinned_pressures.end(),
                                   dofs[k]))
              {
                ++found.n_pinned;
                found.n_pinned_in_block
                  += (i == 3 || i == 4) && (j == 3 || j == 4);
                found.n_pinned_constant
                  += fe.system_to_component_index(k) == std::make_pair(2u, 0u);
              }
        }
    found.n_pinned = Utilities::MPI::sum(found.n_pinned, MPI_COMM_WORLD);
    found.n_pinned_in_block
      = Utilities::MPI::sum(found.n_pinned_in_block, MPI_COMM_WORLD);
    found.n_pinned_constant
      = Utilities::MPI::sum(found.n_pinned_constant, MPI_COMM_WORLD);
    return found;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const Found                      closed = find(Ring::closed);
  checker.check(closed.n_pockets == 1 && closed.n_pinned == 1
                  && closed.n_pinned_in_block == 1
                  && closed.n_pinned_constant == 1,
                "closed ring: one pocket, the constant pressure of one of "
                "its cells decoupled (pockets "
                  + std::to_string(closed.n_pockets) + ", pinned "
                  + std::to_string(closed.n_pinned) + ", in the block "
                  + std::to_string(closed.n_pinned_in_block) + ")");
  const Found open = find(Ring::open);
  checker.check(open.n_pockets == 0 && open.n_pinned == 0,
                "ring with a gap: no pocket (found "
                  + std::to_string(open.n_pockets) + ")");
  const Found none = find(Ring::none);
  checker.check(none.n_pockets == 0 && none.n_pinned == 0,
                "nothing fixed: no pocket (found "
                  + std::to_string(none.n_pockets) + ")");
  return checker.exit_code();
}
