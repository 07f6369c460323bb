#include "flow_pressure_mode.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <map>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /** Subtracts from @p mode the combination of the patch's null modes
       *  that makes it zero on the patch's decoupled rows. */
      void
      cancel_on_decoupled_rows(const PatchNullModes                      &patch,
                               std::map<types::global_dof_index, double> &mode)
      {
        const unsigned int k = patch.pinned.size();
        FullMatrix<double> pinned_block(k, k);
        Vector<double>     on_pinned(k), weights(k);
        bool               nonzero = false;
        for (unsigned int i = 0; i < k; ++i)
          {
            const auto found = mode.find(patch.rows[patch.pinned[i]]);
            on_pinned(i)     = found == mode.end() ? 0. : found->second;
            nonzero |= on_pinned(i) != 0.;
            for (unsigned int j = 0; j < k; ++j)
              pinned_block(i, j) = patch.basis(patch.pinned[i], j);
          }
        if (!nonzero)
          return;
        pinned_block.gauss_jordan();
        pinned_block.vmult(weights, on_pinned);
        for (unsigned int r = 0; r < patch.rows.size(); ++r)
          {
            double change = 0.;
            for (unsigned int j = 0; j < k; ++j)
              change += patch.basis(r, j) * weights(j);
            mode[patch.rows[r]] -= change;
          }
      }
    } // namespace



    template <int dim>
    bool
    constant_pressure_is_null_mode(
      const DoFHandler<dim>           &dof_handler,
      const Mapping<dim>              &mapping,
      const AffineConstraints<double> &zero_constraints,
      const IndexSet                  &owned_velocities,
      const IndexSet                  &relevant_dofs,
      MPI_Comm                         communicator)
    {
      const auto               &fe = dof_handler.get_fe();
      const QGauss<dim>         quadrature(fe.degree + 1);
      FEValues<dim>             fe_values(mapping,
                              fe,
                              quadrature,
                              update_gradients | update_JxW_values);
      AffineConstraints<double> hanging(relevant_dofs);
      DoFTools::make_hanging_node_constraints(dof_handler, hanging);
      hanging.close();

      TrilinosWrappers::MPI::Vector        flux(owned_velocities, communicator);
      double                               scale = 0.;
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::vector<types::global_dof_index> velocity_dofs;
      std::vector<double>                  velocity_flux;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dofs);
            velocity_dofs.clear();
            velocity_flux.clear();
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                if (c == dim)
                  continue;
                double cell_flux = 0.;
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  cell_flux += fe_values.shape_grad_component(i, q, c)[c]
                               * fe_values.JxW(q);
                scale = std::max(scale, std::abs(cell_flux));
                velocity_dofs.push_back(dofs[i]);
                velocity_flux.push_back(cell_flux);
              }
            // velocity DoFs are numbered first: their global indices are
            // those of the velocity block
            hanging.distribute_local_to_global(velocity_flux.begin(),
                                               velocity_flux.end(),
                                               velocity_dofs.begin(),
                                               flux);
          }
      flux.compress(VectorOperation::add);

      double largest = 0.;
      for (const auto dof : flux.locally_owned_elements())
        if (!zero_constraints.is_constrained(dof))
          largest = std::max(largest, std::abs(flux(dof)));
      return Utilities::MPI::max(largest, communicator)
             <= 1e-10 * Utilities::MPI::max(scale, communicator);
    }



    std::vector<std::pair<types::global_dof_index, double>>
    enclosed_flow_pressure_mode(
      const std::vector<types::global_dof_index> &flow_constants,
      const std::vector<PatchNullModes>          &patches,
      const std::vector<types::global_dof_index> &decoupled)
    {
      std::map<types::global_dof_index, double> mode;
      for (const auto dof : flow_constants)
        mode[dof] = 1.;
      for (const PatchNullModes &patch : patches)
        cancel_on_decoupled_rows(patch, mode);

      // the decoupled rows are zero to round-off now; drop them exactly
      std::vector<std::pair<types::global_dof_index, double>> result;
      for (const auto &[dof, value] : mode)
        if (value != 0.
            && !std::binary_search(decoupled.begin(), decoupled.end(), dof))
          result.emplace_back(dof, value);
      return result;
    }

    template bool
    constant_pressure_is_null_mode<2>(const DoFHandler<2> &,
                                      const Mapping<2> &,
                                      const AffineConstraints<double> &,
                                      const IndexSet &,
                                      const IndexSet &,
                                      MPI_Comm);
    template bool
    constant_pressure_is_null_mode<3>(const DoFHandler<3> &,
                                      const Mapping<3> &,
                                      const AffineConstraints<double> &,
                                      const IndexSet &,
                                      const IndexSet &,
                                      MPI_Comm);
  } // namespace fluid
} // namespace particulate
