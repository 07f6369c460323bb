#ifndef particulate_rigid_sequential_impulse_solver_h
#define particulate_rigid_sequential_impulse_solver_h

#include <particulate/rigid/velocity_contact_solver.h>

namespace particulate {
  namespace rigid {
    /**
     * Sequential impulses (thesis §4.4.5, Algorithm 8): each contact point in
     * turn receives the impulse that makes its relative velocity admissible,
     * applied to the body velocities at once, and the sweeps repeat until the
     * impulses stop changing. Accumulated impulses are clamped (normal >= 0,
     * tangential inside the circular Coulomb cone |f_t| <= mu f_n, eq. 4.103),
     * which keeps the iteration a projected Gauss–Seidel on the contact
     * problem, but matrix free.
     */
    class SequentialImpulseSolver : public VelocityContactSolver
    {
    public:
      using VelocityContactSolver::VelocityContactSolver;
      ContactSolverType
      type() const override
      {
        return ContactSolverType::sequential_impulses;
      }

    protected:
      unsigned int
      solve_rows(std::size_t begin, std::size_t end) override;
    };
  } // namespace rigid
} // namespace particulate

#endif
