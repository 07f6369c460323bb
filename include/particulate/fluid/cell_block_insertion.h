#ifndef particulate_fluid_cell_block_insertion_h
#define particulate_fluid_cell_block_insertion_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Epetra_CrsMatrix.h>

namespace particulate {
  namespace fluid {
    /**
     * Adds one cell's part of a local matrix into one block of a distributed
     * Trilinos matrix whose sparsity pattern already holds every coupling of
     * the cell.
     *
     * Why not SparseMatrix::add (what AffineConstraints'
     * distribute_local_to_global calls row by row): Epetra translates every
     * column of every row from its global index through a hash table and
     * then finds it in the row by binary search; for the 81 x 81 velocity
     * block of a Q2 hexahedron that was as costly as computing the entries
     * (doc/performance.md, "Assembling the Jacobian"). Here each column is
     * translated once per cell and sorted, and every locally owned row of
     * the cell is merged with the matrix's sorted row in one pass, adding
     * through Epetra's row view.
     *
     * Rows and columns to leave out (constrained velocities, decoupled
     * pressures) are given as numbers::invalid_dof_index. Rows another rank
     * owns go through SparseMatrix::add, which keeps them for compress().
     * The matrix must be filled with sorted local column indices
     * (applicable()); constraints other than plain Dirichlet rows are the
     * caller's to leave to AffineConstraints.
     */
    class CellBlockInsertion
    {
    public:
      /** Whether @p matrix takes direct additions: it has its final
       *  structure with local column indices (FillComplete() also sorts
       *  every row's; a row found unsorted stops add() with an error). */
      static bool
      applicable(const dealii::TrilinosWrappers::SparseMatrix &matrix)
      {
        const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
        return A.Filled() && A.IndicesAreLocal();
      }

      /** matrix(rows[i], columns[j]) += value(i, j) for every row and
       *  column not left out (indices within the block). */
      template <typename ValueOf>
      void
      add(dealii::TrilinosWrappers::SparseMatrix             &matrix,
          const std::vector<dealii::types::global_dof_index> &rows,
          const std::vector<dealii::types::global_dof_index> &columns,
          const ValueOf                                      &value)
      {
        using dealii::numbers::invalid_dof_index;
        const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
        sorted_columns.clear();
        bool all_columns_local = true;
        for (unsigned int j = 0; j < columns.size(); ++j)
          if (columns[j] != invalid_dof_index)
            {
              const int local = A.ColMap().LID(global_id(columns[j]));
              all_columns_local &= local >= 0;
              sorted_columns.emplace_back(local, j);
            }
        std::sort(sorted_columns.begin(), sorted_columns.end());
        positions.clear(); // found for another set of columns

        for (unsigned int i = 0; i < rows.size(); ++i)
          {
            if (rows[i] == invalid_dof_index)
              continue;
            const int local_row = A.RowMap().LID(global_id(rows[i]));
            if (local_row < 0 || !all_columns_local)
              {
                add_through_global_indices(matrix, rows[i], i, columns, value);
                continue;
              }
            int     n_entries = 0;
            double *entries   = nullptr;
            int    *indices   = nullptr;
            A.ExtractMyRowView(local_row, n_entries, entries, indices);
            if (!positions_fit(n_entries, indices))
              find_positions(n_entries, indices);
            for (unsigned int m = 0; m < sorted_columns.size(); ++m)
              entries[positions[m]] += value(i, sorted_columns[m].second);
          }
      }

      /**
       * Whether add_saddle_point_cell() gives what
       * AffineConstraints::distribute_local_to_global would: the blocks
       * (0,0), (0,1), (1,0) take direct additions, and every constraint is
       * a plain Dirichlet row of a velocity (no DoF coupled to others, as
       * at hanging nodes or on a slip plane that is not a coordinate
       * plane, and no pressure constrained).
       */
      static bool
      applicable(const dealii::TrilinosWrappers::BlockSparseMatrix &matrix,
                 const dealii::AffineConstraints<double>           &constraints,
                 const dealii::types::global_dof_index n_velocity_dofs)
      {
        if (!applicable(matrix.block(0, 0)) || !applicable(matrix.block(0, 1))
            || !applicable(matrix.block(1, 0)))
          return false;
        for (const auto &line : constraints.get_lines())
          if (!line.entries.empty() || line.index >= n_velocity_dofs)
            return false;
        return true;
      }

