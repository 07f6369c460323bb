#ifndef particulate_rigid_dem_solver_h
#define particulate_rigid_dem_solver_h

#include <particulate/rigid/contact_solver.h>

namespace particulate {
  namespace rigid {
    /**
     * Soft-contact DEM (thesis §4.4.4, Algorithm 7). For an overlap delta =
     * -gap > 0 the force on body b is
     *   F_n = (k_n delta - eta_n v_n) n                           (4.87, 4.90)
     * with the damping eta_n = 2 zeta sqrt(m_eff k_n) chosen so that a binary
     * collision has the material's restitution e (no clamp to F_n >= 0, which
     * would raise the effective e; the short tensile phase ends with the
     * overlap) (zeta = -ln e / sqrt(pi^2 + ln^2 e)); tangentially a spring on
     * the accumulated tangential displacement (Cundall–Strack): while its
     * elastic force stays below mu_s f_n the contact sticks (spring plus
     * dashpot, capped at mu_s f_n), beyond it the contact slides with exactly
     * mu_d f_n and the spring is cut back to that force. Forces and torques are
     * accumulated pairwise and the velocities kicked explicitly, so the substep
     * must resolve the contact time t_c = pi sqrt(m_eff / k_n): World picks the
     * substeps.
     */
    class DemSolver : public ContactSolver
    {
    public:
      using ContactSolver::ContactSolver;
      void
      solve(SolverContext &ctx) override;
      ContactSolverType
      type() const override
      {
        return ContactSolverType::dem;
      }

      /** Damping ratio zeta for restitution @p e (1 for e = 0). */
      static double
      damping_ratio(double e);

    private:
      std::vector<Eigen::Vector3d> f_, t_;
      std::vector<Eigen::Matrix3d> inv_I_;
    };
  } // namespace rigid
} // namespace particulate

#endif
