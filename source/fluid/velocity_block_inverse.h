#ifndef particulate_fluid_velocity_block_inverse_h
#define particulate_fluid_velocity_block_inverse_h

#include <particulate/fluid/fluid_parameters.h>
#include <particulate/fluid/viscosity_model.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * What a velocity preconditioner may be built from: the velocity block
     * of a Newton system, either assembled or described by the stage's
     * coefficients and the linearisation point.
     */
    struct VelocityLinearisation
    {
      /// the assembled velocity block; nullptr with the matrix-free operator
      const dealii::TrilinosWrappers::SparseMatrix *matrix = nullptr;
      /// the current iterate's velocity (ghosted velocity block)
      const dealii::TrilinosWrappers::MPI::Vector *velocity = nullptr;
      /// rho / k; 0 for the steady problem
      double mass_coefficient = 0.;
      double theta_implicit   = 1.;
      /// the viscosity of the iterate
      const ViscosityModel *viscosity = nullptr;
    };

    /**
     * The approximate inverse of the velocity block A inside the block
     * preconditioner: one interface over algebraic multigrid, a
     * Jacobi-Chebyshev polynomial and geometric multigrid.
     *
     * An implementation may keep what it built across Newton iterations,
     * stages and steps. Whether it keeps it is decided by iteration counts
     * only (never by timing), so that a run's numbers do not depend on the
     * machine's load: prepare() says whether it was built from the matrix
     * at hand ("fresh"), and record_solve() hands it the FGMRES count of
     * each solve.
     */
    template <int dim>
    class VelocityBlockInverse
    {
    public:
      virtual ~VelocityBlockInverse() = default;

      /** Make ready for a solve with the matrix @p a; returns true when
       *  what it applies was built from @p a (fresh), false when kept. */
      virtual bool
      prepare(const VelocityLinearisation &a)
        = 0;

      /** The kept inverse failed: build it afresh from @p a now. */
      virtual void
      rebuild(const VelocityLinearisation &a)
        = 0;

      /** dst ~ A^{-1} src (velocity block layout). */
      virtual void
      vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
            const dealii::TrilinosWrappers::MPI::Vector &src) const = 0;

      /** FGMRES needed @p iterations with it, @p fresh as prepare() said:
       *  decides whether it is still kept for the next solve. */
      virtual void
      record_solve(const unsigned int iterations, const bool fresh)
        = 0;

      /** The iterations a fresh inverse needs (the kept one is given
       *  twice that, plus a margin, before it is rebuilt). */
      virtual unsigned int
      reference_iterations() const = 0;

      /** A new Jacobian was assembled or linearised. */
      virtual void
      matrix_changed()
        = 0;

      /** Drop everything built from the matrices (before they are
       *  cleared, or at a checkpoint: a run and a run restarted there
       *  then compute the same numbers). */
      virtual void
      reset()
        = 0;

      /** The mesh moved by one step's ALE motion. */
      virtual void
      mesh_moved()
      {}

      /** The solution was carried to a freshly adapted mesh. */
      virtual void
      mesh_replaced()
      {}

      /** Velocity DoFs (system numbering, locally relevant) constrained
       *  inside fictitious-boundary bodies. */
      virtual void
      set_masked_dofs(const std::vector<dealii::types::global_dof_index> &)
      {}

      /** The Q2^dim velocity DoF handler, numbered like the velocity block,
       *  where the inverse has one (geometric multigrid); nullptr
       *  otherwise. The matrix-free velocity operator works on it. */
      virtual const dealii::DoFHandler<dim> *
      velocity_dof_handler() const
      {
        return nullptr;
      }

      virtual std::size_t
      memory_consumption() const = 0;

      /** Bytes one application moves through memory at least on this
       *  rank, given those of one product with the velocity block. */
      virtual double
      bytes_per_application(const double operator_bytes) const = 0;
    };

    /**
     * A kept preconditioner is worn out once FGMRES needs half as many
     * iterations again as with a fresh one, plus 5.
     */
    inline bool
    kept_preconditioner_is_worn(const unsigned int iterations,
                                const unsigned int fresh_iterations)
    {
      return iterations > 1.5 * fresh_iterations + 5;
    }

    /**
     * The velocity block inverse that @p parameters ask for ('Velocity
     * preconditioner'), for the system on @p dof_handler (velocity block
     * first, @p owned_velocity its locally owned velocity DoFs). @p log
     * prints the keep-or-rebuild decisions ('Verbose').
     */
    template <int dim>
    std::unique_ptr<VelocityBlockInverse<dim>>
    make_velocity_block_inverse(const FluidParameters         &parameters,
                                const dealii::DoFHandler<dim> &dof_handler,
                                const dealii::IndexSet        &owned_velocity,
                                const dealii::Mapping<dim>    &mapping,
                                const MPI_Comm                 communicator,
                                dealii::TimerOutput           &timer,
                                const dealii::ConditionalOStream &log);
  } // namespace fluid
} // namespace particulate

#endif
