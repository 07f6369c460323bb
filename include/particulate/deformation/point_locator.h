#ifndef particulate_deformation_point_locator_h
#define particulate_deformation_point_locator_h

#include <deal.II/base/point.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>

namespace particulate {
  namespace deformation {
    /**
     * Finds the active cell of a fixed mesh that holds a point which moves
     * in small steps, as the vertices do while the deformation ODE is
     * integrated (thesis §5.6): a ray is traced from the centre of the cell
     * that held the point last to its new position, cell by cell through
     * the faces it crosses; if the ray gets lost, a brute-force search over
     * the mesh finds the cell, and the fallback is counted.
     */
    template <int dim>
    class PointLocator
    {
    public:
      using Cell = typename dealii::Triangulation<dim>::active_cell_iterator;

      struct Location
      {
        Cell               cell;
        dealii::Point<dim> unit_point;    ///< in the cell's reference cell
        bool               inside = true; ///< false: outside the mesh
      };

      explicit PointLocator(const dealii::Triangulation<dim> &tria);

      /** The cell holding @p p, searched from @p hint. */
      Location
      locate(const dealii::Point<dim> &p, const Cell &hint) const;

      /** How many searches needed the brute-force fallback. */
      unsigned int
      n_fallbacks() const
      {
        return fallbacks;
      }

      const dealii::Mapping<dim> &
      get_mapping() const
      {
        return mapping;
      }

    private:
      const dealii::Triangulation<dim> &tria;
      dealii::MappingQ<dim>             mapping;
      mutable unsigned int              fallbacks = 0;
    };
  } // namespace deformation
} // namespace particulate

#endif
