#include <particulate/rigid/dem_solver.h>

#include <cmath>

namespace particulate {
  namespace rigid {
    double
    DemSolver::damping_ratio(const double e)
    {
      if (e <= 0.)
        return 1.;
      if (e >= 1.)
        return 0.;
      const double l = std::log(e);
      return -l / std::sqrt(M_PI * M_PI + l * l);
    }



    void
    DemSolver::solve(SolverContext &ctx)
    {
      auto        &bodies = *ctx.bodies;
      const double h      = ctx.h;
      f_.assign(bodies.size(), Eigen::Vector3d::Zero());
      t_.assign(bodies.size(), Eigen::Vector3d::Zero());
      // World-frame inverse inertia once per body and substep.
      inv_I_.resize(bodies.size());
      for (unsigned int i = 0; i < bodies.size(); ++i)
        inv_I_[i] = bodies[i].is_fixed() ? Eigen::Matrix3d::Zero() :
                                           bodies[i].inverse_inertia_world();

      // Algorithm 7: loop over the edges of the contact graph.
      for (ContactEdge &e : ctx.graph->edges())
        {
          if (e.manifold.points.empty())
            continue;
          const RigidBody &A = bodies[e.manifold.a], &B = bodies[e.manifold.b];
          const ContactMaterial &mat = ctx.material(e);
          // 2 zeta sqrt(k): the dashpots are these times sqrt(m_eff).
          const double c_n = 2. * mat.damping_ratio * std::sqrt(mat.stiffness);
          const double c_t
            = 2. * mat.damping_ratio * std::sqrt(mat.tangential_stiffness);
          const double kn = mat.stiffness, kt = mat.tangential_stiffness;
          const Eigen::Matrix3d &Ia = inv_I_[e.manifold.a];
          const Eigen::Matrix3d &Ib = inv_I_[e.manifold.b];
          for (ContactPoint &c : e.manifold.points)
            {
              c.impulse.setZero();
              if (c.distance >= 0.)
                {
                  c.dem_spring.setZero();
                  continue;
                }
              const Eigen::Vector3d &n  = c.normal;
              const Eigen::Vector3d  ra = c.position - A.position;
              const Eigen::Vector3d  rb = c.position - B.position;
              const Eigen::Vector3d  vrel
                = B.linear_velocity + B.angular_velocity.cross(rb)
                  - A.linear_velocity - A.angular_velocity.cross(ra);
              const double vn = vrel.dot(n);
              // Effective mass of the pair along the normal at this point,
              // rotation included (for off-centre contacts it is much smaller
              // than the reduced mass, and the dashpot must see it to stay
              // stable and to give the intended restitution).
              const Eigen::Vector3d ran = ra.cross(n), rbn = rb.cross(n);
              const double          m_eff = 1.
                                   / (A.inverse_mass() + B.inverse_mass()
                                      + ran.dot(Ia * ran) + rbn.dot(Ib * rbn));
              const double          sqrt_m = std::sqrt(m_eff);
              const double          eta_n  = c_n * sqrt_m;
              const double          eta_t  = c_t * sqrt_m;
              const Eigen::Vector3d vt     = vrel - vn * n;
              // No clamp to f_n >= 0: the linear spring-dashpot then gives
              // exactly the restitution e whose damping ratio was chosen (a
              // clamp would raise the effective e by several percent); the
              // brief tensile phase ends with the overlap.
              const double fn = kn * (-c.distance) - eta_n * vn;

              // Tangential spring on the tangential displacement history.
              Eigen::Vector3d xi = c.dem_spring - c.dem_spring.dot(n) * n;
              xi += h * vt;
              // Coulomb test on the elastic part (the dashpot only damps the
              // sticking oscillation): beyond mu_s f_n the contact slips, the
              // spring is cut back to the sliding force mu_d f_n and the
              // tangential force is exactly the dynamic Coulomb force.
              const double    fn_pos = std::max(fn, 0.);
              Eigen::Vector3d ft     = -kt * xi;
              if (ft.norm() > mat.static_friction * fn_pos)
                {
                  const double len = ft.norm();
                  ft               = len > 0. ? Eigen::Vector3d(
                         ft * (mat.dynamic_friction * fn_pos / len)) :
                                                Eigen::Vector3d::Zero();
                  xi               = kt > 0. ? Eigen::Vector3d(-ft / kt) :
                                               Eigen::Vector3d::Zero();
                }
              else
                {
                  ft -= eta_t * vt;
                  const double len = ft.norm(),
                               lim = mat.static_friction * fn_pos;
                  if (len > lim)
                    ft *= lim / len;
                }
              c.dem_spring = xi;

              const Eigen::Vector3d F = fn * n + ft; // on b
              f_[e.manifold.b] += F;
              t_[e.manifold.b] += rb.cross(F);
              f_[e.manifold.a] -= F;
              t_[e.manifold.a] -= ra.cross(F);
              c.impulse = h * F;
            }
        }

      for (unsigned int i = 0; i < bodies.size(); ++i)
        {
          RigidBody &b = bodies[i];
          if (b.is_fixed())
            continue;
          b.linear_velocity
            += h
               * (b.inverse_mass() * ((*ctx.forces)[i] + f_[i]) + ctx.gravity);
          const Eigen::Vector3d T = (*ctx.torques)[i] + t_[i];
          if (T.squaredNorm() > 0.)
            b.angular_velocity += h * (inv_I_[i] * T);
        }
      last_iterations_ = 1;
    }
  } // namespace rigid
} // namespace particulate
