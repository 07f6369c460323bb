#include <particulate/deformation/point_locator.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <cmath>
#include <limits>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    namespace {
      /** Reference coordinates of @p p in @p cell; false if the inversion
       *  of the bilinear map fails (far outside a distorted cell). */
      template <int dim, typename Cell>
      bool
      to_unit_cell(const Mapping<dim> &mapping,
                   const Cell         &cell,
                   const Point<dim>   &p,
                   Point<dim>         &unit)
      {
        try
          {
            unit = mapping.transform_real_to_unit_cell(cell, p);
            return true;
          }
        catch (const typename Mapping<dim>::ExcTransformationFailed &)
          {
            return false;
          }
      }

      template <int dim>
      Point<dim>
      unit_cell_centre()
      {
        Point<dim> centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = 0.5;
        return centre;
      }

      /** Outward normal of the plane that stands for face @p f (exact for
       *  the straight edges of 2D cells; the plane of the diagonals of a
       *  bilinear 3D face). */
      template <int dim, typename Cell>
      Tensor<1, dim>
      outward_normal(const Cell &cell, const unsigned int f)
      {
        const auto     face = cell->face(f);
        Tensor<1, dim> n;
        if constexpr (dim == 2)
          {
            const Tensor<1, 2> t = face->vertex(1) - face->vertex(0);
            n[0]                 = t[1];
            n[1]                 = -t[0];
          }
        else
          n = cross_product_3d(face->vertex(3) - face->vertex(0),
                               face->vertex(2) - face->vertex(1));
        if (n * (face->center() - cell->center()) < 0.)
          n *= -1.;
        return n;
      }
    } // namespace



    template <int dim>
    PointLocator<dim>::PointLocator(const Triangulation<dim> &tria_)
      : tria(tria_)
      , mapping(1)
    {}



    template <int dim>
    typename PointLocator<dim>::Location
    PointLocator<dim>::locate(const Point<dim> &p, const Cell &hint) const
    {
      const double tolerance = 1e-10;
      Point<dim>   unit;
      if (to_unit_cell(mapping, hint, p, unit)
          && GeometryInfo<dim>::is_inside_unit_cell(unit, tolerance))
        return {hint, unit, true};

      // Trace the ray from the hint's centre to p through the faces it
      // leaves each cell by: the exit face of a convex cell is, among the
      // faces the ray runs towards, the one whose plane it meets first.
      const Point<dim>     start     = hint->center();
      const Tensor<1, dim> direction = p - start;
      Cell                 cell      = hint;
      const unsigned int   max_cells
        = 100
          + 4
              * static_cast<unsigned int>(
                std::pow(double(tria.n_active_cells()), 1. / dim));
      for (unsigned int step = 0; step < max_cells; ++step)
        {
          unsigned int exit_face = numbers::invalid_unsigned_int;
          double       exit_t    = std::numeric_limits<double>::max();
          for (const unsigned int f : cell->face_indices())
            {
              const Tensor<1, dim> n     = outward_normal<dim>(cell, f);
              const double         along = n * direction;
              if (along <= 0.)
                continue;
              const double t = n * (cell->face(f)->center() - start) / along;
              if (t < exit_t)
                {
                  exit_t    = t;
                  exit_face = f;
                }
            }
          if (exit_face == numbers::invalid_unsigned_int || exit_t >= 1.)
            break; // p should be in this cell: let the fallback decide
          if (cell->at_boundary(exit_face))
            {
              // p lies outside the mesh beyond this boundary face; the
              // caller extrapolates from the last cell.
              if (!to_unit_cell(mapping, cell, p, unit))
                unit = unit_cell_centre<dim>();
              return {cell, unit, false};
            }
          cell = cell->neighbor(exit_face);
          if (to_unit_cell(mapping, cell, p, unit)
              && GeometryInfo<dim>::is_inside_unit_cell(unit, tolerance))
            return {cell, unit, true};
        }

      ++fallbacks;
      try
        {
          const auto found
            = GridTools::find_active_cell_around_point(mapping, tria, p);
          return {found.first, found.second, true};
        }
      catch (...)
        {
          if (!to_unit_cell(mapping, cell, p, unit))
            unit = unit_cell_centre<dim>();
          return {cell, unit, false};
        }
    }

    template class PointLocator<2>;
    template class PointLocator<3>;
  } // namespace deformation
} // namespace particulate
