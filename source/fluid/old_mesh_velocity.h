#ifndef particulate_fluid_old_mesh_velocity_h
#define particulate_fluid_old_mesh_velocity_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * The velocity of a solution on the current (old) vertex positions,
     * evaluated at points where a remeshing puts the velocity nodes
     * (FlowDiscretisation::transfer_to_moved_mesh). Each point comes with
     * the cell its node sits on, which is near the point: a remeshing moves
     * a node by a few cells.
     *
     * A point is found in three ways, cheapest first:
     * - a walk across faces from its node's cell, within this rank's cells;
     * - where the walk reaches a ghost cell, the ghost's owner continues it
     *   (the cells and points exchanged once, by Utilities::MPI::
     *   some_to_some);
     * - the rest, Utilities::MPI::RemotePointEvaluation.
     * Why not GridTools' searches (which RemotePointEvaluation uses) for
     * all: for a point on a vertex, edge or face deal.II 9.4 collects the
     * cells around it by a loop over all cells, and the carried zone moves
     * nodes by whole cells onto the old mesh's vertices, edges and faces,
     * which made the transfer quadratic in the mesh size
     * (doc/performance.md, "Mesh transfer").
     */
    template <int dim>
    class OldMeshVelocity
    {
    public:
      using ActiveCell = typename dealii::DoFHandler<dim>::active_cell_iterator;

      /** The velocity (the first dim components of @p fe) of @p solution
       *  (ghosted), on the mesh as it is now. */
      OldMeshVelocity(
        const dealii::DoFHandler<dim>                    &dofs,
        const dealii::Mapping<dim>                       &mapping,
        const dealii::FESystem<dim>                      &fe,
        const dealii::TrilinosWrappers::MPI::BlockVector &solution);

      /**
       * The velocity at @p points, each with a locally owned cell near it
       * (@p starts). Collective. Throws std::runtime_error if a point lies
       * outside the mesh.
       */
      std::vector<dealii::Tensor<1, dim>>
      at(const std::vector<dealii::Point<dim>> &points,
         const std::vector<ActiveCell>         &starts) const;

    private:
      /** Where a walk towards a point ended: the last cell it reached, and
       *  the point's reference coordinates there if that cell holds it. */
      struct WalkEnd
      {
        ActiveCell         cell;
        bool               found = false;
        dealii::Point<dim> unit;
      };

      /** Walk from @p cell towards @p p until a cell holds it, the walk
       *  leaves this rank's cells or the mesh, or 64 cells are passed. */
      WalkEnd
      walk(ActiveCell cell, const dealii::Point<dim> &p) const;

      /** The velocity at reference coordinates @p unit of @p cell. */
      dealii::Tensor<1, dim>
      evaluate(const ActiveCell &cell, const dealii::Point<dim> &unit) const;

      /** The owners of the ghost cells in @p ghosts continue the walks to
       *  @p points; what they find goes to @p values, the indices of the
       *  others to @p lost. Collective. */
      void
      hand_off(const std::vector<dealii::Point<dim>> &points,
               const std::vector<unsigned int>       &indices,
               const std::vector<ActiveCell>         &ghosts,
               std::vector<dealii::Tensor<1, dim>>   &values,
               std::vector<unsigned int>             &lost) const;

      /** Evaluate @p values at the points @p indices of @p points through
       *  RemotePointEvaluation. Collective. */
      void
      search_globally(const std::vector<dealii::Point<dim>> &points,
                      const std::vector<unsigned int>       &indices,
                      std::vector<dealii::Tensor<1, dim>>   &values) const;

      const dealii::DoFHandler<dim>                    &dofs;
      const dealii::Mapping<dim>                       &mapping;
      const dealii::FESystem<dim>                      &fe;
      const dealii::TrilinosWrappers::MPI::BlockVector &solution;
    };
  } // namespace fluid
} // namespace particulate

#endif
