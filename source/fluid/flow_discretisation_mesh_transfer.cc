// Remeshing of the flow solver: the velocity carried from the old vertex
// positions to new ones by interpolation (NavierStokes::
// transfer_to_moved_mesh), for mesh moves too large for the ALE term.

#include <particulate/fluid/flow_discretisation.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <array>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>


namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /**
       * The locally owned cell of the current (old) mesh that holds @p p,
       * and @p p's reference coordinates there, found by walking from
       * @p start across faces towards @p p: at each cell the face whose
       * reference coordinate @p p exceeds most (or, where the inverse
       * mapping fails, the neighbour whose centre is nearest to @p p).
       * A remeshing moves a node by a few cells, so the walk is short; it
       * gives up (nullopt) when it reaches a cell of another rank or the
       * boundary, or after @p max_steps, and the caller asks the other
       * ranks. Why not GridTools' searches: for a point on a vertex, edge or
       * face deal.II 9.4 collects the cells around it by a loop over all
       * cells, which made the transfer quadratic in the mesh size
       * (doc/performance.md).
       */
      template <int dim>
      std::optional<std::pair<typename Triangulation<dim>::active_cell_iterator,
                              Point<dim>>>
      walk_to_point(const Mapping<dim>                               &mapping,
                    typename Triangulation<dim>::active_cell_iterator cell,
                    const Point<dim>                                 &p,
                    const unsigned int                                max_steps)
      {
        for (unsigned int step = 0; step < max_steps; ++step)
          {
            if (!cell->is_locally_owned())
              return std::nullopt;
            unsigned int exit_face = numbers::invalid_unsigned_int;
            try
              {
                const Point<dim> unit
                  = mapping.transform_real_to_unit_cell(cell, p);
                if (GeometryInfo<dim>::is_inside_unit_cell(unit, 1e-10))
                  return std::make_pair(cell, unit);
                // faces 2d and 2d+1 bound reference coordinate d below 0 and
                // above 1
                double worst = 0.;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    if (-unit[d] > worst)
                      worst = -unit[d], exit_face = 2 * d;
                    if (unit[d] - 1. > worst)
                      worst = unit[d] - 1., exit_face = 2 * d + 1;
                  }
              }
            catch (const typename Mapping<dim>::ExcTransformationFailed &)
              {
                double nearest = std::numeric_limits<double>::max();
                for (const unsigned int f : cell->face_indices())
                  if (!cell->at_boundary(f)
                      && cell->neighbor(f)->center().distance(p) < nearest)
                    {
                      nearest   = cell->neighbor(f)->center().distance(p);
                      exit_face = f;
                    }
              }
            if (exit_face == numbers::invalid_unsigned_int
                || cell->at_boundary(exit_face)
                || !cell->neighbor(exit_face)->is_active())
              return std::nullopt;
            cell = cell->neighbor(exit_face);
          }
        return std::nullopt;
      }
    } // namespace

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
      std::vector<typename Triangulation<dim>::active_cell_iterator> starts;
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

      // The old velocity at the new nodes: in this rank's cells by a walk
      // from the node's own cell, which finds nearly all of them; the rest
      // (nodes that moved into cells of another rank) through
      // RemotePointEvaluation.
      const auto                          &velocity_fe = fe.base_element(0);
      std::vector<Tensor<1, dim>>          carried_values(points.size());
      std::vector<unsigned int>            remote;
      std::vector<Point<dim>>              remote_points;
      std::vector<types::global_dof_index> old_dofs(fe.n_dofs_per_cell());
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          const auto found
            = walk_to_point<dim>(mapping, starts[i], points[i], 64);
          if (!found)
            {
              remote.push_back(i);
              remote_points.push_back(points[i]);
              continue;
            }
          typename DoFHandler<dim>::active_cell_iterator(&triangulation,
                                                         found->first->level(),
                                                         found->first->index(),
                                                         &dof_handler)
            ->get_dof_indices(old_dofs);
          Tensor<1, dim> u;
          for (unsigned int k = 0; k < velocity_fe.n_dofs_per_cell(); ++k)
            {
              const double phi = velocity_fe.shape_value(k, found->second);
              for (unsigned int c = 0; c < dim; ++c)
                u[c]
                  += phi
                     * solution(old_dofs[fe.component_to_system_index(c, k)]);
            }
          carried_values[i] = u;
        }

      Utilities::MPI::RemotePointEvaluation<dim> evaluation;
      evaluation.reinit(remote_points, triangulation, mapping);
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

      // The new mesh, with the carried velocity (for the nodes located
      // remotely, the mean where a node lies on the faces of several old
      // cells; the velocity is continuous, so they agree to round-off).
      move_vertices();
      BlockVector carried(owned_partitioning, communicator);
      carried                               = solution;
      const std::vector<unsigned int> &ptrs = evaluation.get_point_ptrs();
      for (unsigned int r = 0; r < remote.size(); ++r)
        {
          Tensor<1, dim> mean;
          for (unsigned int j = ptrs[r]; j < ptrs[r + 1]; ++j)
            mean += values[j];
          carried_values[remote[r]] = mean / double(ptrs[r + 1] - ptrs[r]);
        }
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
