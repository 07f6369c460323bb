#ifndef particulate_fluid_undetermined_pressures_h
#define particulate_fluid_undetermined_pressures_h

// Private header of the fluid library: which discontinuous pressure modes no
// equation determines once fictitious-boundary bodies prescribe velocities.

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace particulate {
  namespace fluid {
    /// A velocity DoF whose value a constraint fixes (no other DoF in its
    /// line); a hanging node, which follows free DoFs, stays free.
    inline bool
    is_fixed_by_constraint(const dealii::AffineConstraints<double> &constraints,
                           const dealii::types::global_dof_index    dof)
    {
      const auto *entries = constraints.get_constraint_entries(dof);
      return entries != nullptr && entries->empty();
    }

    /** The null modes one patch of cells next to a body contributes. */
    struct PatchNullModes
    {
      /// pressure DoFs of the patch not decoupled before it
      std::vector<dealii::types::global_dof_index> rows;
      /// rows x modes: columns spanning the patch's null modes
      dealii::FullMatrix<double> basis;
      /// the positions in `rows` decoupled for them, one per mode
      std::vector<unsigned int> pinned;
    };

    /** What find_undetermined_pressure_dofs() found. */
    struct UndeterminedPressures
    {
      /// locally owned pressure DoFs to decouple (sorted)
      std::vector<dealii::types::global_dof_index> decoupled;
      /// the patches' null modes in the order they were found; each is
      /// zero on the DoFs decoupled before it
      std::vector<PatchNullModes> patches;
    };

    /**
     * Pressure DoFs (locally owned, sorted) to decouple from the flow, and
     * the null modes they stand for.
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
     * Every cell touching one of `prescribed_dofs` (the fictitious-boundary
     * velocity DoFs, sorted) is examined on a patch: itself and its locally
     * owned face neighbours that touch a body too, with the divergence block
     * on all free velocities of the patch. Its left null vectors are null
     * modes of the whole system (zero outside the patch), including modes
     * that two cells share. The Gram matrix of the block gives them
     * (eigenvalues below 1e-12 of the largest squared singular value of a
     * cell's unconstrained block); one pressure DoF per null mode is chosen
     * by pivoting (the one with the largest component left), so that
     * setting the chosen ones to zero removes the null space without
     * removing an equation. Patches are taken one after another, each
     * without the DoFs pinned before. Modes across partition boundaries are
     * not searched for. The cells without a free velocity are decoupled
     * whole and give no patch: their divergence block is empty; so are the
     * cells touching one of `joint_dofs` (sorted), where the velocities of
     * two parts of an articulated body meet and no divergence-free flow
     * takes both.
     */
    template <int dim>
    UndeterminedPressures
    find_undetermined_pressure_dofs(
      const dealii::DoFHandler<dim>                      &dof_handler,
      const dealii::Mapping<dim>                         &mapping,
      const dealii::AffineConstraints<double>            &zero_constraints,
      const std::vector<dealii::types::global_dof_index> &prescribed_dofs,
      const std::vector<dealii::types::global_dof_index> &joint_dofs = {});
  } // namespace fluid
} // namespace particulate

#endif