      /**
       * One cell of a saddle-point matrix [A B^T; B 0] whose velocity DoFs
       * are numbered before the pressure DoFs: A(i, j) = a(i, j) for the
       * cell's velocity DoFs @p velocity_dofs, B(k, j) = b(k, j) for its
       * pressure DoFs @p pressure_dofs (system numbering;
       * invalid_dof_index for a pressure that is to have no row and no
       * column). Constrained velocities get no row and no column, and the
       * diagonal entry distribute_local_to_global gives them: |a(i, i)|, or
       * where that is zero zero_diagonal_replacement().
       */
      template <typename AValue, typename BValue>
      void
      add_saddle_point_cell(
        dealii::TrilinosWrappers::BlockSparseMatrix        &matrix,
        const dealii::AffineConstraints<double>            &constraints,
        const std::vector<dealii::types::global_dof_index> &velocity_dofs,
        const std::vector<dealii::types::global_dof_index> &pressure_dofs,
        const dealii::types::global_dof_index               n_velocity_dofs,
        const AValue                                       &a,
        const BValue                                       &b,
        const unsigned int                                  n_cell_dofs)
      {
        using dealii::numbers::invalid_dof_index;
        velocity_kept.resize(velocity_dofs.size());
        for (unsigned int i = 0; i < velocity_dofs.size(); ++i)
          velocity_kept[i] = constraints.is_constrained(velocity_dofs[i]) ?
                               invalid_dof_index :
                               velocity_dofs[i];
        pressure_kept.resize(pressure_dofs.size());
        for (unsigned int k = 0; k < pressure_dofs.size(); ++k)
          pressure_kept[k] = pressure_dofs[k] == invalid_dof_index ?
                               invalid_dof_index :
                               pressure_dofs[k] - n_velocity_dofs;
        add(matrix.block(0, 0), velocity_kept, velocity_kept, a);
        add(matrix.block(0, 1),
            velocity_kept,
            pressure_kept,
            [&](const unsigned int i, const unsigned int k) {
              return b(k, i);
            });
        add(matrix.block(1, 0), pressure_kept, velocity_kept, b);

        double fallback = -1.; // for a zero diagonal entry, when first needed
        for (unsigned int i = 0; i < velocity_dofs.size(); ++i)
          if (velocity_kept[i] == invalid_dof_index)
            {
              double diagonal = std::abs(a(i, i));
              if (diagonal == 0.)
                {
                  if (fallback < 0.)
                    fallback = zero_diagonal_replacement(a,
                                                         b,
                                                         velocity_dofs.size(),
                                                         n_cell_dofs);
                  diagonal = fallback;
                }
              matrix.block(0, 0).add(velocity_dofs[i],
                                     velocity_dofs[i],
                                     diagonal);
            }
      }

