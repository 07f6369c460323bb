// Remeshing of the flow solver: the velocity carried from the old vertex
// positions to new ones by interpolation (NavierStokes::
// transfer_to_moved_mesh), for mesh moves too large for the ALE term.

#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <array>
#include <stdexcept>
#include <string>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    void
    NavierStokes<dim>::transfer_to_moved_mesh(
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
                std::array<types::global_dof_index, dim> dofs;
                for (unsigned int c = 0; c < dim; ++c)
                  dofs[c] = dof_indices[fe.component_to_system_index(c, k)];
                node_dofs.push_back(dofs);
              }
          }
      for (const auto &cell : triangulation.cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = old_vertices[cell->vertex_index(v)];

      // The old velocity at the new nodes, wherever they are now.
      Utilities::MPI::RemotePointEvaluation<dim> evaluation;
      evaluation.reinit(points, triangulation, mapping);
      if (!evaluation.all_points_found())
        throw std::runtime_error(
          "Moving the mesh put velocity nodes outside the old mesh, so the "
          "flow cannot be carried over: the boundary vertices must stay on "
          "the boundary.");
      const FEValuesExtractors::Vector velocities(0);
      std::vector<Tensor<1, dim>>      values, buffer;
      evaluation.template evaluate_and_process<Tensor<1, dim>>(
        values,
        buffer,
        [&](const ArrayView<Tensor<1, dim>> &out,
            const typename Utilities::MPI::RemotePointEvaluation<dim>::CellData
              &cells) {
          std::vector<Tensor<1, dim>> u;
          for (unsigned int c = 0; c < cells.cells.size(); ++c)
            {
              const unsigned int begin = cells.reference_point_ptrs[c],
                                 end   = cells.reference_point_ptrs[c + 1];
              const Quadrature<dim> unit_points(std::vector<Point<dim>>(
                cells.reference_point_values.begin() + begin,
                cells.reference_point_values.begin() + end));
              FEValues<dim> fe_values(mapping, fe, unit_points, update_values);
              fe_values.reinit(typename DoFHandler<dim>::active_cell_iterator(
                &triangulation,
                cells.cells[c].first,
                cells.cells[c].second,
                &dof_handler));
              u.resize(end - begin);
              fe_values[velocities].get_function_values(solution, u);
              for (unsigned int q = 0; q < u.size(); ++q)
                out[begin + q] = u[q];
            }
        });

      // The new mesh, with the carried velocity (the mean where a node lies
      // on the faces of several old cells).
      move_vertices();
      BlockVector carried(owned_partitioning, communicator);
      carried                               = solution;
      const std::vector<unsigned int> &ptrs = evaluation.get_point_ptrs();
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          Tensor<1, dim> mean;
          for (unsigned int j = ptrs[i]; j < ptrs[i + 1]; ++j)
            mean += values[j];
          mean /= double(ptrs[i + 1] - ptrs[i]);
          for (unsigned int c = 0; c < dim; ++c)
            carried(node_dofs[i][c]) = mean[c];
        }
      carried.compress(VectorOperation::insert);
      solution              = carried;
      old_solution          = solution;
      has_previous_solution = false;
      mesh_velocity         = 0.;
      has_mesh_velocity     = true;
      assemble_geometric_matrices();
      if (velocity_multigrid)
        refresh_multigrid_geometry();
    }

    template void
    NavierStokes<2>::transfer_to_moved_mesh(const std::function<void()> &);
    template void
    NavierStokes<3>::transfer_to_moved_mesh(const std::function<void()> &);
  } // namespace fluid
} // namespace particulate
