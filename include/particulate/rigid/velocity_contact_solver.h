#ifndef particulate_rigid_velocity_contact_solver_h
#define particulate_rigid_velocity_contact_solver_h

#include <particulate/rigid/contact_solver.h>

namespace particulate {
  namespace rigid {
    /**
     * What the two velocity-level solvers (PGS and SI) share: the contact
     * rows (normal and two tangents per point, effective masses), the
     * restitution pass, warm starting and the write-back of impulses.
     *
     * One substep reads:
     * 1. rows from the contact points, friction coefficient per point chosen
     *    from the pre-step tangential speed (static below
     *    `sticking_speed`, dynamic above; eqs. 4.34–4.35);
     * 2. restitution pass: contacts that touch or would touch within the
     *    substep and approach faster than the threshold receive pairwise
     *    normal impulses -(1+e) v_n / K_nn, swept over each contact group in
     *    its propagation order until no contact approaches (Guendelman's
     *    collision step; this is how a Newton's cradle propagates its shock,
     *    Fig. 3.11);
     * 3. kick with applied forces and gravity;
     * 4. the contact problem with e = 0, the speculative bound
     *    v_n >= -gap/h for open contacts (Sauer–Schömer nu_k/dt, eq. 4.64)
     *    and Baumgarte push-out for penetrations: solve_rows() of the derived
     *    class;
     * 5. impulses back into the contact points (warm start cache, forces).
     */
    class VelocityContactSolver : public ContactSolver
    {
    public:
      using ContactSolver::ContactSolver;

      void
      solve(SolverContext &ctx) override;

    protected:
      /** Velocities and inverse mass properties of one body. */
      struct SolverBody
      {
        Eigen::Vector3d v, w;
        double          inv_m = 0.;
        Eigen::Matrix3d inv_I = Eigen::Matrix3d::Zero();
      };

      /** One contact point as three velocity rows. */
      struct Row
      {
        unsigned int    a = 0, b = 0, edge = 0, point = 0;
        Eigen::Vector3d dir[3]  = {Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero()}; // n, t1, t2
        Eigen::Vector3d ra_x[3] = {Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero()}; // ra x dir
        Eigen::Vector3d rb_x[3] = {Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero()}; // rb x dir
        // I_a^{-1} (ra x dir)
        Eigen::Vector3d ia[3] = {Eigen::Vector3d::Zero(),
                                 Eigen::Vector3d::Zero(),
                                 Eigen::Vector3d::Zero()};
        // I_b^{-1} (rb x dir)
        Eigen::Vector3d ib[3] = {Eigen::Vector3d::Zero(),
                                 Eigen::Vector3d::Zero(),
                                 Eigen::Vector3d::Zero()};
        double          k[3]  = {0., 0., 0.}; // diagonal of the Delassus block
        double          bias  = 0.;           // lower bound of v_n in m/s
        double          gap   = 0.;
        double          mu    = 0.;
        double          e     = 0.;
        double          lambda[3]         = {0., 0., 0.};
        double          collision_impulse = 0.;
      };

      /** Relative velocity of b with respect to a along direction k of
       *  row r. */
      double
      velocity(const Row &r, int k) const;
      /** Applies the impulse p along direction k of row r (+ on b, - on a). */
      void
      apply(const Row &r, int k, double p);

      /** Solves the contact problem of one group (rows [begin, end)),
       * returning the sweeps used. */
      virtual unsigned int
      solve_rows(std::size_t begin, std::size_t end)
        = 0;

      std::vector<SolverBody> sb_;
      std::vector<Row>        rows_;
    };
  } // namespace rigid
} // namespace particulate

#endif
