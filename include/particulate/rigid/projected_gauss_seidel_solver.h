#ifndef particulate_rigid_projected_gauss_seidel_solver_h
#define particulate_rigid_projected_gauss_seidel_solver_h

#include <particulate/rigid/velocity_contact_solver.h>

namespace particulate {
  namespace rigid {
    /**
     * The velocity-level frictional LCP of thesis §4.4.2 solved per contact
     * group by projected Gauss–Seidel (§4.4.3, eq. 4.86): the Delassus matrix
     * A = J M^{-1} J^T (eqs. 4.69–4.72, with two friction rows per point) is
     * assembled explicitly as sparse 3x3 blocks between points that share a
     * dynamic body, then
     *   x_i <- clamp(x_i - (A x + b)_i / A_ii, lo_i, hi_i)         (4.84)
     * with lo = 0, hi = inf for normal rows and |x_t| <= mu x_n for the
     * friction rows (a friction pyramid whose first tangent follows the
     * sliding direction, so sliding friction is exact Coulomb).
     */
    class ProjectedGaussSeidelSolver : public VelocityContactSolver
    {
    public:
      using VelocityContactSolver::VelocityContactSolver;
      ContactSolverType
      type() const override
      {
        return ContactSolverType::projected_gauss_seidel;
      }

    protected:
      unsigned int
      solve_rows(std::size_t begin, std::size_t end) override;

    private:
      struct Block
      {
        unsigned int col; // other row index
        double       m[3][3];
      };
      std::vector<std::vector<Block>> blocks_;
    };
  } // namespace rigid
} // namespace particulate

#endif
