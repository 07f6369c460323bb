#include <particulate/core/checkpoint.h>
#include <particulate/deformation/moving_mesh.h>
#include <particulate/deformation/vertex_hierarchy.h>

#include <deal.II/grid/cell_id.h>

#include <istream>
#include <ostream>
#include <stdexcept>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    template <int dim>
    MovingMesh<dim>::MovingMesh(const core::MeshParameters  &mesh_parameters,
                                const DeformationParameters &parameters)
      : method(create_mesh_deformation<dim>(parameters))
    {
      if (!method)
        throw std::invalid_argument(
          "MovingMesh needs a deformation method ('Method' in subsection "
          "'Mesh deformation' is 'none')");
      core::create_serial_mesh(mesh_parameters, mesh);
      undeformed = mesh.get_vertices();
    }



    template <int dim>
    DeformationReport
    MovingMesh<dim>::adapt(const DistanceField<dim> &distance)
    {
      const std::vector<Point<dim>> before = mesh.get_vertices();
      try
        {
          VertexHierarchy<dim>::write_positions(mesh, undeformed);
          return method->deform(mesh, distance);
        }
      catch (const DeformationError &)
        {
          // the undeformed mesh would resolve the bodies worse than the
          // last adapted one
          VertexHierarchy<dim>::write_positions(mesh, before);
          throw;
        }
    }



    template <int dim>
    void
    MovingMesh<dim>::copy_vertices_to(Triangulation<dim> &tria) const
    {
      for (const auto &cell : tria.cell_iterators())
        {
          const auto twin = mesh.create_cell_iterator(cell->id());
          for (const auto v : cell->vertex_indices())
            cell->vertex(v) = twin->vertex(v);
        }
    }



    template <int dim>
    void
    MovingMesh<dim>::save(std::ostream &out) const
    {
      core::write_binary_vector(out, mesh.get_vertices());
    }



    template <int dim>
    void
    MovingMesh<dim>::load(std::istream &in)
    {
      const auto x = core::read_binary_vector<Point<dim>>(in);
      if (x.size() != mesh.n_vertices())
        throw std::runtime_error(
          "the checkpoint's deformed mesh has " + std::to_string(x.size())
          + " vertices, the case's mesh " + std::to_string(mesh.n_vertices()));
      VertexHierarchy<dim>::write_positions(mesh, x);
    }

    template class MovingMesh<2>;
    template class MovingMesh<3>;
  } // namespace deformation
} // namespace particulate
