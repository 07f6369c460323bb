#include <particulate/geometry/dealii/mesh_point_classifier.h>
#include <particulate/geometry/geometry_error.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>

namespace particulate {
  namespace geometry {

    namespace {
      Eigen::Vector3d
      to_eigen(const dealii::Point<3> &p)
      {
        return Eigen::Vector3d(p[0], p[1], p[2]);
      }

      PointHashGrid
      vertex_grid(const dealii::Triangulation<3>               &tria,
                  std::vector<dealii::types::global_dof_index> &ids,
                  const double                                  cell_size)
      {
        std::vector<char>            seen(tria.n_vertices(), 0);
        std::vector<Eigen::Vector3d> pts;
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              {
                const unsigned int id = cell->vertex_index(v);
                if (!seen[id])
                  {
                    seen[id] = 1;
                    ids.push_back(id);
                    pts.push_back(to_eigen(cell->vertex(v)));
                  }
              }
        return PointHashGrid(std::move(pts), cell_size);
      }

      PointHashGrid
      support_point_grid(const dealii::Mapping<3>    &mapping,
                         const dealii::DoFHandler<3> &dof_handler,
                         const unsigned int           component,
                         std::vector<dealii::types::global_dof_index> &ids,
                         const double cell_size)
      {
        const auto &fe = dof_handler.get_fe();
        if (!fe.has_support_points())
          throw GeometryError("MeshPointClassifier: the finite element "
                              + fe.get_name()
                              + " has no support points; use the vertex "
                                "constructor or a nodal (Lagrange) element.");
        if (component >= fe.n_components())
          throw GeometryError(
            "MeshPointClassifier: component " + std::to_string(component)
            + " requested but " + fe.get_name() + " has "
            + std::to_string(fe.n_components()) + " components.");
        // The support points of the element as a quadrature: FEValues maps them
        // to each cell with the given mapping (curved cells included).
        const dealii::Quadrature<3> nodes(fe.get_unit_support_points());
        dealii::FEValues<3>         fe_values(mapping,
                                      fe,
                                      nodes,
                                      dealii::update_quadrature_points);
        const auto                 &owned = dof_handler.locally_owned_dofs();
        std::vector<dealii::types::global_dof_index> local(
          fe.n_dofs_per_cell());
        std::vector<char>            seen(owned.n_elements(), 0);
        std::vector<Eigen::Vector3d> pts;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              cell->get_dof_indices(local);
              for (unsigned int i = 0; i < local.size(); ++i)
                {
                  if (fe.system_to_component_index(i).first != component
                      || !owned.is_element(local[i]))
                    continue;
                  const auto pos = owned.index_within_set(local[i]);
                  if (seen[pos])
                    continue;
                  seen[pos] = 1;
                  ids.push_back(local[i]);
                  pts.push_back(to_eigen(fe_values.quadrature_point(i)));
                }
            }
        return PointHashGrid(std::move(pts), cell_size);
      }
    } // namespace

    MeshPointClassifier::MeshPointClassifier(
      const dealii::Triangulation<3> &tria,
      const double                    cell_size)
      : grid(vertex_grid(tria, ids, cell_size))
    {}

    MeshPointClassifier::MeshPointClassifier(
      const dealii::Mapping<3>    &mapping,
      const dealii::DoFHandler<3> &dof_handler,
      const unsigned int           component,
      const double                 cell_size)
      : grid(
        support_point_grid(mapping, dof_handler, component, ids, cell_size))
    {}

    std::vector<int>
    MeshPointClassifier::classify(const std::vector<PlacedShape> &bodies,
                                  std::vector<double>            *distances,
                                  ContainmentStatistics *statistics) const
    {
      return classify_points(grid, bodies, distances, statistics);
    }

  } // namespace geometry
} // namespace particulate
