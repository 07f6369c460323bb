#ifndef particulate_fluid_pressure_laplacian_h
#define particulate_fluid_pressure_laplacian_h

#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cstddef>
#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * Decoupled pressures (see NavierStokes::decoupled_pressure_dofs) have
     * empty rows in L_p = B D^{-1} B^T. The solver keeps them at zero; a
     * diagonal entry of the size of the largest other one keeps the
     * multigrid hierarchy of L_p, and its direct coarse solve, well
     * defined. Rows whose diagonal is at most 1e-12 of the largest count as
     * empty: their off-diagonal entries are zeroed and the diagonal set.
     * Where the product did not store a diagonal the matrix is rebuilt with
     * one (a new Epetra object); otherwise it is changed in place.
     * Returns in `first_flow_row` the lowest row (over all ranks) that was
     * not empty: a pressure of the flow.
     */
    void
    regularise_empty_pressure_rows(
      dealii::TrilinosWrappers::SparseMatrix &matrix,
      dealii::types::global_dof_index        &first_flow_row);

    /**
     * The pressure Laplacian L_p = B D^{-1} B^T of the Schur complement
     * approximation when the velocity block is matrix-free: B^T is the
     * assembled gradient (velocity rows, pressure columns), D the lumped
     * velocity mass, and the sum over velocity DoFs i,
     *
     *   L_p = M_p ( sum_{i free} b_i b_i^T / D_i ) M_p,
     *
     * runs over the velocities that no constraint fixes (b_i: row i of
     * B^T); M_p zeroes the rows and columns of decoupled pressures.
     *
     * The bodies' covered nodes change every time step, the mesh's
     * boundary conditions only with the mesh. So the sum over all
     * velocities not fixed by the mesh, L_base, is formed once, and every
     * update subtracts the covered velocities' part, a product over their
     * rows only (a few per cent of the DoFs), in place: the matrix keeps
     * its Epetra object and structure.
     */
    class PressureLaplacian
    {
    public:
      /** Forget L_base (new DoFs, a moved mesh, new B). */
      void
      clear();

      /**
       * Whether update() with these mesh-fixed velocities only changes
       * values (true), or builds a new matrix (false).
       */
      bool
      keeps_structure(
        const std::vector<dealii::types::global_dof_index> &mesh_fixed) const;

      /**
       * L_p into `laplacian`. `mesh_fixed` and `covered` are the locally
       * owned velocity DoFs fixed by boundary conditions and by bodies
       * (disjoint, sorted), `free_pressure` is 1 for coupled pressures and
       * 0 for decoupled ones (owned pressures). Empty rows are regularised
       * (regularise_empty_pressure_rows), whose `first_flow_row` is
       * returned.
       */
      dealii::types::global_dof_index
      update(dealii::TrilinosWrappers::SparseMatrix             &laplacian,
             const dealii::TrilinosWrappers::SparseMatrix       &gradient,
             const dealii::TrilinosWrappers::MPI::Vector        &inverse_mass,
             const std::vector<dealii::types::global_dof_index> &mesh_fixed,
             const std::vector<dealii::types::global_dof_index> &covered,
             const dealii::TrilinosWrappers::MPI::Vector        &free_pressure);

      std::size_t
      memory_consumption() const;

    private:
      /// sum over the velocities not fixed by the mesh, all pressures,
      /// with every diagonal stored
      dealii::TrilinosWrappers::SparseMatrix       base;
      std::vector<dealii::types::global_dof_index> base_mesh_fixed;
      bool                                         has_base = false;
    };
  } // namespace fluid
} // namespace particulate

#endif
