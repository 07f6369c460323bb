#include <particulate/rigid/velocity_contact_solver.h>

#include <Eigen/Geometry>

#include <cmath>

namespace particulate {
  namespace rigid {
    double
    VelocityContactSolver::velocity(const Row &r, const int k) const
    {
      const SolverBody &A = sb_[r.a], &B = sb_[r.b];
      return r.dir[k].dot(B.v - A.v) + r.rb_x[k].dot(B.w) - r.ra_x[k].dot(A.w);
    }



    void
    VelocityContactSolver::apply(const Row &r, const int k, const double p)
    {
      SolverBody &A = sb_[r.a], &B = sb_[r.b];
      B.v += (B.inv_m * p) * r.dir[k];
      B.w += p * r.ib[k];
      A.v -= (A.inv_m * p) * r.dir[k];
      A.w -= p * r.ia[k];
    }



    void
    VelocityContactSolver::solve(SolverContext &ctx)
    {
      auto        &bodies = *ctx.bodies;
      auto        &graph  = *ctx.graph;
      const double h      = ctx.h;
      const auto  &P      = parameters;

      // Solver copies of the velocities (pre-kick) and inverse masses.
      sb_.resize(bodies.size());
      for (unsigned int i = 0; i < bodies.size(); ++i)
        {
          const RigidBody &b = bodies[i];
          SolverBody      &s = sb_[i];
          s.v                = b.linear_velocity;
          s.w                = b.angular_velocity;
          s.inv_m            = b.inverse_mass();
          if (!b.is_fixed())
            s.inv_I = b.inverse_inertia_world();
          else
            s.inv_I.setZero();
        }

      // 1. Rows, grouped by contact group in propagation order.
      rows_.clear();
      std::vector<std::size_t> group_start;
      const auto              &groups = graph.group_edges();
      for (const auto &g : groups)
        {
          group_start.push_back(rows_.size());
          for (const unsigned int k : g)
            {
              const ContactEdge     &e   = graph.edges()[k];
              const ContactMaterial &mat = ctx.material(e);
              for (unsigned int p = 0; p < e.manifold.points.size(); ++p)
                {
                  const ContactPoint &c = e.manifold.points[p];
                  Row                 r;
                  r.a                      = e.manifold.a;
                  r.b                      = e.manifold.b;
                  r.edge                   = k;
                  r.point                  = p;
                  r.gap                    = c.distance;
                  r.e                      = mat.restitution;
                  const Eigen::Vector3d ra = c.position - bodies[r.a].position;
                  const Eigen::Vector3d rb = c.position - bodies[r.b].position;
                  r.ra_x[0]                = ra;
                  r.rb_x[0]                = rb; // radii stored temporarily
                  const Eigen::Vector3d vrel = sb_[r.b].v + sb_[r.b].w.cross(rb)
                                               - sb_[r.a].v
                                               - sb_[r.a].w.cross(ra);
                  const Eigen::Vector3d vt
                    = vrel - vrel.dot(c.normal) * c.normal;
                  r.mu = vt.norm() <= P.sticking_speed ? mat.static_friction :
                                                         mat.dynamic_friction;
                  r.dir[0] = c.normal;
                  rows_.push_back(r);
                }
            }
        }
      group_start.push_back(rows_.size());

      // Normal-direction data (needed by the restitution pass).
      for (Row &r : rows_)
        {
          const Eigen::Vector3d ra = r.ra_x[0], rb = r.rb_x[0];
          // Keep the radii in dir[1], dir[2] slots until tangents are set.
          r.dir[1]  = ra;
          r.dir[2]  = rb;
          r.ra_x[0] = ra.cross(r.dir[0]);
          r.rb_x[0] = rb.cross(r.dir[0]);
          r.ia[0]   = sb_[r.a].inv_I * r.ra_x[0];
          r.ib[0]   = sb_[r.b].inv_I * r.rb_x[0];
          r.k[0]    = sb_[r.a].inv_m + sb_[r.b].inv_m + r.ra_x[0].dot(r.ia[0])
                   + r.rb_x[0].dot(r.ib[0]);
        }

      // 2. Restitution pass, sweeping each group in propagation order.
      const double v_threshold
        = P.restitution_threshold + 2. * ctx.gravity.norm() * h;
      last_iterations_ = 0;
      for (std::size_t g = 0; g + 1 < group_start.size(); ++g)
        for (unsigned int sweep = 0; sweep < P.collision_iterations; ++sweep)
          {
            bool any = false;
            for (std::size_t i = group_start[g]; i < group_start[g + 1]; ++i)
              {
                Row         &r  = rows_[i];
                const double vn = velocity(r, 0);
                if (vn < -v_threshold && r.gap + vn * h <= 0.)
                  {
                    const double p = -(1. + r.e) * vn / r.k[0];
                    apply(r, 0, p);
                    r.collision_impulse += p;
                    any = true;
                  }
              }
            if (!any)
              break;
          }

      // 3. Kick with applied forces and gravity.
      for (unsigned int i = 0; i < bodies.size(); ++i)
        if (!bodies[i].is_fixed())
          {
            sb_[i].v += h * (sb_[i].inv_m * (*ctx.forces)[i] + ctx.gravity);
            sb_[i].w += h * (sb_[i].inv_I * (*ctx.torques)[i]);
          }

      // 4. Tangents (first one along the sliding direction), bias, warm start.
      for (Row &r : rows_)
        {
          const Eigen::Vector3d ra = r.dir[1], rb = r.dir[2], n = r.dir[0];
          const Eigen::Vector3d vrel = sb_[r.b].v + sb_[r.b].w.cross(rb)
                                       - sb_[r.a].v - sb_[r.a].w.cross(ra);
          const Eigen::Vector3d vt = vrel - vrel.dot(n) * n;
          const double          s  = vt.norm();
          r.dir[1] = s > 1.e-12 * (vrel.norm() + 1.e-300) && s > 1.e-14 ?
                       Eigen::Vector3d(vt / s) :
                       n.unitOrthogonal();
          r.dir[2] = n.cross(r.dir[1]);
          for (int k = 1; k < 3; ++k)
            {
              r.ra_x[k] = ra.cross(r.dir[k]);
              r.rb_x[k] = rb.cross(r.dir[k]);
              r.ia[k]   = sb_[r.a].inv_I * r.ra_x[k];
              r.ib[k]   = sb_[r.b].inv_I * r.rb_x[k];
              r.k[k] = sb_[r.a].inv_m + sb_[r.b].inv_m + r.ra_x[k].dot(r.ia[k])
                       + r.rb_x[k].dot(r.ib[k]);
            }
          r.bias
            = r.gap > 0. ?
                -r.gap / h :
                P.baumgarte * std::max(-r.gap - P.penetration_slop, 0.) / h;
          if (P.warm_start)
            {
              const ContactPoint &c
                = graph.edges()[r.edge].manifold.points[r.point];
              r.lambda[0] = c.normal_impulse;
              r.lambda[1] = c.tangent_impulse.dot(r.dir[1]);
              r.lambda[2] = c.tangent_impulse.dot(r.dir[2]);
            }
        }

      // 5. The contact problem, group by group (independent units, §3.3).
      for (std::size_t g = 0; g + 1 < group_start.size(); ++g)
        last_iterations_
          = std::max(last_iterations_,
                     solve_rows(group_start[g], group_start[g + 1]));

      // 6. Impulses back into the cache and the velocities into the bodies.
      for (const Row &r : rows_)
        {
          ContactPoint &c   = graph.edges()[r.edge].manifold.points[r.point];
          c.normal_impulse  = r.lambda[0];
          c.tangent_impulse = r.lambda[1] * r.dir[1] + r.lambda[2] * r.dir[2];
          c.impulse         = (r.lambda[0] + r.collision_impulse) * r.dir[0]
                      + c.tangent_impulse;
        }
      for (unsigned int i = 0; i < bodies.size(); ++i)
        if (!bodies[i].is_fixed())
          {
            bodies[i].linear_velocity  = sb_[i].v;
            bodies[i].angular_velocity = sb_[i].w;
          }
    }
  } // namespace rigid
} // namespace particulate
