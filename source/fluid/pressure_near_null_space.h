#ifndef particulate_fluid_pressure_near_null_space_h
#define particulate_fluid_pressure_near_null_space_h

// Private header of the fluid library: the near-null space that the
// algebraic multigrid of the pressure Laplacian L_p is built on.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * The pressures L_p = B D^{-1} B^T barely acts on, for ML's smoothed
     * aggregation: the constant and the dim linear functions x_d, each put
     * into the discontinuous P1 pressure space cell by cell (L2 projection).
     *
     * With the constant alone, the coarse levels see a pressure as one
     * value per aggregate and cannot represent the slope that any smooth
     * pressure has inside the aggregate; the P1disc slope DoFs of a smooth
     * error are then left to the smoother. A linear pressure is as much a
     * near-null vector of L_p as the constant: D^{-1} B^T p is then nearly
     * the constant velocity grad p, whose discrete divergence B vanishes
     * in cells away from constrained velocities. Smoothed aggregation
     * needs to be told, as it is told the rigid-body modes of elasticity.
     *
     * The coordinates are taken relative to the centre of the mesh's
     * bounding box and divided by its diagonal, so that the vectors are of
     * similar size. Returned vector after vector (dim + 1 of them), each
     * with the owned pressure DoFs in the order of `owned_pressures`, as
     * ML's "null space: vectors" expects. Pressure DoFs are numbered after
     * `first_pressure_dof` in the DoFHandler (block numbering).
     */
    template <int dim>
    std::vector<double>
    pressure_near_null_space(
      const dealii::Mapping<dim>           &mapping,
      const dealii::DoFHandler<dim>        &dof_handler,
      const dealii::IndexSet               &owned_pressures,
      const dealii::types::global_dof_index first_pressure_dof,
      const MPI_Comm                        communicator);
  } // namespace fluid
} // namespace particulate

#endif
