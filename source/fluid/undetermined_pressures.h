#ifndef particulate_fluid_undetermined_pressures_h
#define particulate_fluid_undetermined_pressures_h

// Private header of the fluid library: which discontinuous pressure modes no
// equation determines once fictitious-boundary bodies prescribe velocities.

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * Pressure DoFs (locally owned, sorted) to decouple from the flow.
     *
     * A P1disc pressure q of one cell enters the equations only through
     * (q, div v) for the velocity test functions v of that cell. When
     * constraints fix the value of some of those velocities (a body's
     * nodes, a wall), the cell's divergence block restricted to the free
     * ones, B_free (n_p x n_free), may lose rank: its left null vectors are
     * pressure modes that no equation sees. They make the Schur complement
     * and L_p = B D^{-1} B^T singular, which the AMG of L_p cannot cope with
     * (NaN in FGMRES, Newton stalling). This is common next to a body when
     * more nodes are covered (`Covered nodes = nearest`), and it is every
     * mode of a cell whose velocities are all constrained.
     *
     * For each locally owned cell with at least one of `prescribed_dofs`
     * (the fictitious-boundary velocity DoFs, sorted), the singular value
     * decomposition of B_free gives the null modes (singular values below
     * 1e-10 of the largest one of the unconstrained block). One pressure DoF
     * per null mode is chosen by pivoting (the one with the largest
     * component left), so that setting the chosen ones to zero removes the
     * whole null space: the discrete solution is then unique, and equal to
     * the one with those modes at zero.
     */
    template <int dim>
    std::vector<dealii::types::global_dof_index>
    find_undetermined_pressure_dofs(
      const dealii::DoFHandler<dim>                      &dof_handler,
      const dealii::Mapping<dim>                         &mapping,
      const dealii::AffineConstraints<double>            &zero_constraints,
      const std::vector<dealii::types::global_dof_index> &prescribed_dofs);
  } // namespace fluid
} // namespace particulate

#endif
