#include <particulate/rigid/contact_solver.h>
#include <particulate/rigid/dem_solver.h>
#include <particulate/rigid/newton_euler_integrator.h>
#include <particulate/rigid/projected_gauss_seidel_solver.h>
#include <particulate/rigid/sequential_impulse_solver.h>

#include <stdexcept>

namespace particulate {
  namespace rigid {
    std::string
    to_string(const ContactSolverType type)
    {
      switch (type)
        {
          case ContactSolverType::projected_gauss_seidel:
            return "projected Gauss-Seidel";
          case ContactSolverType::sequential_impulses:
            return "sequential impulses";
          case ContactSolverType::dem:
            return "DEM";
        }
      return "unknown";
    }



    ContactSolverType
    contact_solver_type_from_string(const std::string &name)
    {
      for (const auto t : {ContactSolverType::projected_gauss_seidel,
                           ContactSolverType::sequential_impulses,
                           ContactSolverType::dem})
        if (name == to_string(t))
          return t;
      throw std::invalid_argument(
        "rigid: unknown contact solver '" + name
        + "'; choose one of 'projected Gauss-Seidel', 'sequential impulses', "
          "'DEM'.");
    }



    std::unique_ptr<ContactSolver>
    ContactSolver::create(const ContactSolverType        type,
                          const ContactSolverParameters &p)
    {
      switch (type)
        {
          case ContactSolverType::projected_gauss_seidel:
            return std::make_unique<ProjectedGaussSeidelSolver>(p);
          case ContactSolverType::sequential_impulses:
            return std::make_unique<SequentialImpulseSolver>(p);
          case ContactSolverType::dem:
            return std::make_unique<DemSolver>(p);
        }
      throw std::invalid_argument("rigid::ContactSolver::create(): bad type");
    }



    void
    ContactSolver::kick(SolverContext &ctx)
    {
      auto &bodies = *ctx.bodies;
      for (unsigned int i = 0; i < bodies.size(); ++i)
        NewtonEulerIntegrator::integrate_velocity(bodies[i],
                                                  (*ctx.forces)[i],
                                                  (*ctx.torques)[i],
                                                  ctx.gravity,
                                                  ctx.h);
    }
  } // namespace rigid
} // namespace particulate
