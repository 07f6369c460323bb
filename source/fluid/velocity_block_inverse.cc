#include "velocity_block_inverse.h"

#include "velocity_amg.h"
#include "velocity_chebyshev.h"
#include "velocity_multigrid_inverse.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      template <int dim>
      typename VelocityMultigrid<dim>::Settings
      multigrid_settings(const FluidParameters &parameters)
      {
        const auto &bc = parameters.boundary_conditions;
        typename VelocityMultigrid<dim>::Settings settings;
        settings.dirichlet_ids = bc.no_slip;
        settings.dirichlet_ids.insert(settings.dirichlet_ids.end(),
                                      bc.dirichlet.begin(),
                                      bc.dirichlet.end());
        settings.free_slip_ids   = bc.free_slip;
        settings.smoother_degree = parameters.linear_solver.chebyshev_degree;
        using CoarseSolve        = typename VelocityMultigrid<dim>::CoarseSolve;
        switch (parameters.linear_solver.multigrid_coarse_solver)
          {
            case MultigridCoarseSolver::chebyshev:
              settings.coarse_solver = CoarseSolve::chebyshev;
              break;
            case MultigridCoarseSolver::cg_amg:
              settings.coarse_solver = CoarseSolve::cg_amg;
              break;
            case MultigridCoarseSolver::automatic:
              settings.coarse_solver = CoarseSolve::automatic;
              break;
          }
        return settings;
      }
    } // namespace



    template <int dim>
    std::unique_ptr<VelocityBlockInverse<dim>>
    make_velocity_block_inverse(const FluidParameters    &parameters,
                                const DoFHandler<dim>    &dof_handler,
                                const IndexSet           &owned_velocity,
                                const Mapping<dim>       &mapping,
                                const MPI_Comm            communicator,
                                TimerOutput              &timer,
                                const ConditionalOStream &log)
    {
      const auto &linear = parameters.linear_solver;
      switch (linear.velocity_preconditioner)
        {
          case VelocityPreconditioner::amg:
            return std::make_unique<VelocityAmg<dim>>(linear,
                                                      dof_handler,
                                                      timer);
          case VelocityPreconditioner::chebyshev:
            return std::make_unique<VelocityChebyshev<dim>>(
              linear.chebyshev_degree,
              owned_velocity,
              communicator,
              timer);
          case VelocityPreconditioner::geometric_multigrid:
            return std::make_unique<VelocityMultigridInverse<dim>>(
              std::make_unique<VelocityMultigrid<dim>>(dof_handler,
                                                       owned_velocity,
                                                       mapping,
                                                       multigrid_settings<dim>(
                                                         parameters),
                                                       timer),
              owned_velocity,
              communicator,
              linear.multigrid_on_moving_mesh,
              log);
          case VelocityPreconditioner::automatic:
            break; // NavierStokes makes the choice before this
        }
      AssertThrow(false, ExcInternalError());
      return nullptr;
    }

    template std::unique_ptr<VelocityBlockInverse<2>>
    make_velocity_block_inverse(const FluidParameters &,
                                const DoFHandler<2> &,
                                const IndexSet &,
                                const Mapping<2> &,
                                const MPI_Comm,
                                TimerOutput &,
                                const ConditionalOStream &);
    template std::unique_ptr<VelocityBlockInverse<3>>
    make_velocity_block_inverse(const FluidParameters &,
                                const DoFHandler<3> &,
                                const IndexSet &,
                                const Mapping<3> &,
                                const MPI_Comm,
                                TimerOutput &,
                                const ConditionalOStream &);
  } // namespace fluid
} // namespace particulate
