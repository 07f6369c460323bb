#include "pressure_laplacian_amg.h"

#include <deal.II/fe/fe.h>

#include "pressure_near_null_space.h"
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    bool
    initialize_pressure_laplacian_amg(
      TrilinosWrappers::PreconditionAMG    &amg,
      const TrilinosWrappers::SparseMatrix &laplacian,
      const DoFHandler<dim>                &dof_handler,
      const Mapping<dim>                   &mapping,
      const IndexSet                       &owned_pressures,
      const types::global_dof_index         first_pressure_dof,
      const PressureLaplacianSmoother       smoother,
      std::vector<double>                  &near_null_space,
      const MPI_Comm                        communicator)
    {
      const FiniteElement<dim> &fe = dof_handler.get_fe();
      // Near-null space for ML: L_p's null space is the constant pressure,
      // the constant-mode DoF of every cell; its near-null space also holds
      // the linear pressures (pressure_near_null_space()). An aggregate of
      // linear-mode DoFs alone (where a cut cell's constant mode is
      // decoupled, see decoupled_pressure_dofs) would have a zero null
      // space, a singular tentative prolongator and a V-cycle that returns
      // NaN. So the aggregation works on cells: ML's "PDE equations" =
      // dim + 1 blocks the dim + 1 pressure DoFs of a cell, which the
      // numbering keeps consecutive (checked here), and every aggregate
      // holds a constant mode. Where the numbering does not, one 0/1
      // vector per mode is the fall-back, with coarse levels dim + 1 times
      // larger.
      const types::global_dof_index  n_owned = owned_pressures.n_elements();
      std::vector<std::vector<bool>> pressure_modes(dim + 1,
                                                    std::vector<bool>(n_owned,
                                                                      false));
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      bool cells_are_blocks = n_owned % (dim + 1) == 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            types::global_dof_index block = numbers::invalid_dof_index;
            for (unsigned int i = 0; i < dof_indices.size(); ++i)
              {
                const auto [component, mode] = fe.system_to_component_index(i);
                if (component != dim)
                  continue;
                const auto local = owned_pressures.index_within_set(
                  dof_indices[i] - first_pressure_dof);
                pressure_modes[mode][local] = true;
                if (block == numbers::invalid_dof_index)
                  block = local / (dim + 1);
                cells_are_blocks &= local / (dim + 1) == block;
              }
          }
      cells_are_blocks
        = Utilities::MPI::min(cells_are_blocks ? 1 : 0, communicator) == 1;

      // Smoother ('Pressure Laplacian smoother'): ILU(0) of the symmetric
      // L_p is symmetric, so the V-cycle stays a valid CG preconditioner;
      // where the smoother rather than the coarse space limits the inner
      // CG, ILU(0) needs several times fewer iterations than Chebyshev
      // (doc/performance.md).
      TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
      amg_data.elliptic              = true;
      amg_data.higher_order_elements = false;
      if (smoother == PressureLaplacianSmoother::ilu)
        {
          amg_data.smoother_type   = "ILU";
          amg_data.smoother_sweeps = 1;
        }
      else
        {
          amg_data.smoother_type   = "Chebyshev";
          amg_data.smoother_sweeps = 2;
        }
      amg_data.aggregation_threshold = 0.02;
      if (cells_are_blocks)
        {
          amg_data.constant_modes = {pressure_modes[0]};
          Teuchos::ParameterList              ml_parameters;
          std::unique_ptr<Epetra_MultiVector> distributed_modes;
          amg_data.set_parameters(ml_parameters, distributed_modes, laplacian);
          ml_parameters.set("PDE equations", static_cast<int>(dim + 1));
          // the constant and the linear pressures: with the constant alone
          // the coarse levels miss the slope of a smooth pressure inside an
          // aggregate (doc/performance.md)
          if (near_null_space.empty())
            near_null_space = pressure_near_null_space(mapping,
                                                       dof_handler,
                                                       owned_pressures,
                                                       first_pressure_dof,
                                                       communicator);
          ml_parameters.set("null space: type", "pre-computed");
          ml_parameters.set("null space: dimension", static_cast<int>(dim + 1));
          ml_parameters.set("null space: vectors", near_null_space.data());
          amg.initialize(laplacian, ml_parameters);
        }
      else
        {
          amg_data.constant_modes = pressure_modes;
          amg.initialize(laplacian, amg_data);
        }
      return cells_are_blocks;
    }

    template bool
    initialize_pressure_laplacian_amg<2>(TrilinosWrappers::PreconditionAMG &,
                                         const TrilinosWrappers::SparseMatrix &,
                                         const DoFHandler<2> &,
                                         const Mapping<2> &,
                                         const IndexSet &,
                                         const types::global_dof_index,
                                         const PressureLaplacianSmoother,
                                         std::vector<double> &,
                                         const MPI_Comm);
    template bool
    initialize_pressure_laplacian_amg<3>(TrilinosWrappers::PreconditionAMG &,
                                         const TrilinosWrappers::SparseMatrix &,
                                         const DoFHandler<3> &,
                                         const Mapping<3> &,
                                         const IndexSet &,
                                         const types::global_dof_index,
                                         const PressureLaplacianSmoother,
                                         std::vector<double> &,
                                         const MPI_Comm);
  } // namespace fluid
} // namespace particulate
