#include <particulate/fluid/pressure_laplacian.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>

#include <EpetraExt_MatrixMatrix.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_FECrsMatrix.h>
#include <Epetra_Vector.h>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      // Epetra's row views: deal.II's row iterators copy a row per
      // construction, far too slow for O(nnz) passes over 1e5 rows.
      std::tuple<int, double *, int *>
      row_view(const Epetra_CrsMatrix &matrix, const int local_row)
      {
        int     n       = 0;
        double *values  = nullptr;
        int    *columns = nullptr;
        matrix.ExtractMyRowView(local_row, n, values, columns);
        return {n, values, columns};
      }

      /// deal.II 9.4 hands out the Epetra matrix as const only; changing
      /// its values keeps its structure, which is all the wrapper keeps of
      /// it
      Epetra_CrsMatrix &
      writable(TrilinosWrappers::SparseMatrix &matrix)
      {
        return const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
      }

      const Epetra_Vector &
      epetra(const TrilinosWrappers::MPI::Vector &vector)
      {
        return *vector.trilinos_vector()(0);
      }

      /// local index of the diagonal entry in each row, -1 where the row
      /// stores none
      std::vector<int>
      diagonal_positions(const Epetra_CrsMatrix &matrix)
      {
        std::vector<int> position(matrix.NumMyRows(), -1);
        for (int local = 0; local < matrix.NumMyRows(); ++local)
          {
            const auto [n, values, columns] = row_view(matrix, local);
            const auto row = TrilinosWrappers::global_row_index(matrix, local);
            for (int k = 0; k < n; ++k)
              if (TrilinosWrappers::global_column_index(matrix, columns[k])
                  == row)
                position[local] = k;
          }
        return position;
      }

      /// `matrix` with a (zero) diagonal entry added in every row that
      /// stores none: a new matrix where one was missing (collective).
      /// Returns the diagonal_positions() of the result, so that callers
      /// need not search the rows again (the search is about half the cost
      /// of an L_p update).
      std::vector<int>
      store_every_diagonal(TrilinosWrappers::SparseMatrix &matrix)
      {
        const auto position = diagonal_positions(matrix.trilinos_matrix());
        const bool complete
          = std::find(position.begin(), position.end(), -1) == position.end();
        if (Utilities::MPI::min(complete ? 1 : 0, matrix.get_mpi_communicator())
            == 1)
          return position;
        const Epetra_CrsMatrix           &source = matrix.trilinos_matrix();
        TrilinosWrappers::SparsityPattern pattern(
          matrix.locally_owned_range_indices(),
          matrix.locally_owned_domain_indices(),
          matrix.get_mpi_communicator());
        std::vector<types::global_dof_index> global_columns;
        for (int local = 0; local < source.NumMyRows(); ++local)
          {
            const auto [n, values, columns] = row_view(source, local);
            const auto row = TrilinosWrappers::global_row_index(source, local);
            global_columns.assign(1, row);
            for (int k = 0; k < n; ++k)
              global_columns.push_back(
                TrilinosWrappers::global_column_index(source, columns[k]));
            std::sort(global_columns.begin(), global_columns.end());
            global_columns.erase(std::unique(global_columns.begin(),
                                             global_columns.end()),
                                 global_columns.end());
            pattern.add_entries(row,
                                global_columns.begin(),
                                global_columns.end(),
                                true);
          }
        pattern.compress();

        TrilinosWrappers::SparseMatrix completed(pattern);
        std::vector<TrilinosScalar>    row_values;
        for (int local = 0; local < source.NumMyRows(); ++local)
          {
            const auto [n, values, columns] = row_view(source, local);
            const auto row = TrilinosWrappers::global_row_index(source, local);
            global_columns.clear();
            row_values.clear();
            for (int k = 0; k < n; ++k)
              {
                global_columns.push_back(
                  TrilinosWrappers::global_column_index(source, columns[k]));
                row_values.push_back(values[k]);
              }
            completed.set(row,
                          global_columns.size(),
                          global_columns.data(),
                          row_values.data(),
                          false);
          }
        completed.compress(VectorOperation::insert);
        matrix.copy_from(completed);
        return diagonal_positions(matrix.trilinos_matrix());
      }

      /// (D^{-1/2} S B^T) with S selecting the rows `rows` (owned, sorted):
      /// the factor X of sum_{i in rows} b_i b_i^T / D_i = X^T X
      std::unique_ptr<Epetra_CrsMatrix>
      scaled_rows(const Epetra_CrsMatrix                     &gradient,
                  const Epetra_Vector                        &inverse_mass,
                  const std::vector<types::global_dof_index> &rows)
      {
        // global column indices: the column map is built from the columns
        // these rows use, not all of B^T's
        auto factor
          = std::make_unique<Epetra_CrsMatrix>(Copy, gradient.RowMap(), 0);
        std::vector<double> scaled;
        std::vector<int>    global_columns;
        for (const auto row : rows)
          {
            const int local = gradient.LRID(
              static_cast<TrilinosWrappers::types::int_type>(row));
            const int in_vector = inverse_mass.Map().LID(
              static_cast<TrilinosWrappers::types::int_type>(row));
            AssertThrow(local >= 0 && in_vector >= 0,
                        ExcMessage("L_p: velocity DoF " + std::to_string(row)
                                   + " is not locally owned."));
            const auto [n, values, columns] = row_view(gradient, local);
            const double factor_of_row = std::sqrt(inverse_mass[in_vector]);
            scaled.resize(n);
            global_columns.resize(n);
            for (int k = 0; k < n; ++k)
              {
                scaled[k]         = factor_of_row * values[k];
                global_columns[k] = gradient.GCID(columns[k]);
              }
            AssertThrow(factor->InsertGlobalValues(gradient.GRID(local),
                                                   n,
                                                   scaled.data(),
                                                   global_columns.data())
                          >= 0,
                        ExcMessage("Epetra could not copy a row of B^T."));
          }
        AssertThrow(factor->FillComplete(gradient.DomainMap(),
                                         gradient.RangeMap())
                      == 0,
                    ExcMessage("Epetra could not complete a factor of L_p."));
        return factor;
      }

      /// X^T X, keeping every entry the structure produces (also exact
      /// zeros of symmetric meshes: a later update must find them). The
      /// transpose is formed here, rows sent to the owners of the pressures
      /// (an FE matrix's global assembly), and the product taken without
      /// transposition: EpetraExt's transposed product A^T B came out wrong
      /// on several ranks when A has empty rows (Trilinos 13.2; found by
      /// tests/fluid/pressure_laplacian_update.cc), and a factor of the
      /// covered velocities has empty rows everywhere else.
      void
      gram_product(const std::unique_ptr<Epetra_CrsMatrix> &factor,
                   Epetra_CrsMatrix                        &result)
      {
        const Epetra_Map  &pressures = factor->DomainMap();
        Epetra_FECrsMatrix transpose(Copy, pressures, 0);
        for (int local = 0; local < factor->NumMyRows(); ++local)
          {
            const auto [n, values, columns] = row_view(*factor, local);
            int row                         = factor->GRID(local);
            for (int k = 0; k < n; ++k)
              {
                int column = factor->GCID(columns[k]);
                AssertThrow(
                  transpose.InsertGlobalValues(1, &column, 1, &row, &values[k])
                    >= 0,
                  ExcMessage("Epetra could not transpose B^T."));
              }
          }
        AssertThrow(transpose.GlobalAssemble(factor->RangeMap(), pressures)
                      == 0,
                    ExcMessage("Epetra could not transpose B^T."));
        AssertThrow(EpetraExt::MatrixMatrix::Multiply(transpose,
                                                      false,
                                                      *factor,
                                                      false,
                                                      result,
                                                      true,
                                                      true)
                      == 0,
                    ExcMessage("EpetraExt could not form B D^-1 B^T."));
      }
    } // namespace



    void
    regularise_empty_pressure_rows(TrilinosWrappers::SparseMatrix &matrix,
                                   types::global_dof_index &first_flow_row)
    {
      const MPI_Comm    communicator = matrix.get_mpi_communicator();
      const auto        position     = store_every_diagonal(matrix);
      Epetra_CrsMatrix &product      = writable(matrix);
      double            largest      = 0.;
      for (int local = 0; local < product.NumMyRows(); ++local)
        {
          const auto [n, values, columns] = row_view(product, local);
          largest = std::max(largest, std::abs(values[position[local]]));
        }
      largest = Utilities::MPI::max(largest, communicator);

      first_flow_row = numbers::invalid_dof_index;
      for (int local = 0; local < product.NumMyRows(); ++local)
        {
          const auto [n, values, columns] = row_view(product, local);
          if (std::abs(values[position[local]]) > 1e-12 * largest)
            first_flow_row = std::min<types::global_dof_index>(
              first_flow_row,
              TrilinosWrappers::global_row_index(product, local));
          else
            {
              std::fill(values, values + n, 0.);
              values[position[local]] = largest;
            }
        }
      first_flow_row = Utilities::MPI::min(first_flow_row, communicator);
    }



    void
    PressureLaplacian::clear()
    {
      base.clear();
      base_mesh_fixed.clear();
      has_base = false;
    }



    bool
    PressureLaplacian::keeps_structure(
      const std::vector<types::global_dof_index> &mesh_fixed) const
    {
      if (!has_base)
        return false;
      return Utilities::MPI::min(mesh_fixed == base_mesh_fixed ? 1 : 0,
                                 base.get_mpi_communicator())
             == 1;
    }



    types::global_dof_index
    PressureLaplacian::update(
      TrilinosWrappers::SparseMatrix             &laplacian,
      const TrilinosWrappers::SparseMatrix       &gradient,
      const TrilinosWrappers::MPI::Vector        &inverse_mass,
      const std::vector<types::global_dof_index> &mesh_fixed,
      const std::vector<types::global_dof_index> &covered,
      const TrilinosWrappers::MPI::Vector        &free_pressure)
    {
      const Epetra_CrsMatrix &b_transpose = gradient.trilinos_matrix();
      if (!keeps_structure(mesh_fixed))
        {
          // L_base over the velocities not fixed by the mesh
          std::vector<types::global_dof_index> not_fixed;
          not_fixed.reserve(b_transpose.NumMyRows());
          for (int local = 0; local < b_transpose.NumMyRows(); ++local)
            {
              const types::global_dof_index row
                = TrilinosWrappers::global_row_index(b_transpose, local);
              if (!std::binary_search(mesh_fixed.begin(),
                                      mesh_fixed.end(),
                                      row))
                not_fixed.push_back(row);
            }
          std::sort(not_fixed.begin(), not_fixed.end());
          Epetra_CrsMatrix sum(Copy, b_transpose.DomainMap(), 0);
          gram_product(scaled_rows(b_transpose,
                                   epetra(inverse_mass),
                                   not_fixed),
                       sum);
          base.reinit(sum, true);
          store_every_diagonal(base);
          base_mesh_fixed = mesh_fixed;
          has_base        = true;
          laplacian.copy_from(base);
        }
      else
        {
          // values only: laplacian is a copy of base (same Epetra
          // structure, row by row), changed in values since
          const Epetra_CrsMatrix &from = base.trilinos_matrix();
          Epetra_CrsMatrix       &to   = writable(laplacian);
          AssertThrow(from.NumMyRows() == to.NumMyRows()
                        && from.NumMyNonzeros() == to.NumMyNonzeros(),
                      ExcMessage("L_p lost the structure of L_base."));
          for (int local = 0; local < from.NumMyRows(); ++local)
            {
              const auto [n, values, columns]          = row_view(from, local);
              const auto [n_to, values_to, columns_to] = row_view(to, local);
              AssertThrow(n == n_to,
                          ExcMessage("L_p lost the structure of L_base."));
              std::memcpy(values_to, values, n * sizeof(double));
            }
        }

      // minus the covered velocities' part
      Epetra_CrsMatrix &result = writable(laplacian);
      Epetra_CrsMatrix  covered_part(Copy, b_transpose.DomainMap(), 0);
      gram_product(scaled_rows(b_transpose, epetra(inverse_mass), covered),
                   covered_part);
      AssertThrow(
        EpetraExt::MatrixMatrix::Add(covered_part, false, -1., result, 1.) == 0,
        ExcMessage("EpetraExt could not subtract the covered nodes from L_p "
                   "(an entry outside the structure of L_base)."));

      // rows and columns of decoupled pressures
      AssertThrow(result.LeftScale(epetra(free_pressure)) == 0
                    && result.RightScale(epetra(free_pressure)) == 0,
                  ExcMessage("Epetra could not scale L_p."));
      types::global_dof_index first_flow_row;
      regularise_empty_pressure_rows(laplacian, first_flow_row);
      return first_flow_row;
    }



    std::size_t
    PressureLaplacian::memory_consumption() const
    {
      return (has_base ? base.memory_consumption() : 0)
             + base_mesh_fixed.capacity() * sizeof(types::global_dof_index);
    }
  } // namespace fluid
} // namespace particulate