    private:
      /** What distribute_local_to_global puts on a constrained row whose
       *  local diagonal entry is zero: the average |diagonal| of the local
       *  matrix of @p n_cell_dofs DoFs (the pressures' are zero); where all
       *  are zero its l1 norm (largest column sum) over @p n_cell_dofs; 1
       *  if the local matrix is zero. Decoupled pressures (pressure_kept)
       *  have no entries, as the cell matrix the reference path sees. */
      template <typename AValue, typename BValue>
      double
      zero_diagonal_replacement(const AValue      &a,
                                const BValue      &b,
                                const unsigned int n_velocities,
                                const unsigned int n_cell_dofs) const
      {
        double average = 0.;
        for (unsigned int i = 0; i < n_velocities; ++i)
          average += std::abs(a(i, i));
        if (average != 0.)
          return average / n_cell_dofs;
        double l1_norm = 0.;
        for (unsigned int j = 0; j < n_velocities; ++j)
          {
            double column = 0.;
            for (unsigned int i = 0; i < n_velocities; ++i)
              column += std::abs(a(i, j));
            for (unsigned int k = 0; k < pressure_kept.size(); ++k)
              if (pressure_kept[k] != dealii::numbers::invalid_dof_index)
                column += std::abs(b(k, j));
            l1_norm = std::max(l1_norm, column);
          }
        for (unsigned int k = 0; k < pressure_kept.size(); ++k)
          if (pressure_kept[k] != dealii::numbers::invalid_dof_index)
            {
              double column = 0.;
              for (unsigned int i = 0; i < n_velocities; ++i)
                column += std::abs(b(k, i));
              l1_norm = std::max(l1_norm, column);
            }
        return l1_norm != 0. ? l1_norm / n_cell_dofs : 1.;
      }

      static dealii::TrilinosWrappers::types::int_type
      global_id(const dealii::types::global_dof_index index)
      {
        return static_cast<dealii::TrilinosWrappers::types::int_type>(index);
      }

      /** One row by global indices (a row another rank owns). */
      template <typename ValueOf>
      void
      add_through_global_indices(
        dealii::TrilinosWrappers::SparseMatrix             &matrix,
        const dealii::types::global_dof_index               row,
        const unsigned int                                  i,
        const std::vector<dealii::types::global_dof_index> &columns,
        const ValueOf                                      &value)
      {
        row_columns.clear();
        row_values.clear();
        for (unsigned int j = 0; j < columns.size(); ++j)
          if (columns[j] != dealii::numbers::invalid_dof_index)
            {
              row_columns.push_back(columns[j]);
              row_values.push_back(value(i, j));
            }
        matrix.add(row,
                   row_columns.size(),
                   row_columns.data(),
                   row_values.data(),
                   false);
      }

      /**
       * Whether the positions found for an earlier row of this cell hold
       * the cell's columns in this row too. Rows of one node's components
       * (and the pressure rows of one cell) have the same columns, so most
       * rows take the positions of the row before after checking them (one
       * comparison per column, instead of a pass over the row's ~375
       * entries in 3D).
       */
      bool
      positions_fit(const int n_entries, const int *indices) const
      {
        if (positions.size() != sorted_columns.size()
            || n_entries != positions_row_length)
          return false;
        for (unsigned int m = 0; m < positions.size(); ++m)
          if (indices[positions[m]] != sorted_columns[m].first)
            return false;
        return true;
      }

      /** Positions of the cell's columns in a row: one merging pass. */
      void
      find_positions(const int n_entries, const int *indices)
      {
        positions.resize(sorted_columns.size());
        positions_row_length = n_entries;
        int k                = 0;
        for (unsigned int m = 0; m < sorted_columns.size(); ++m)
          {
            const int local_column = sorted_columns[m].first;
            while (k < n_entries && indices[k] < local_column)
              ++k;
            AssertThrow(k < n_entries && indices[k] == local_column,
                        dealii::ExcMessage(
                          "A coupling of the cell is missing from the "
                          "matrix's sparsity pattern."));
            positions[m] = k;
          }
      }

      /// (local column index, position in the cell's column list)
      std::vector<std::pair<int, unsigned int>> sorted_columns;
      /// where sorted_columns stand in the last row merged, of that length
      std::vector<int>                             positions;
      int                                          positions_row_length = -1;
      std::vector<dealii::types::global_dof_index> row_columns;
      std::vector<double>                          row_values;
      /// the cell's indices within the blocks, invalid where left out
      std::vector<dealii::types::global_dof_index> velocity_kept;
      std::vector<dealii::types::global_dof_index> pressure_kept;
    };
  } // namespace fluid
} // namespace particulate

#endif
