#ifndef particulate_fluid_velocity_amg_h
#define particulate_fluid_velocity_amg_h

#include <deal.II/lac/trilinos_precondition.h>

#include "velocity_block_inverse.h"

namespace particulate {
  namespace fluid {
    /**
     * One ML algebraic-multigrid V-cycle on the assembled velocity block,
     * with the velocity components' constant modes as near-null space.
     *
     * The hierarchy is kept across Newton iterations, stages and time steps
     * (its set-up costs as much as a Krylov solve). A kept hierarchy gets a
     * limited number of iterations; if it needs more, or markedly more than
     * the solve right after its construction (kept_preconditioner_is_worn),
     * it is rebuilt from the current matrix.
     */
    template <int dim>
    class VelocityAmg : public VelocityBlockInverse<dim>
    {
    public:
      VelocityAmg(const LinearSolverParameters  &parameters,
                  const dealii::DoFHandler<dim> &dof_handler,
                  dealii::TimerOutput           &timer);

      bool
      prepare(const VelocityLinearisation &a) override;
      void
      rebuild(const VelocityLinearisation &a) override;
      void
      vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
            const dealii::TrilinosWrappers::MPI::Vector &src) const override;
      void
      record_solve(const unsigned int iterations, const bool fresh) override;
      unsigned int
      reference_iterations() const override
      {
        return fresh_iterations;
      }
      void
      matrix_changed() override
      {}
      void
      reset() override
      {
        amg.reset();
      }
      std::size_t
      memory_consumption() const override;
      /** The finest level: its pre- and post-smoothing sweeps and the
       *  residual, each a pass over the velocity block. */
      double
      bytes_per_application(const double operator_bytes) const override
      {
        return (2. * parameters.amg_smoother_sweeps + 1.) * operator_bytes;
      }

    private:
      const LinearSolverParameters                              &parameters;
      const dealii::DoFHandler<dim>                             &dof_handler;
      dealii::TimerOutput                                       &timer;
      std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
      /// FGMRES iterations of the solve right after the last build
      unsigned int fresh_iterations = 0;
    };
  } // namespace fluid
} // namespace particulate

#endif
