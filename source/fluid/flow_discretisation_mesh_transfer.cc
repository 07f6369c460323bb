// Remeshing of the flow solver: the velocity carried from the old vertex
// positions to new ones by interpolation (NavierStokes::
// transfer_to_moved_mesh), for mesh moves too large for the ALE term.

#include <particulate/fluid/flow_discretisation.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <array>

#include "old_mesh_velocity.h"


namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    void
    FlowDiscretisation<dim>::transfer_to_moved_mesh(
      const std::function<void()> &move_vertices)
    {
      TimerOutput::Scope scope(timer, "fluid: mesh transfer");

      // The new positions of the velocity nodes of this rank's DoFs: move
      // the mesh, record them, and move it back for the evaluation.
      const std::vector<Point<dim>> old_vertices = triangulation.get_vertices();
      move_vertices();
      const Quadrature<dim> nodes(fe.base_element(0).get_unit_support_points());
      FEValues<dim> at_nodes(mapping, fe, nodes, update_quadrature_points);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      const IndexSet         &owned = dof_handler.locally_owned_dofs();
      std::vector<bool>       recorded(owned.n_elements(), false);
      std::vector<Point<dim>> points;
      std::vector<std::array<types::global_dof_index, dim>> node_dofs;
      /// the cell each node was recorded on: where its walk starts
      std::vector<typename DoFHandler<dim>::active_cell_iterator> starts;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            at_nodes.reinit(cell);
            cell->get_dof_indices(dof_indices);
            for (unsigned int k = 0; k < nodes.size(); ++k)
              {
                const auto x = dof_indices[fe.component_to_system_index(0, k)];
                if (!owned.is_element(x) || recorded[owned.index_within_set(x)])
                  continue;
                recorded[owned.index_within_set(x)] = true;
                points.push_back(at_nodes.quadrature_point(k));
                starts.push_back(cell);
                std::array<types::global_dof_index, dim> dofs;
                for (unsigned int c = 0; c < dim; ++c)
                  dofs[c] = dof_indices[fe.component_to_system_index(c, k)];
                node_dofs.push_back(dofs);
              }
          }
      for (const auto &cell : triangulation.cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = old_vertices[cell->vertex_index(v)];

      // The old velocity at the new nodes, each found from the cell its
      // node sits on.
      const std::vector<Tensor<1, dim>> carried_values
        = OldMeshVelocity<dim>(dof_handler, mapping, fe, solution)
            .at(points, starts);

      // The new mesh, with the carried velocity.
      move_vertices();
      BlockVector carried(owned_partitioning, communicator);
      carried = solution;
      for (unsigned int i = 0; i < points.size(); ++i)
        for (unsigned int c = 0; c < dim; ++c)
          carried(node_dofs[i][c]) = carried_values[i][c];
      carried.compress(VectorOperation::insert);
      solution          = carried;
      old_solution      = solution;
      mesh_velocity     = 0.;
      has_mesh_velocity = true;
      assemble_geometric_matrices();
    }

    template void
    FlowDiscretisation<2>::transfer_to_moved_mesh(
      const std::function<void()> &);
    template void
    FlowDiscretisation<3>::transfer_to_moved_mesh(
      const std::function<void()> &);
  } // namespace fluid
} // namespace particulate
