#include "undetermined_pressures.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /// A velocity DoF whose value a constraint fixes (no other DoF in its
      /// line); a hanging node, which follows free DoFs, stays free.
      bool
      is_fixed(const AffineConstraints<double> &constraints,
               const types::global_dof_index    dof)
      {
        const auto *entries = constraints.get_constraint_entries(dof);
        return entries != nullptr && entries->empty();
      }



      /**
       * Rows of `null_basis` (n_p x k, columns spanning the null space) to
       * pin, one per column, chosen by Gaussian elimination with the largest
       * remaining entry as pivot: the pinned rows of the basis form an
       * invertible k x k block, so no null vector survives the pinning.
       */
      std::vector<unsigned int>
      pivot_rows(FullMatrix<double> null_basis)
      {
        std::vector<unsigned int> pinned;
        for (unsigned int j = 0; j < null_basis.n(); ++j)
          {
            unsigned int pivot   = numbers::invalid_unsigned_int;
            double       largest = 0.;
            for (unsigned int r = 0; r < null_basis.m(); ++r)
              if (std::find(pinned.begin(), pinned.end(), r) == pinned.end()
                  && std::abs(null_basis(r, j)) > largest)
                {
                  largest = std::abs(null_basis(r, j));
                  pivot   = r;
                }
            Assert(pivot != numbers::invalid_unsigned_int, ExcInternalError());
            pinned.push_back(pivot);
            for (unsigned int l = j + 1; l < null_basis.n(); ++l)
              {
                const double factor
                  = null_basis(pivot, l) / null_basis(pivot, j);
                for (unsigned int r = 0; r < null_basis.m(); ++r)
                  null_basis(r, l) -= factor * null_basis(r, j);
              }
          }
        return pinned;
      }
    } // namespace



    template <int dim>
    std::vector<types::global_dof_index>
    find_undetermined_pressure_dofs(
      const DoFHandler<dim>                      &dof_handler,
      const Mapping<dim>                         &mapping,
      const AffineConstraints<double>            &zero_constraints,
      const std::vector<types::global_dof_index> &prescribed_dofs)
    {
      std::vector<types::global_dof_index> undetermined;
      if (prescribed_dofs.empty())
        return undetermined;

      const auto               &fe = dof_handler.get_fe();
      const QGauss<dim>         quadrature(fe.degree + 1);
      FEValues<dim>             fe_values(mapping,
                              fe,
                              quadrature,
                              update_values | update_gradients
                                | update_JxW_values);
      const unsigned int        n_dofs = fe.n_dofs_per_cell();
      std::vector<unsigned int> pressure_local, velocity_local;
      for (unsigned int i = 0; i < n_dofs; ++i)
        (fe.system_to_component_index(i).first == dim ? pressure_local :
                                                        velocity_local)
          .push_back(i);
      const unsigned int               n_p = pressure_local.size();
      const FEValuesExtractors::Vector velocity(0);
      const FEValuesExtractors::Scalar pressure(dim);

      std::vector<types::global_dof_index> dofs(n_dofs);
      std::vector<unsigned int> free_velocity; // positions in velocity_local
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          cell->get_dof_indices(dofs);
          bool touches_body = false, all_constrained = true;
          free_velocity.clear();
          for (unsigned int j = 0; j < velocity_local.size(); ++j)
            {
              const auto dof = dofs[velocity_local[j]];
              touches_body |= std::binary_search(prescribed_dofs.begin(),
                                                 prescribed_dofs.end(),
                                                 dof);
              all_constrained &= zero_constraints.is_constrained(dof);
              if (!is_fixed(zero_constraints, dof))
                free_velocity.push_back(j);
            }
          if (!touches_body)
            continue;
          if (all_constrained || free_velocity.empty())
            {
              for (const unsigned int k : pressure_local)
                undetermined.push_back(dofs[k]);
              continue;
            }

          // B (n_p x all velocities) with b_kj = (q_k, div v_j)
          fe_values.reinit(cell);
          FullMatrix<double> divergence(n_p, velocity_local.size());
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int k = 0; k < n_p; ++k)
              {
                const double q_jxw
                  = fe_values[pressure].value(pressure_local[k], q)
                    * fe_values.JxW(q);
                for (unsigned int j = 0; j < velocity_local.size(); ++j)
                  divergence(k, j)
                    += q_jxw
                       * fe_values[velocity].divergence(velocity_local[j], q);
              }
          // scale: the cell's block without constraints
          LAPACKFullMatrix<double> full(n_p, velocity_local.size());
          full = divergence;
          full.compute_svd();
          const double reference = full.singular_value(0);

          LAPACKFullMatrix<double> restricted(n_p, free_velocity.size());
          for (unsigned int k = 0; k < n_p; ++k)
            for (unsigned int j = 0; j < free_velocity.size(); ++j)
              restricted(k, j) = divergence(k, free_velocity[j]);
          restricted.compute_svd();
          const unsigned int n_values
            = std::min<unsigned int>(n_p, free_velocity.size());
          unsigned int rank = 0;
          while (rank < n_values
                 && restricted.singular_value(rank) > 1e-10 * reference)
            ++rank;
          if (rank == n_p)
            continue;

          // left singular vectors beyond the rank span the null space
          const LAPACKFullMatrix<double> &u = restricted.get_svd_u();
          FullMatrix<double>              null_basis(n_p, n_p - rank);
          for (unsigned int k = 0; k < n_p; ++k)
            for (unsigned int l = rank; l < n_p; ++l)
              null_basis(k, l - rank) = u(k, l);
          for (const unsigned int row : pivot_rows(null_basis))
            undetermined.push_back(dofs[pressure_local[row]]);
        }
      std::sort(undetermined.begin(), undetermined.end());
      return undetermined;
    }



    template std::vector<types::global_dof_index>
    find_undetermined_pressure_dofs<2>(
      const DoFHandler<2> &,
      const Mapping<2> &,
      const AffineConstraints<double> &,
      const std::vector<types::global_dof_index> &);
    template std::vector<types::global_dof_index>
    find_undetermined_pressure_dofs<3>(
      const DoFHandler<3> &,
      const Mapping<3> &,
      const AffineConstraints<double> &,
      const std::vector<types::global_dof_index> &);
  } // namespace fluid
} // namespace particulate
