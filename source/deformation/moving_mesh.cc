#include <particulate/core/checkpoint.h>
#include <particulate/deformation/carried_zone_realignment.h>
#include <particulate/deformation/distance_field.h>
#include <particulate/deformation/laplace_smoothing.h>
#include <particulate/deformation/mesh_quality.h>
#include <particulate/deformation/moving_mesh.h>
#include <particulate/deformation/vertex_hierarchy.h>

#include <deal.II/grid/cell_id.h>

#include <algorithm>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    template <int dim>
    MovingMesh<dim>::MovingMesh(const core::MeshParameters  &mesh_parameters,
                                const DeformationParameters &parameters)
      : method(create_mesh_deformation<dim>(parameters))
      , following(parameters.following)
      , readaptation_quality(parameters.readaptation_quality)
      , readaptation_aspect_ratio(parameters.readaptation_aspect_ratio)
      , carried_zone_width(parameters.carried_zone_width)
      , carried_zone_fade(parameters.carried_zone_fade)
    {
      if (!method
          && following != DeformationParameters::Following::carry_neighbourhood)
        throw std::invalid_argument(
          "MovingMesh needs a deformation method ('Method' in subsection "
          "'Mesh deformation' is 'none') unless it carries the bodies' "
          "neighbourhoods");
      if (following == DeformationParameters::Following::carry_surface
          && !dynamic_cast<const LaplaceAlpha<dim> *>(method.get()))
        throw std::invalid_argument(
          "'Moving bodies = carry surface vertices' needs 'Method = "
          "laplace-alpha' (subsection 'Mesh deformation')");
      core::create_serial_mesh(mesh_parameters, mesh);
      undeformed = mesh.get_vertices();
    }



    template <int dim>
    MovingMesh<dim>::~MovingMesh() = default;



    template <int dim>
    DeformationReport
    MovingMesh<dim>::adapt(const DistanceField<dim> &distance)
    {
      const std::vector<Point<dim>> before = mesh.get_vertices();
      try
        {
          VertexHierarchy<dim>::write_positions(mesh, undeformed);
          if (following == DeformationParameters::Following::readapt)
            return method->deform(mesh, distance);
          DeformationReport report;
          if (following == DeformationParameters::Following::carry_surface)
            {
              const auto &alpha
                = static_cast<const LaplaceAlpha<dim> &>(*method);
              std::vector<bool> placed;
              report = alpha.deform(mesh, distance, placed);
              // The fresh mesh in the form carry() gives it: carry() pins
              // every surface vertex from the start of each level, while
              // deform() placed some only after that level's smoothing
              // (those the smoothing brought near the surface, and second
              // tries after being held back). Left as it is, the first
              // carried step would move the vertices around those for the
              // difference alone, a one-step spike of the mesh velocity and
              // with it of the pressure and the force (the 3D slab: drag
              // -70 % for one step after each fresh adaptation). Carried by
              // zero, the mesh changes only as the bodies move from here
              // on.
              const auto settled = alpha.carry(
                mesh,
                undeformed,
                distance,
                [](const Point<dim> &) { return Tensor<1, dim>(); },
                placed);
              report.projected_vertices = settled.projected_vertices;
              report.held_back_vertices += settled.held_back_vertices;
              report.quality = settled.quality;
              on_surface.swap(placed);
            }
          else
            {
              if (method)
                report = method->deform(mesh, distance);
              else
                report.quality = compute_mesh_quality(mesh);
              // marks the mesh as adapted (follow() carries it from here)
              on_surface.assign(mesh.n_vertices(), false);
            }
          fresh_min_quality      = report.quality.min_scaled_jacobian;
          fresh_max_aspect_ratio = report.quality.max_aspect_ratio;
          return report;
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
    DeformationReport
    MovingMesh<dim>::follow(
      const DistanceField<dim> &distance,
      const std::function<Tensor<1, dim>(const Point<dim> &)>
                               &body_displacement,
      const DistanceField<dim> *previous)
    {
      fresh_start.clear();
      const std::vector<Point<dim>> before = mesh.get_vertices();
      const auto                    moved  = [&](DeformationReport report) {
        if (report.quality.min_scaled_jacobian <= 0.)
          refuse_inverted_mesh(before, report.quality.min_scaled_jacobian);
        for (unsigned int v = 0; v < before.size(); ++v)
          report.max_vertex_move
            = std::max(report.max_vertex_move,
                       before[v].distance(mesh.get_vertices()[v]));
        return report;
      };
      if (following == DeformationParameters::Following::readapt
          || on_surface.empty())
        {
          auto report      = adapt(distance);
          report.readapted = true;
          return moved(report);
        }
      std::vector<bool>       carried = on_surface;
      const DeformationReport report
        = following == DeformationParameters::Following::carry_surface ?
            static_cast<const LaplaceAlpha<dim> &>(*method)
              .carry(mesh, undeformed, distance, body_displacement, carried) :
            carry_neighbourhood(distance, body_displacement);
      const bool lost_surface_vertices = carried != on_surface;
      if (!lost_surface_vertices && keeps_quality(report))
        return moved(report);
      // the carried mesh has run out of room: start afresh
      if (following == DeformationParameters::Following::carry_neighbourhood
          && !method)
        {
          const std::vector<Point<dim>> carried_now = mesh.get_vertices();
          DeformationReport             fresh;
          if (previous)
            {
              // where the step starts, then carried over the step; unless
              // that carry alone bends a cell below `Re-adaptation
              // quality` (a body moving about a cell per step towards a
              // wall): then the fresh start is made where the bodies are
              // now
              restart_carried_zones(before, *previous, body_displacement);
              fresh_start = mesh.get_vertices();
              fresh       = carry_neighbourhood(distance, body_displacement);
              const double worst = fresh.quality.min_scaled_jacobian;
              if (worst < readaptation_quality || worst <= 0.)
                {
                  fresh_start.clear();
                  fresh = restart_carried_zones(carried_now, distance);
                }
            }
          else
            fresh = restart_carried_zones(carried_now, distance);
          fresh.readapted = true;
          return moved(fresh);
        }
      VertexHierarchy<dim>::write_positions(mesh, before);
      auto fresh      = adapt(distance);
      fresh.readapted = true;
      return moved(fresh);
    }



    template <int dim>
    void
    MovingMesh<dim>::refuse_inverted_mesh(const std::vector<Point<dim>> &before,
                                          const double min_scaled_jacobian)
    {
      VertexHierarchy<dim>::write_positions(mesh, before);
      fresh_start.clear();
      std::ostringstream message;
      message << "Moving the mesh with the bodies inverts a cell (smallest "
                 "scaled Jacobian "
              << min_scaled_jacobian
              << "): a body moves too far in one step for the cells between "
                 "it and a wall or another body. Reduce 'Time step' in "
                 "subsection 'Time'.";
      throw DeformationError(message.str());
    }



    template <int dim>
    bool
    MovingMesh<dim>::keeps_quality(const DeformationReport &report) const
    {
      return report.quality.min_scaled_jacobian
               >= std::min(readaptation_quality, fresh_min_quality)
             && report.quality.max_aspect_ratio
                  <= std::max(readaptation_aspect_ratio,
                              fresh_max_aspect_ratio);
    }



    template <int dim>
    DeformationReport
    MovingMesh<dim>::restart_carried_zones(
      const std::vector<Point<dim>> &carried_positions,
      const DistanceField<dim>      &at,
      const std::function<Tensor<1, dim>(const Point<dim> &)> &step)
    {
      // from the undeformed mesh, each body's zone carried back to where
      // its vertices were wherever the mesh repeats itself there
      // (carried_zone_realignment.h)
      VertexHierarchy<dim>::write_positions(mesh, carried_positions);
      const auto zones = realigned_zones(mesh.get_vertices(),
                                         undeformed,
                                         at,
                                         carried_zone_width,
                                         step);
      VertexHierarchy<dim>::write_positions(mesh, undeformed);
      auto fresh        = carry_neighbourhood(at, [&](const Point<dim> &x) {
        return residual_near(zones, x);
      });
      fresh_min_quality = fresh.quality.min_scaled_jacobian;
      fresh_max_aspect_ratio = fresh.quality.max_aspect_ratio;
      return fresh;
    }



    template <int dim>
    double
    MovingMesh<dim>::carried_share(const double d) const
    {
      if (d <= carried_zone_width)
        return 1.;
      if (d >= carried_zone_width + carried_zone_fade)
        return 0.;
      const double t = (d - carried_zone_width) / carried_zone_fade;
      return 1. - t * t * (3. - 2. * t);
    }



    template <int dim>
    DeformationReport
    MovingMesh<dim>::carry_neighbourhood(
      const DistanceField<dim> &distance,
      const std::function<Tensor<1, dim>(const Point<dim> &)>
        &body_displacement)
    {
      // vertices on the boundary only slide along its planes, so the
      // hierarchy's boundary normals stay valid for every carried mesh
      if (!carried_hierarchy)
        carried_hierarchy = std::make_unique<VertexHierarchy<dim>>(mesh);
      const VertexHierarchy<dim> &hierarchy = *carried_hierarchy;
      std::vector<Point<dim>>     positions = mesh.get_vertices();
      for (unsigned int v = 0; v < positions.size(); ++v)
        {
          const Tensor<1, dim> shift = body_displacement(positions[v]);
          // @p distance is about the bodies' new places; a vertex that moves
          // all the way keeps its distance, so it is measured there
          const double share
            = carried_share(distance.signed_distance(positions[v] + shift));
          if (share > 0.)
            // vertices on the domain boundary slide along it
            positions[v] += hierarchy.admissible_displacement(v, share * shift);
        }
      VertexHierarchy<dim>::write_positions(mesh, positions);
      DeformationReport report;
      report.quality = compute_mesh_quality(mesh);
      return report;
    }



    template <int dim>
    void
    MovingMesh<dim>::copy_vertices_to(Triangulation<dim> &tria) const
    {
      copy_vertices_to(tria, mesh.get_vertices());
    }



    template <int dim>
    void
    MovingMesh<dim>::copy_vertices_to(
      Triangulation<dim>            &tria,
      const std::vector<Point<dim>> &positions) const
    {
      AssertDimension(positions.size(), mesh.n_vertices());
      for (const auto &cell : tria.cell_iterators())
        {
          const auto twin = mesh.create_cell_iterator(cell->id());
          for (const auto v : cell->vertex_indices())
            cell->vertex(v) = positions[twin->vertex_index(v)];
        }
    }



    template <int dim>
    void
    MovingMesh<dim>::save(std::ostream &out) const
    {
      core::write_binary_vector(out, mesh.get_vertices());
      core::write_binary_vector(out,
                                std::vector<unsigned char>(on_surface.begin(),
                                                           on_surface.end()));
      core::write_binary(out, fresh_min_quality);
      core::write_binary(out, fresh_max_aspect_ratio);
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
      const auto flags = core::read_binary_vector<unsigned char>(in);
      on_surface.assign(flags.begin(), flags.end());
      fresh_min_quality      = core::read_binary<double>(in);
      fresh_max_aspect_ratio = core::read_binary<double>(in);
    }

    template class MovingMesh<2>;
    template class MovingMesh<3>;
  } // namespace deformation
} // namespace particulate
