#include "old_mesh_velocity.h"

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/cell_id.h>

#include <limits>
#include <map>
#include <stdexcept>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /** A walk handed to the owner of the ghost cell it reached. */
      template <int dim>
      struct HandedWalk
      {
        CellId::binary_type cell;
        Point<dim>          point;

        template <class Archive>
        void
        serialize(Archive &archive, const unsigned int)
        {
          for (auto &word : cell)
            archive &word;
          archive &point;
        }
      };

      /** What the owner found: per walk, 1 and the velocity, or 0 and
       *  zeros. */
      using HandOffAnswer = std::vector<double>;
    } // namespace



    template <int dim>
    OldMeshVelocity<dim>::OldMeshVelocity(
      const DoFHandler<dim>                    &dofs,
      const Mapping<dim>                       &mapping,
      const FESystem<dim>                      &fe,
      const TrilinosWrappers::MPI::BlockVector &solution)
      : dofs(dofs)
      , mapping(mapping)
      , fe(fe)
      , solution(solution)
    {}



    /*
     * At each cell the walk leaves by the face whose reference coordinate
     * the point exceeds most, or, where the inverse mapping fails, towards
     * the neighbour whose centre is nearest to the point.
     */
    template <int dim>
    typename OldMeshVelocity<dim>::WalkEnd
    OldMeshVelocity<dim>::walk(ActiveCell cell, const Point<dim> &p) const
    {
      for (unsigned int step = 0; step < 64; ++step)
        {
          if (!cell->is_locally_owned())
            return {cell, false, Point<dim>()};
          unsigned int exit_face = numbers::invalid_unsigned_int;
          try
            {
              const Point<dim> unit
                = mapping.transform_real_to_unit_cell(cell, p);
              if (GeometryInfo<dim>::is_inside_unit_cell(unit, 1e-10))
                return {cell, true, unit};
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
            return {cell, false, Point<dim>()};
          cell = cell->neighbor(exit_face);
        }
      return {cell, false, Point<dim>()};
    }



    template <int dim>
    Tensor<1, dim>
    OldMeshVelocity<dim>::evaluate(const ActiveCell &cell,
                                   const Point<dim> &unit) const
    {
      const auto                          &velocity_fe = fe.base_element(0);
      std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
      cell->get_dof_indices(cell_dofs);
      Tensor<1, dim> u;
      for (unsigned int k = 0; k < velocity_fe.n_dofs_per_cell(); ++k)
        {
          const double phi = velocity_fe.shape_value(k, unit);
          for (unsigned int c = 0; c < dim; ++c)
            u[c]
              += phi * solution(cell_dofs[fe.component_to_system_index(c, k)]);
        }
      return u;
    }



    template <int dim>
    std::vector<Tensor<1, dim>>
    OldMeshVelocity<dim>::at(const std::vector<Point<dim>> &points,
                             const std::vector<ActiveCell> &starts) const
    {
      std::vector<Tensor<1, dim>> values(points.size());
      std::vector<unsigned int>   at_ghosts, lost;
      std::vector<ActiveCell>     ghosts;
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          const WalkEnd end = walk(starts[i], points[i]);
          if (end.found)
            values[i] = evaluate(end.cell, end.unit);
          else if (end.cell->is_ghost())
            {
              at_ghosts.push_back(i);
              ghosts.push_back(end.cell);
            }
          else
            lost.push_back(i);
        }
      hand_off(points, at_ghosts, ghosts, values, lost);
      search_globally(points, lost, values);
      return values;
    }



    template <int dim>
    void
    OldMeshVelocity<dim>::hand_off(const std::vector<Point<dim>>   &points,
                                   const std::vector<unsigned int> &indices,
                                   const std::vector<ActiveCell>   &ghosts,
                                   std::vector<Tensor<1, dim>>     &values,
                                   std::vector<unsigned int>       &lost) const
    {
      std::map<unsigned int, std::vector<HandedWalk<dim>>> walks;
      std::map<unsigned int, std::vector<unsigned int>>    sent;
      for (unsigned int j = 0; j < indices.size(); ++j)
        {
          const unsigned int owner = ghosts[j]->subdomain_id();
          walks[owner].push_back(
            {ghosts[j]->id().template to_binary<dim>(), points[indices[j]]});
          sent[owner].push_back(indices[j]);
        }
      const MPI_Comm comm     = dofs.get_triangulation().get_communicator();
      const auto     received = Utilities::MPI::some_to_some(comm, walks);

      std::map<unsigned int, HandOffAnswer> answers;
      for (const auto &[rank, handed] : received)
        {
          HandOffAnswer &answer = answers[rank];
          for (const HandedWalk<dim> &w : handed)
            {
              const auto cell
                = dofs.get_triangulation().create_cell_iterator(CellId(w.cell));
              const ActiveCell     start(&dofs.get_triangulation(),
                                     cell->level(),
                                     cell->index(),
                                     &dofs);
              const WalkEnd        end = walk(start, w.point);
              const Tensor<1, dim> u
                = end.found ? evaluate(end.cell, end.unit) : Tensor<1, dim>();
              answer.push_back(end.found ? 1. : 0.);
              for (unsigned int c = 0; c < dim; ++c)
                answer.push_back(u[c]);
            }
        }
      const auto returned = Utilities::MPI::some_to_some(comm, answers);

      for (const auto &[rank, answer] : returned)
        {
          const std::vector<unsigned int> &asked = sent.at(rank);
          for (unsigned int j = 0; j < asked.size(); ++j)
            {
              const double *entry = &answer[j * (dim + 1)];
              if (entry[0] == 0.)
                {
                  lost.push_back(asked[j]);
                  continue;
                }
              for (unsigned int c = 0; c < dim; ++c)
                values[asked[j]][c] = entry[1 + c];
            }
        }
    }



    template <int dim>
    void
    OldMeshVelocity<dim>::search_globally(
      const std::vector<Point<dim>>   &points,
      const std::vector<unsigned int> &indices,
      std::vector<Tensor<1, dim>>     &values) const
    {
      std::vector<Point<dim>> remote_points;
      for (const unsigned int i : indices)
        remote_points.push_back(points[i]);
      const auto &tria = dofs.get_triangulation();
      Utilities::MPI::RemotePointEvaluation<dim> evaluation;
      evaluation.reinit(remote_points, tria, mapping);
      if (!evaluation.all_points_found())
        throw std::runtime_error(
          "Moving the mesh put velocity nodes outside the old mesh, so the "
          "flow cannot be carried over: the boundary vertices must stay on "
          "the boundary.");
      const FEValuesExtractors::Vector velocities(0);
      std::vector<Tensor<1, dim>>      found, buffer;
      evaluation.template evaluate_and_process<Tensor<1, dim>>(
        found,
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
              fe_values.reinit(ActiveCell(&tria,
                                          cells.cells[c].first,
                                          cells.cells[c].second,
                                          &dofs));
              u.resize(end - begin);
              fe_values[velocities].get_function_values(solution, u);
              for (unsigned int q = 0; q < u.size(); ++q)
                out[begin + q] = u[q];
            }
        });
      // the mean where a point lies on the faces of several old cells; the
      // velocity is continuous, so they agree to round-off
      const std::vector<unsigned int> &ptrs = evaluation.get_point_ptrs();
      for (unsigned int r = 0; r < indices.size(); ++r)
        {
          Tensor<1, dim> mean;
          for (unsigned int j = ptrs[r]; j < ptrs[r + 1]; ++j)
            mean += found[j];
          values[indices[r]] = mean / double(ptrs[r + 1] - ptrs[r]);
        }
    }

    template class OldMeshVelocity<2>;
    template class OldMeshVelocity<3>;
  } // namespace fluid
} // namespace particulate
