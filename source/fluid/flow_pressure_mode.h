#ifndef particulate_fluid_flow_pressure_mode_h
#define particulate_fluid_flow_pressure_mode_h

// Private header of the fluid library: the constant pressure of an enclosed
// flow as the null mode of the system that is actually solved.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <utility>
#include <vector>

#include "undetermined_pressures.h"

namespace particulate {
  namespace fluid {
    /**
     * The pressure mode no equation of an enclosed flow determines, as
     * (DoF, value) pairs of locally owned pressure DoFs, sorted.
     *
     * In a domain with velocities fixed on its whole boundary, the pressure
     * equal to 1 on the flow's cells, z0, is a left null vector of the
     * divergence B restricted to the free velocities: (1, div v) is the flux
     * of v through the boundary of its support, where v vanishes. So the
     * continuity equations can only hold together if the fixed velocities
     * carry no net flux into the flow, and a Newton step can change no part
     * of the residual along the null vector. Fictitious-boundary velocities
     * break that balance a little where bodies in contact cover cells
     * together; the residual then stalls at that part.
     *
     * Decoupling pressures makes z0 itself no null vector of the reduced
     * system: it is not zero on the decoupled DoFs. Each patch's null modes
     * m_j (find_undetermined_pressure_dofs) are null vectors too, and their
     * decoupled rows form an invertible block, so z0 - sum a_j m_j can be
     * made zero on them, patch after patch (each patch's modes are zero on
     * the DoFs decoupled before it, so a later patch leaves the earlier
     * zeros in place). The result is the exact null vector of the reduced
     * system. @p flow_constants: the constant pressure DoFs of the flow's
     * cells (find_enclosed_fluid); @p decoupled: all decoupled DoFs, sorted.
     */
    /**
     * Whether the constant pressure is a null vector of the discrete
     * divergence on this mesh: whether, for every velocity basis function
     * that @p zero_constraints leaves free (condensed over hanging nodes),
     * the flux (1, div phi_j) through the boundary of its support vanishes
     * to round-off (1e-10 of the largest of one cell). It does where the
     * quadrature integrates div phi_j exactly over cells that fit together,
     * as on the box meshes (QGauss(3) is exact for Q2 maps); on the `ball`
     * mesh, whose boundary cells carry the sphere's manifold, it does not
     * (up to a fifth of a cell's flux on one face function). There the
     * equations determine the flow's pressure, and there is no net flux to
     * remove.
     * Collective.
     */
    template <int dim>
    bool
    constant_pressure_is_null_mode(
      const dealii::DoFHandler<dim>           &dof_handler,
      const dealii::Mapping<dim>              &mapping,
      const dealii::AffineConstraints<double> &zero_constraints,
      const dealii::IndexSet                  &owned_velocities,
      const dealii::IndexSet                  &relevant_dofs,
      MPI_Comm                                 communicator);

    std::vector<std::pair<dealii::types::global_dof_index, double>>
    enclosed_flow_pressure_mode(
      const std::vector<dealii::types::global_dof_index> &flow_constants,
      const std::vector<PatchNullModes>                  &patches,
      const std::vector<dealii::types::global_dof_index> &decoupled);
  } // namespace fluid
} // namespace particulate

#endif
