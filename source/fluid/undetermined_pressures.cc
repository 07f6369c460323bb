#include "undetermined_pressures.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /**
       * Rows of `null_basis` (n x k, columns spanning the null space) to
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



      /// The divergence block of one cell next to a body: (q_k, div v_j)
      /// for its pressures q_k and its free velocity DoFs v_j.
      struct CellBlock
      {
        std::vector<types::global_dof_index> pressures;
        std::vector<types::global_dof_index> free_velocities;
        FullMatrix<double>                   divergence;
        /// largest singular value of the cell's block on all velocities
        double scale = 0.;
      };
    } // namespace



    template <int dim>
    UndeterminedPressures
    find_undetermined_pressure_dofs(
      const DoFHandler<dim>                      &dof_handler,
      const Mapping<dim>                         &mapping,
      const AffineConstraints<double>            &zero_constraints,
      const std::vector<types::global_dof_index> &prescribed_dofs,
      const std::vector<types::global_dof_index> &joint_dofs)
    {
      std::set<types::global_dof_index> pinned;
      UndeterminedPressures             found;
      if (prescribed_dofs.empty())
        return found;

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

      // 1. The cells touching a body. Those without a free velocity lose
      //    all their pressures at once; the others keep their block.
      std::map<unsigned int, CellBlock>    blocks; // by active cell index
      std::vector<types::global_dof_index> dofs(n_dofs);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          cell->get_dof_indices(dofs);
          bool touches_body = false, all_constrained = true, at_joint = false;
          std::vector<unsigned int> free; // positions in velocity_local
          for (unsigned int j = 0; j < velocity_local.size(); ++j)
            {
              const auto dof = dofs[velocity_local[j]];
              touches_body |= std::binary_search(prescribed_dofs.begin(),
                                                 prescribed_dofs.end(),
                                                 dof);
              at_joint |= std::binary_search(joint_dofs.begin(),
                                             joint_dofs.end(),
                                             dof);
              all_constrained &= zero_constraints.is_constrained(dof);
              if (!is_fixed_by_constraint(zero_constraints, dof))
                free.push_back(j);
            }
          if (!touches_body)
            continue;
          if (all_constrained || free.empty() || at_joint)
            {
              for (const unsigned int k : pressure_local)
                pinned.insert(dofs[k]);
              continue;
            }

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
          // largest singular value of the block on all velocities, from
          // its n_p x n_p Gram matrix
          FullMatrix<double> gram_full(n_p, n_p);
          divergence.mTmult(gram_full, divergence);
          LAPACKFullMatrix<double> gram(n_p, n_p);
          gram = gram_full;
          gram.compute_svd();

          CellBlock &block = blocks[cell->active_cell_index()];
          block.scale      = std::sqrt(gram.singular_value(0));
          for (const unsigned int k : pressure_local)
            block.pressures.push_back(dofs[k]);
          block.divergence.reinit(n_p, free.size());
          for (unsigned int j = 0; j < free.size(); ++j)
            {
              block.free_velocities.push_back(dofs[velocity_local[free[j]]]);
              for (unsigned int k = 0; k < n_p; ++k)
                block.divergence(k, j) = divergence(k, free[j]);
            }
        }

      // 2. Null modes on patches: a cell next to a body with its face
      //    neighbours that also touch it (locally owned; a mode across a
      //    partition boundary is not seen). A left null vector of the patch
      //    block, on all free velocities of the patch cells, is one of the
      //    whole system: outside the patch its pressures are zero. Patches
      //    are taken one after the other, each without the pressures already
      //    pinned, so every pin removes a mode that is still there (pinning
      //    a component of a null vector never removes an equation).
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned()
              || blocks.count(cell->active_cell_index()) == 0)
            continue;
          std::vector<const CellBlock *> patch{
            &blocks.at(cell->active_cell_index())};
          for (const unsigned int f : cell->face_indices())
            if (!cell->at_boundary(f) && !cell->neighbor_is_coarser(f))
              {
                const auto neighbor = cell->neighbor(f);
                if (neighbor->is_active() && neighbor->is_locally_owned()
                    && blocks.count(neighbor->active_cell_index()) > 0)
                  patch.push_back(&blocks.at(neighbor->active_cell_index()));
              }

          std::vector<types::global_dof_index>            rows;
          std::map<types::global_dof_index, unsigned int> columns;
          double                                          scale = 0.;
          for (const CellBlock *block : patch)
            {
              for (const auto p : block->pressures)
                if (pinned.count(p) == 0)
                  rows.push_back(p);
              for (const auto v : block->free_velocities)
                columns.emplace(v, columns.size());
              scale = std::max(scale, block->scale);
            }
          if (rows.empty())
            continue;
          FullMatrix<double> patch_block(rows.size(), columns.size());
          for (const CellBlock *block : patch)
            for (unsigned int k = 0; k < block->pressures.size(); ++k)
              {
                const auto row
                  = std::find(rows.begin(), rows.end(), block->pressures[k]);
                if (row == rows.end())
                  continue;
                for (unsigned int j = 0; j < block->free_velocities.size(); ++j)
                  patch_block(row - rows.begin(),
                              columns.at(block->free_velocities[j]))
                    += block->divergence(k, j);
              }
          // The Gram matrix P P^T (rows x rows) has the same left singular
          // vectors, with the squared singular values: far cheaper than the
          // SVD of the wide P itself, whose right factor is columns^2. Its
          // eigenvalues are exact only to about 1e-16 of the largest, so a
          // mode counts as null below 1e-12 of scale^2 (a singular value
          // below 1e-6 of the cell's largest).
          FullMatrix<double> gram_full(rows.size(), rows.size());
          patch_block.mTmult(gram_full, patch_block);
          LAPACKFullMatrix<double> gram(rows.size(), rows.size());
          gram = gram_full;
          gram.compute_svd();
          unsigned int rank = 0;
          while (rank < rows.size()
                 && gram.singular_value(rank) > 1e-12 * scale * scale)
            ++rank;
          if (rank == rows.size())
            continue;

          // left singular vectors beyond the rank span the null space
          const LAPACKFullMatrix<double> &u = gram.get_svd_u();
          FullMatrix<double> null_basis(rows.size(), rows.size() - rank);
          for (unsigned int k = 0; k < rows.size(); ++k)
            for (unsigned int l = rank; l < rows.size(); ++l)
              null_basis(k, l - rank) = u(k, l);
          PatchNullModes modes{rows, null_basis, pivot_rows(null_basis)};
          for (const unsigned int row : modes.pinned)
            pinned.insert(rows[row]);
          found.patches.push_back(std::move(modes));
        }
      found.decoupled.assign(pinned.begin(), pinned.end());
      return found;
    }



    template UndeterminedPressures
    find_undetermined_pressure_dofs<2>(
      const DoFHandler<2> &,
      const Mapping<2> &,
      const AffineConstraints<double> &,
      const std::vector<types::global_dof_index> &,
      const std::vector<types::global_dof_index> &);
    template UndeterminedPressures
    find_undetermined_pressure_dofs<3>(
      const DoFHandler<3> &,
      const Mapping<3> &,
      const AffineConstraints<double> &,
      const std::vector<types::global_dof_index> &,
      const std::vector<types::global_dof_index> &);
  } // namespace fluid
} // namespace particulate
