#ifndef particulate_fluid_pressure_laplacian_amg_h
#define particulate_fluid_pressure_laplacian_amg_h

#include <particulate/fluid/fluid_parameters.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * Builds @p amg, ML's smoothed-aggregation V-cycle of the pressure
     * Laplacian @p laplacian (L_p = B D^{-1} B^T on the P1disc pressures,
     * numbered after @p first_pressure_dof in @p dof_handler), with
     * @p smoother ('Pressure Laplacian smoother').
     *
     * Where the numbering keeps the dim + 1 pressure DoFs of each cell
     * consecutive, the aggregation works on cells and the near-null space
     * holds the constant and the linear pressures
     * (pressure_near_null_space(), computed into @p near_null_space when it
     * is empty: it depends on the mesh only). Otherwise one 0/1 vector per
     * pressure mode is the near-null space. Returns whether the
     * aggregation works on cells.
     */
    template <int dim>
    bool
    initialize_pressure_laplacian_amg(
      dealii::TrilinosWrappers::PreconditionAMG    &amg,
      const dealii::TrilinosWrappers::SparseMatrix &laplacian,
      const dealii::DoFHandler<dim>                &dof_handler,
      const dealii::Mapping<dim>                   &mapping,
      const dealii::IndexSet                       &owned_pressures,
      const dealii::types::global_dof_index         first_pressure_dof,
      const PressureLaplacianSmoother               smoother,
      std::vector<double>                          &near_null_space,
      const MPI_Comm                                communicator);
  } // namespace fluid
} // namespace particulate

#endif
