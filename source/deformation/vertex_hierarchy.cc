#include <particulate/deformation/mesh_quality.h>
#include <particulate/deformation/vertex_hierarchy.h>

#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <set>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    namespace {
      /** Normal of a flat boundary face given by its vertices. */
      template <int dim>
      Tensor<1, dim>
      face_normal(const std::vector<Point<dim>> &x)
      {
        Tensor<1, dim> n;
        if constexpr (dim == 2)
          {
            const Tensor<1, 2> t = x[1] - x[0];
            n[0]                 = -t[1];
            n[1]                 = t[0];
          }
        else
          n = cross_product_3d(x[1] - x[0], x[2] - x[0]);
        return n / n.norm();
      }
    } // namespace



    template <int dim>
    VertexHierarchy<dim>::VertexHierarchy(const Triangulation<dim> &tria)
    {
      const unsigned int n_vertices = tria.n_vertices();
      const unsigned int n_levels   = tria.n_levels();
      cells.resize(n_levels);
      level_vertices.resize(n_levels);
      level_neighbours.resize(n_levels);
      vertex_cells.resize(n_levels);
      new_vertices.resize(n_levels);
      normals.resize(n_vertices);
      n_constraints.assign(n_vertices, 0);

      auto add_normal = [&](const unsigned int vertex, Tensor<1, dim> n) {
        for (unsigned int k = 0; k < n_constraints[vertex]; ++k)
          n -= (n * normals[vertex][k]) * normals[vertex][k];
        if (n_constraints[vertex] < dim && n.norm() > 1e-6)
          normals[vertex][n_constraints[vertex]++] = n / n.norm();
      };

      for (unsigned int level = 0; level < n_levels; ++level)
        {
          std::vector<bool> on_level(n_vertices, false);
          level_neighbours[level].resize(n_vertices);
          vertex_cells[level].resize(n_vertices);
          for (const auto &cell : tria.cell_iterators_on_level(level))
            {
              CellVertices c;
              for (unsigned int v = 0; v < c.size(); ++v)
                {
                  c[v]           = cell->vertex_index(v);
                  on_level[c[v]] = true;
                  vertex_cells[level][c[v]].push_back(cells[level].size());
                }
              for (unsigned int l = 0; l < GeometryInfo<dim>::lines_per_cell;
                   ++l)
                {
                  const unsigned int a
                    = c[GeometryInfo<dim>::line_to_cell_vertices(l, 0)];
                  const unsigned int b
                    = c[GeometryInfo<dim>::line_to_cell_vertices(l, 1)];
                  level_neighbours[level][a].push_back(b);
                  level_neighbours[level][b].push_back(a);
                }
              for (const unsigned int f : cell->face_indices())
                if (cell->face(f)->at_boundary())
                  {
                    const auto face = cell->face(f);
                    if (face->manifold_id() != numbers::flat_manifold_id)
                      for (const unsigned int v : face->vertex_indices())
                        n_constraints[face->vertex_index(v)] = dim;
                    else
                      {
                        std::vector<Point<dim>> x;
                        for (const unsigned int v : face->vertex_indices())
                          x.push_back(face->vertex(v));
                        const Tensor<1, dim> n = face_normal<dim>(x);
                        for (const unsigned int v : face->vertex_indices())
                          add_normal(face->vertex_index(v), n);
                      }
                  }
              cells[level].push_back(c);
            }
          for (unsigned int v = 0; v < n_vertices; ++v)
            if (on_level[v])
              {
                level_vertices[level].push_back(v);
                auto &n = level_neighbours[level][v];
                std::sort(n.begin(), n.end());
                n.erase(std::unique(n.begin(), n.end()), n.end());
              }

          // The vertices this level's refinement creates, each with the
          // parent it is interpolated from. Children and their vertices
          // are numbered lexicographically, so vertex v of child c sits at
          // (bit_d(c) + bit_d(v)) / 2 in the parent's unit cell.
          if (level + 1 < n_levels)
            {
              std::vector<bool> seen = on_level;
              for (const auto &cell : tria.cell_iterators_on_level(level))
                {
                  AssertThrow(
                    cell->has_children()
                      && cell->n_children()
                           == GeometryInfo<dim>::max_children_per_cell,
                    ExcMessage("The mesh deformation needs a "
                               "globally refined mesh hierarchy."));
                  for (unsigned int ch = 0; ch < cell->n_children(); ++ch)
                    for (const unsigned int v :
                         cell->child(ch)->vertex_indices())
                      {
                        const unsigned int index
                          = cell->child(ch)->vertex_index(v);
                        if (seen[index])
                          continue;
                        seen[index] = true;
                        NewVertex nv;
                        nv.vertex = index;
                        nv.parent = cell->index();
                        for (unsigned int d = 0; d < dim; ++d)
                          nv.reference[d]
                            = 0.5 * (((ch >> d) & 1u) + ((v >> d) & 1u));
                        new_vertices[level].push_back(nv);
                      }
                }
            }
        }
    }



    template <int dim>
    Tensor<1, dim>
    VertexHierarchy<dim>::admissible_displacement(
      const unsigned int    vertex,
      const Tensor<1, dim> &displacement) const
    {
      if (is_fixed(vertex))
        return Tensor<1, dim>();
      Tensor<1, dim> d = displacement;
      for (unsigned int k = 0; k < n_constraints[vertex]; ++k)
        d -= (d * normals[vertex][k]) * normals[vertex][k];
      return d;
    }



    template <int dim>
    void
    VertexHierarchy<dim>::prolongate(const unsigned int       level,
                                     std::vector<Point<dim>> &positions) const
    {
      for (const NewVertex &nv : new_vertices[level])
        {
          if (is_fixed(nv.vertex))
            continue; // on a curved boundary: keep the manifold's point
          const CellVertices &parent = cells[level][nv.parent];
          Point<dim>          x;
          for (unsigned int v = 0; v < parent.size(); ++v)
            {
              double weight = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                weight
                  *= ((v >> d) & 1u) ? nv.reference[d] : 1. - nv.reference[d];
              x += weight * positions[parent[v]];
            }
          positions[nv.vertex] = x;
        }
    }



    template <int dim>
    double
    VertexHierarchy<dim>::cell_quality(
      const unsigned int             level,
      const unsigned int             cell,
      const std::vector<Point<dim>> &positions) const
    {
      std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell> x;
      for (unsigned int v = 0; v < x.size(); ++v)
        x[v] = positions[cells[level][cell][v]];
      return scaled_jacobian<dim>(x);
    }



    template <int dim>
    unsigned int
    VertexHierarchy<dim>::back_off(const unsigned int             level,
                                   const std::vector<Point<dim>> &old_positions,
                                   std::vector<Point<dim>>       &new_positions,
                                   const double min_quality) const
    {
      const unsigned int     max_halvings = 8;
      std::set<unsigned int> held_back;
      for (unsigned int attempt = 0; attempt <= max_halvings; ++attempt)
        {
          std::set<unsigned int> offending;
          for (unsigned int c = 0; c < cells[level].size(); ++c)
            {
              const double after = cell_quality(level, c, new_positions);
              if (after >= min_quality)
                continue;
              const double before = cell_quality(level, c, old_positions);
              if (after < std::min(min_quality, before))
                for (const unsigned int v : cells[level][c])
                  if (new_positions[v] != old_positions[v])
                    offending.insert(v);
            }
          if (offending.empty())
            break;
          for (const unsigned int v : offending)
            {
              held_back.insert(v);
              new_positions[v]
                = attempt < max_halvings ?
                    old_positions[v]
                      + 0.5 * (new_positions[v] - old_positions[v]) :
                    old_positions[v];
            }
        }
      return held_back.size();
    }



    template <int dim>
    void
    VertexHierarchy<dim>::write_positions(
      Triangulation<dim>            &tria,
      const std::vector<Point<dim>> &positions)
    {
      for (const auto &cell : tria.cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = positions[cell->vertex_index(v)];
    }

    template class VertexHierarchy<2>;
    template class VertexHierarchy<3>;
  } // namespace deformation
} // namespace particulate
