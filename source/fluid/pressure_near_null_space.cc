#include "pressure_near_null_space.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    std::vector<double>
    pressure_near_null_space(const Mapping<dim>           &mapping,
                             const DoFHandler<dim>        &dof_handler,
                             const IndexSet               &owned_pressures,
                             const types::global_dof_index first_pressure_dof,
                             const MPI_Comm                communicator)
    {
      const auto        &fe                 = dof_handler.get_fe();
      const unsigned int pressure_component = dim;

      // bounding box of the whole mesh, for centred, scaled coordinates
      std::array<double, dim> lower, upper;
      lower.fill(std::numeric_limits<double>::max());
      upper.fill(-std::numeric_limits<double>::max());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::min(lower[d], cell->vertex(v)[d]);
                upper[d] = std::max(upper[d], cell->vertex(v)[d]);
              }
      Point<dim> centre;
      double     diagonal = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d]  = Utilities::MPI::min(lower[d], communicator);
          upper[d]  = Utilities::MPI::max(upper[d], communicator);
          centre[d] = 0.5 * (lower[d] + upper[d]);
          diagonal += (upper[d] - lower[d]) * (upper[d] - lower[d]);
        }
      diagonal = std::sqrt(diagonal);

      // the pressure shape functions of a cell: the ones of its component
      std::vector<unsigned int> pressure_index;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        if (fe.system_to_component_index(i).first == pressure_component)
          pressure_index.push_back(i);
      const unsigned int n_p     = pressure_index.size();
      const unsigned int n_modes = dim + 1;
      if (n_p != n_modes)
        throw std::logic_error(
          "pressure_near_null_space: expected the dim + 1 DoFs of a P1disc "
          "pressure per cell, found "
          + std::to_string(n_p) + ".");

      const std::size_t   n_owned = owned_pressures.n_elements();
      std::vector<double> modes(n_modes * n_owned, 0.);

      // degree 2 + 1 on each axis: exact for the P1 x P1 integrands of
      // affine cells, and the mapping's Jacobian is smooth elsewhere
      const QGauss<dim>  quadrature(3);
      FEValues<dim>      fe_values(mapping,
                              fe,
                              quadrature,
                              update_values | update_quadrature_points
                                | update_JxW_values);
      FullMatrix<double> mass(n_p, n_p);
      FullMatrix<double> right_hand_sides(n_p, n_modes),
        coefficients(n_p, n_modes);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            mass             = 0.;
            right_hand_sides = 0.;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double      JxW = fe_values.JxW(q);
                const Point<dim> &x   = fe_values.quadrature_point(q);
                for (unsigned int k = 0; k < n_p; ++k)
                  {
                    const double psi_k
                      = fe_values.shape_value(pressure_index[k], q);
                    for (unsigned int l = 0; l < n_p; ++l)
                      mass(k, l)
                        += psi_k * fe_values.shape_value(pressure_index[l], q)
                           * JxW;
                    right_hand_sides(k, 0) += psi_k * JxW;
                    for (unsigned int d = 0; d < dim; ++d)
                      right_hand_sides(k, 1 + d)
                        += psi_k * (x[d] - centre[d]) / diagonal * JxW;
                  }
              }
            mass.gauss_jordan();
            mass.mmult(coefficients, right_hand_sides);

            cell->get_dof_indices(dof_indices);
            for (unsigned int k = 0; k < n_p; ++k)
              {
                const auto local = owned_pressures.index_within_set(
                  dof_indices[pressure_index[k]] - first_pressure_dof);
                for (unsigned int m = 0; m < n_modes; ++m)
                  modes[m * n_owned + local] = coefficients(k, m);
              }
          }
      return modes;
    }

    template std::vector<double>
    pressure_near_null_space(const Mapping<2> &,
                             const DoFHandler<2> &,
                             const IndexSet &,
                             const types::global_dof_index,
                             const MPI_Comm);
    template std::vector<double>
    pressure_near_null_space(const Mapping<3> &,
                             const DoFHandler<3> &,
                             const IndexSet &,
                             const types::global_dof_index,
                             const MPI_Comm);
  } // namespace fluid
} // namespace particulate
