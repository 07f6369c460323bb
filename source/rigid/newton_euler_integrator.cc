#include <particulate/rigid/newton_euler_integrator.h>

#include <cmath>

namespace particulate {
  namespace rigid {
    void
    NewtonEulerIntegrator::integrate_velocity(RigidBody             &body,
                                              const Eigen::Vector3d &force,
                                              const Eigen::Vector3d &torque,
                                              const Eigen::Vector3d &gravity,
                                              const double           dt)
    {
      if (body.is_fixed())
        return;
      body.linear_velocity += dt * (body.inverse_mass() * force + gravity);
      if (torque.squaredNorm() > 0.)
        body.angular_velocity += dt * (body.inverse_inertia_world() * torque);
    }



    void
    NewtonEulerIntegrator::integrate_position(RigidBody &body, const double dt)
    {
      if (body.is_fixed())
        return;
      body.position += dt * body.linear_velocity;

      const Eigen::Vector3d &I  = body.principal_inertia();
      const Eigen::Vector3d &Ii = body.inverse_principal_inertia();
      const Eigen::Vector3d  w  = body.angular_velocity;
      if (!(w.squaredNorm() > 0.))
        return;

      const bool isotropic = std::abs(I[0] - I[1]) <= 1.e-14 * I[0]
                             && std::abs(I[0] - I[2]) <= 1.e-14 * I[0];
      if (isotropic)
        {
          // No gyroscopic torque: omega is constant, rotate exactly.
          const double             angle = w.norm() * dt;
          const Eigen::Quaterniond dq(Eigen::AngleAxisd(angle, w.normalized()));
          body.orientation = (dq * body.orientation).normalized();
          return;
        }

      // Implicit midpoint for L_b' = L_b x I^{-1} L_b, solved by fixed-point
      // iteration on L_{n+1}; every iterate is an exact rotation of L_n.
      const Eigen::Vector3d L0
        = I.cwiseProduct(body.orientation.conjugate() * w);
      Eigen::Vector3d    L1 = L0;
      Eigen::Quaterniond p  = Eigen::Quaterniond::Identity();
      for (int it = 0; it < 100; ++it)
        {
          const Eigen::Vector3d wm = Ii.cwiseProduct(0.5 * (L0 + L1));
          // Cayley transform cay(h w) as a quaternion: (1, h w / 2) / norm.
          const Eigen::Vector3d g = 0.5 * dt * wm;
          p = Eigen::Quaterniond(1., g[0], g[1], g[2]).normalized();
          const Eigen::Vector3d L_new  = p.conjugate() * L0;
          const double          change = (L_new - L1).norm();
          L1                           = L_new;
          if (change <= 1.e-15 * L0.norm())
            break;
        }
      body.orientation      = (body.orientation * p).normalized();
      body.angular_velocity = body.orientation * Ii.cwiseProduct(L1);
    }
  } // namespace rigid
} // namespace particulate
