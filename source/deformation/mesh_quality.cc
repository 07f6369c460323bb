#include <particulate/deformation/mesh_quality.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    template <int dim>
    double
    scaled_jacobian(
      const std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell> &x)
    {
      double quality = std::numeric_limits<double>::max();
      for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
        {
          // The edges leaving corner v point along +d where bit d of v is
          // 0 and along -d where it is 1; flipping those keeps the frame
          // right-handed for an undistorted cell.
          Tensor<2, dim> frame;
          for (unsigned int d = 0; d < dim; ++d)
            {
              Tensor<1, dim> edge = x[v ^ (1u << d)] - x[v];
              if (v & (1u << d))
                edge *= -1.;
              const double length = edge.norm();
              if (length == 0.)
                return 0.;
              for (unsigned int e = 0; e < dim; ++e)
                frame[e][d] = edge[e] / length;
            }
          quality = std::min(quality, determinant(frame));
        }
      return quality;
    }



    template <int dim>
    double
    aspect_ratio(
      const std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell> &x)
    {
      double shortest = std::numeric_limits<double>::max(), longest = 0.;
      for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
        for (unsigned int d = 0; d < dim; ++d)
          if (!(v & (1u << d)))
            {
              const double length = x[v].distance(x[v | (1u << d)]);
              shortest            = std::min(shortest, length);
              longest             = std::max(longest, length);
            }
      return shortest > 0. ? longest / shortest :
                             std::numeric_limits<double>::infinity();
    }



    namespace {
      template <int dim, typename Cell>
      std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell>
      vertices_of(const Cell &cell)
      {
        std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell> x;
        for (unsigned int v = 0; v < x.size(); ++v)
          x[v] = cell->vertex(v);
        return x;
      }
    } // namespace



    template <int dim>
    MeshQuality
    compute_mesh_quality(const Triangulation<dim> &tria, const int level)
    {
      MeshQuality quality;
      quality.min_scaled_jacobian = std::numeric_limits<double>::max();
      double sum                  = 0.;
      auto   add                  = [&](const auto &cell) {
        const auto   x              = vertices_of<dim>(cell);
        const double q              = scaled_jacobian<dim>(x);
        quality.min_scaled_jacobian = std::min(quality.min_scaled_jacobian, q);
        quality.max_aspect_ratio
          = std::max(quality.max_aspect_ratio, aspect_ratio<dim>(x));
        quality.n_inverted_cells += (q <= 0.);
        sum += q;
        ++quality.n_cells;
      };
      if (level >= 0)
        {
          for (const auto &cell : tria.cell_iterators_on_level(level))
            add(cell);
        }
      else
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
            add(cell);

      const MPI_Comm comm = tria.get_communicator();
      quality.min_scaled_jacobian
        = Utilities::MPI::min(quality.min_scaled_jacobian, comm);
      quality.max_aspect_ratio
        = Utilities::MPI::max(quality.max_aspect_ratio, comm);
      quality.n_inverted_cells
        = Utilities::MPI::sum(quality.n_inverted_cells, comm);
      quality.n_cells = Utilities::MPI::sum(quality.n_cells, comm);
      sum             = Utilities::MPI::sum(sum, comm);
      quality.mean_scaled_jacobian
        = quality.n_cells > 0 ? sum / quality.n_cells : 1.;
      if (quality.n_cells == 0)
        quality.min_scaled_jacobian = 1.;
      return quality;
    }



    template <int dim>
    EquidistributionError
    equidistribution_error(
      const Triangulation<dim>                        &tria,
      const std::function<double(const Point<dim> &)> &monitor)
    {
      std::vector<double> size, target;
      double              volume = 0., target_sum = 0.;
      for (const auto &cell : tria.active_cell_iterators())
        {
          size.push_back(cell->measure());
          target.push_back(monitor(cell->center()));
          volume += size.back();
          target_sum += target.back();
        }
      const double          c = volume / target_sum;
      EquidistributionError error;
      for (unsigned int k = 0; k < size.size(); ++k)
        {
          const double e = size[k] / (c * target[k]) - 1.;
          error.l2 += size[k] * e * e;
          error.max = std::max(error.max, std::abs(e));
        }
      error.l2 = std::sqrt(error.l2 / volume);
      return error;
    }

    template double
    scaled_jacobian<2>(const std::array<Point<2>, 4> &);
    template double
    scaled_jacobian<3>(const std::array<Point<3>, 8> &);
    template double
    aspect_ratio<2>(const std::array<Point<2>, 4> &);
    template double
    aspect_ratio<3>(const std::array<Point<3>, 8> &);
    template MeshQuality
    compute_mesh_quality<2>(const Triangulation<2> &, const int);
    template MeshQuality
    compute_mesh_quality<3>(const Triangulation<3> &, const int);
    template EquidistributionError
    equidistribution_error<2>(const Triangulation<2> &,
                              const std::function<double(const Point<2> &)> &);
    template EquidistributionError
    equidistribution_error<3>(const Triangulation<3> &,
                              const std::function<double(const Point<3> &)> &);
  } // namespace deformation
} // namespace particulate
