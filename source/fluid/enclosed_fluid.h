#ifndef particulate_fluid_enclosed_fluid_h
#define particulate_fluid_enclosed_fluid_h

// Private header of the fluid library: fluid that fixed velocities cut off
// from the rest of the flow.

#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace particulate {
  namespace fluid {
    /** What find_enclosed_fluid() found. */
    struct EnclosedFluid
    {
      /// pockets over all ranks
      unsigned int n_pockets = 0;
      /// locally owned pressure DoFs to decouple, one per pocket (sorted)
      std::vector<dealii::types::global_dof_index> pinned_pressures;
      /// the constant pressure DoFs of the locally owned cells of the flow,
      /// the largest set (sorted)
      std::vector<dealii::types::global_dof_index> flow_constants;
    };

    /**
     * Pockets of fluid that constraints wall off from the flow, and one
     * pressure DoF to decouple in each.
     *
     * The cells holding free velocity DoFs fall into connected sets: two
     * cells belong together when they share a free velocity DoF. For each
     * set, its P1disc pressure equal to 1 on its cells and 0 elsewhere is a
     * pressure mode that no equation determines: tested with any free
     * velocity v of the set, (1, div v) over its cells is the flux of v
     * through the set's boundary, where v vanishes. And the continuity
     * equations of the set can only hold together if the fixed velocities
     * on its boundary carry no net flux into it, which bodies moving
     * relative to each other around a pocket violate: the linear solver
     * stalls at a residual it cannot go below. Decoupling the constant
     * pressure of one cell per pocket removes both: the mode, and the one
     * continuity equation that takes up the net flux (the pocket's fluid
     * is squeezed through a gap the mesh does not resolve).
     *
     * The largest set is the flow itself, whose constant pressure the
     * boundary conditions settle (an outflow) or the solver's zero-mean
     * pressure does (an enclosed domain); every other set is a pocket.
     * The pressure decoupled in a pocket is the constant of one of its
     * cells whose pressures are not among @p decoupled (sorted, locally
     * owned: those find_undetermined_pressure_dofs() decouples already).
     * Collective over @p communicator; the sets are joined across
     * partition boundaries.
     */
    template <int dim>
    EnclosedFluid
    find_enclosed_fluid(
      const dealii::DoFHandler<dim>                      &dof_handler,
      const dealii::AffineConstraints<double>            &zero_constraints,
      const std::vector<dealii::types::global_dof_index> &decoupled,
      MPI_Comm                                            communicator);
  } // namespace fluid
} // namespace particulate

#endif
