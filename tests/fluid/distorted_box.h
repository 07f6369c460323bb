#ifndef particulate_tests_fluid_distorted_box_h
#define particulate_tests_fluid_distorted_box_h

// The set-up two matrix tests share: a distorted box, fully distributed
// over the ranks, with Q2^dim x P1disc DoFs numbered velocities first, and
// the positions of the velocity nodes.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <map>
#include <vector>

namespace particulate {
  namespace testing {
    /** The unit box of @p n^dim cells, its vertices moved at random by up
     *  to 0.2 of a cell (no symmetry that could hide a missing entry;
     *  @p seed fixes them), distributed over the ranks of @p tria. */
    template <int dim>
    void
    make_distorted_box(
      dealii::parallel::fullydistributed::Triangulation<dim> &tria,
      const unsigned int                                      n,
      const unsigned int                                      seed)
    {
      const MPI_Comm             comm = tria.get_communicator();
      dealii::Triangulation<dim> serial;
      dealii::GridGenerator::subdivided_hyper_cube(serial, n, 0., 1.);
      dealii::GridTools::distort_random(0.2, serial, false, seed);
      dealii::GridTools::partition_triangulation(
        dealii::Utilities::MPI::n_mpi_processes(comm),
        serial);
      tria.create_triangulation(
        dealii::TriangulationDescription::Utilities::
          create_description_from_triangulation(serial, comm));
    }

    /** Distribute the DoFs of the Q2^dim x P1disc element @p fe, velocities
     *  first (block 0), then pressures (block 1); returns the number of
     *  velocity DoFs. */
    template <int dim>
    dealii::types::global_dof_index
    distribute_velocities_first(dealii::DoFHandler<dim>     &dof_handler,
                                const dealii::FESystem<dim> &fe)
    {
      dof_handler.distribute_dofs(fe);
      std::vector<unsigned int> blocks(dim + 1, 0);
      blocks[dim] = 1;
      dealii::DoFRenumbering::component_wise(dof_handler, blocks);
      return dealii::DoFTools::count_dofs_per_fe_block(dof_handler, blocks)[0];
    }

    /** Where the velocity nodes of every cell that is not artificial lie
     *  (FE_DGP has no support points, so map_dofs_to_support_points()
     *  cannot take the whole element). */
    template <int dim>
    std::map<dealii::types::global_dof_index, dealii::Point<dim>>
    velocity_node_positions(const dealii::Mapping<dim>    &mapping,
                            const dealii::DoFHandler<dim> &dof_handler)
    {
      const auto &fe          = dof_handler.get_fe();
      const auto &unit_points = fe.base_element(0).get_unit_support_points();
      std::map<dealii::types::global_dof_index, dealii::Point<dim>> points;
      std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const auto [component, index] = fe.system_to_component_index(i);
                if (component < dim)
                  points[dofs[i]]
                    = mapping.transform_unit_to_real_cell(cell,
                                                          unit_points[index]);
              }
          }
      return points;
    }
  } // namespace testing
} // namespace particulate

#endif
