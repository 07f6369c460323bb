#include <particulate/core/mesh_size.h>

#include <deal.II/base/types.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace core {
    namespace {
      /** Cells growing by @p ratio from size @p h over @p length, as
       *  graded_cell_sizes() makes them (at least one). */
      double
      growing_cells(const double length, const double h, const double ratio)
      {
        const double n
          = ratio > 1. ?
              std::floor(std::log1p(length * (ratio - 1.) / (h * ratio))
                         / std::log(ratio)) :
              std::floor(length / h);
        return std::max(1., n);
      }

      /** The cells graded_cell_sizes() makes along one direction. */
      double
      graded_cell_count(const MeshParameters &p, const unsigned int d)
      {
        const double lower = p.lower_corner[d], upper = p.upper_corner[d];
        const double a = std::clamp(p.fine_lower[d], lower, upper);
        const double b = std::clamp(p.fine_upper[d], a, upper);
        const double h = p.fine_cell_size;
        double       n = 0.;
        if (a - lower > 1e-12 * (upper - lower))
          n += growing_cells(a - lower, h, p.grading_ratio);
        if (b - a > 0.)
          n += std::max(1., std::round((b - a) / h));
        if (upper - b > 1e-12 * (upper - lower))
          n += growing_cells(upper - b, h, p.grading_ratio);
        return n;
      }

      std::string
      size_entries(const MeshParameters::Type type)
      {
        switch (type)
          {
            case MeshParameters::Type::hyper_rectangle:
            case MeshParameters::Type::column:
              return "'Subdivisions' and 'Refinements'";
            case MeshParameters::Type::graded_rectangle:
              return "'Fine cell size', 'Grading ratio' and 'Refinements'";
            default:
              return "'Refinements'";
          }
      }
    } // namespace



    double
    coarse_cell_count(const MeshParameters &p, const unsigned int dim)
    {
      double cells = 1.;
      switch (p.type)
        {
          case MeshParameters::Type::hyper_rectangle:
            for (unsigned int d = 0; d < dim; ++d)
              cells *= d < p.subdivisions.size() ? p.subdivisions[d] : 1.;
            return cells;
          case MeshParameters::Type::column:
            // a five-cell disk per axial subdivision
            return 5. * (p.subdivisions.size() > 2 ? p.subdivisions[2] : 1.);
          case MeshParameters::Type::graded_rectangle:
            for (unsigned int d = 0; d < dim; ++d)
              if (d < p.lower_corner.size() && d < p.upper_corner.size()
                  && d < p.fine_lower.size() && d < p.fine_upper.size())
                cells *= graded_cell_count(p, d);
            return cells;
          default:
            return 0.;
        }
    }



    void
    check_mesh_size(const MeshParameters &p,
                    const unsigned int    dim,
                    const double          coarse_cells)
    {
      const double cells = coarse_cells * std::pow(2., dim * p.refinements);
      const double unknowns_per_cell = dim * std::pow(2., dim) + dim + 1;
      const double unknowns          = cells * unknowns_per_cell;
      const double largest           = static_cast<double>(
        std::numeric_limits<dealii::types::global_dof_index>::max());
      if (unknowns <= largest)
        return;
      std::ostringstream message;
      message.precision(3);
      message << "Mesh: " << size_entries(p.type) << " ask for about " << cells
              << " cells, " << unknowns << " unknowns of the flow; deal.II "
              << "numbers them in "
              << 8 * sizeof(dealii::types::global_dof_index)
              << " bits (at most " << largest
              << "). Ask for a coarser mesh: the cells are counted before "
                 "anything is allocated.";
      throw std::runtime_error(message.str());
    }
  } // namespace core
} // namespace particulate
