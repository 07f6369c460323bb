#ifndef particulate_rigid_newton_euler_integrator_h
#define particulate_rigid_newton_euler_integrator_h

#include <particulate/rigid/rigid_body.h>

namespace particulate {
  namespace rigid {
    /**
     * Time integration of the Newton–Euler equations (thesis eq. 4.31) as a
     * symplectic split step: a velocity "kick" with the applied force and
     * torque, then (after the contact solver has corrected velocities) a
     * "drift" that moves the centre of mass and rotates the body freely.
     *
     * The free rotation carries the gyroscopic term omega x (I omega): in the
     * body frame the angular momentum obeys L' = L x I^{-1} L, which we
     * integrate with the implicit midpoint rule. That rule conserves both
     * quadratic invariants (kinetic energy and |L|) exactly, and its update
     * L_{n+1} = cay(h w)^T L_n is a rotation (Cayley transform with the
     * midpoint angular velocity w), which we apply to the orientation as
     * well, so the world-frame angular momentum is conserved exactly too.
     * The quaternion is renormalised after every update.
     */
    class NewtonEulerIntegrator
    {
    public:
      /**
       * Velocity kick: U += dt (F/m + g), omega += dt I_w^{-1} T. Fixed bodies
       * are left alone.
       * @param body The body.
       * @param force Total applied force in N (without gravity).
       * @param torque Total applied torque about the centre of mass in N m.
       * @param gravity Gravitational acceleration in m/s^2.
       * @param dt Time step in s.
       */
      static void
      integrate_velocity(RigidBody             &body,
                         const Eigen::Vector3d &force,
                         const Eigen::Vector3d &torque,
                         const Eigen::Vector3d &gravity,
                         double                 dt);

      /**
       * Drift: X += dt U, and the torque-free rotation over dt including the
       * gyroscopic term (see the class documentation); omega is updated to
       * the end-of-step value.
       */
      static void
      integrate_position(RigidBody &body, double dt);
    };
  } // namespace rigid
} // namespace particulate

#endif
