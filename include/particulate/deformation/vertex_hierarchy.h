#ifndef particulate_deformation_vertex_hierarchy_h
#define particulate_deformation_vertex_hierarchy_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <vector>

namespace particulate {
  namespace deformation {
    /**
     * The vertices of a serial, globally refined mesh seen level by level,
     * which is how the non-PDE methods move them (thesis Algorithm 12):
     * which vertices and cells each level has, the edges that connect them
     * (the neighbours of the Laplacian smoother, eq. 5.26-5.27), how a
     * boundary vertex may slide, and how the vertices a refinement created
     * follow their coarser parents (coordinate prolongation).
     *
     * Positions are held in a vector indexed like the triangulation's
     * vertices; nothing here writes into the triangulation except
     * write_positions().
     */
    template <int dim>
    class VertexHierarchy
    {
    public:
      using CellVertices
        = std::array<unsigned int,
                     dealii::GeometryInfo<dim>::vertices_per_cell>;

      /**
       * Analyse @p tria, which must hold its whole hierarchy (levels
       * 0 ... n_levels()-1, every level complete, as global refinement
       * makes it). Boundary vertices on flat boundary faces slide in the
       * face's plane (along the edge where two such planes meet); vertices
       * on curved boundaries and corners are fixed.
       */
      explicit VertexHierarchy(const dealii::Triangulation<dim> &tria);

      unsigned int
      n_levels() const
      {
        return cells.size();
      }

      /** Vertex indices used by the cells of @p level, ascending. */
      const std::vector<unsigned int> &
      vertices_on_level(const unsigned int level) const
      {
        return level_vertices[level];
      }

      /** The cells of @p level as vertex indices (lexicographic order). */
      const std::vector<CellVertices> &
      cells_on_level(const unsigned int level) const
      {
        return cells[level];
      }

      /** Neighbours of @p vertex along the edges of @p level's cells. */
      const std::vector<unsigned int> &
      neighbours(const unsigned int level, const unsigned int vertex) const
      {
        return level_neighbours[level][vertex];
      }

      /** Cells of @p level (indices into cells_on_level()) at @p vertex. */
      const std::vector<unsigned int> &
      cells_at_vertex(const unsigned int level, const unsigned int vertex) const
      {
        return vertex_cells[level][vertex];
      }

      /**
       * The part of a displacement of @p vertex that keeps a boundary
       * vertex on its boundary (the displacement itself for an interior
       * vertex, zero for a fixed one).
       */
      dealii::Tensor<1, dim>
      admissible_displacement(const unsigned int            vertex,
                              const dealii::Tensor<1, dim> &displacement) const;

      /** True if the vertex cannot move at all (corner, curved boundary). */
      bool
      is_fixed(const unsigned int vertex) const
      {
        return n_constraints[vertex] >= dim;
      }

      /** True if the vertex lies on the domain boundary. */
      bool
      at_boundary(const unsigned int vertex) const
      {
        return n_constraints[vertex] > 0;
      }

      /**
       * Place the vertices that first appear on @p level + 1 by multilinear
       * interpolation of their parent cell on @p level (edge midpoints, face
       * and cell centres of the moved parents).
       */
      void
      prolongate(const unsigned int               level,
                 std::vector<dealii::Point<dim>> &positions) const;

      /** Scaled Jacobian of cell @p cell of @p level at @p positions. */
      double
      cell_quality(const unsigned int                     level,
                   const unsigned int                     cell,
                   const std::vector<dealii::Point<dim>> &positions) const;

      /**
       * Accept the move of @p level's vertices from @p old_positions to
       * @p new_positions only where it spoils no cell: a cell may not end
       * below min(@p min_quality, its scaled Jacobian before). Vertices of
       * offending cells are moved back by halves, at most eight times, then
       * reset. Returns how many vertices were held back.
       */
      unsigned int
      back_off(const unsigned int                     level,
               const std::vector<dealii::Point<dim>> &old_positions,
               std::vector<dealii::Point<dim>>       &new_positions,
               const double                           min_quality) const;

      /** Write @p positions into @p tria (all levels share the vertices). */
      static void
      write_positions(dealii::Triangulation<dim>            &tria,
                      const std::vector<dealii::Point<dim>> &positions);

    private:
      struct NewVertex
      {
        unsigned int       vertex;
        unsigned int       parent;    ///< index into cells[level]
        dealii::Point<dim> reference; ///< position in the parent's unit cell
      };

      std::vector<std::vector<CellVertices>>              cells;
      std::vector<std::vector<unsigned int>>              level_vertices;
      std::vector<std::vector<std::vector<unsigned int>>> level_neighbours;
      std::vector<std::vector<std::vector<unsigned int>>> vertex_cells;
      std::vector<std::vector<NewVertex>>                 new_vertices;
      /// orthonormal boundary normals a vertex must keep its position along
      std::vector<std::array<dealii::Tensor<1, dim>, dim>> normals;
      std::vector<unsigned int>                            n_constraints;
    };
  } // namespace deformation
} // namespace particulate

#endif
