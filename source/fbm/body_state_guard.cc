#include <particulate/fbm/body_state_guard.h>
#include <particulate/geometry/pose.h>
#include <particulate/rigid/narrow_phase.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace particulate {
  namespace fbm {
    namespace {
      const char *const face_names[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};

      bool
      finite(const Eigen::Vector3d &v)
      {
        return v.allFinite();
      }

      /** Calls @p f(d, positive, face) for the faces x-, x+, y-, ... of a
       *  box in @p dim dimensions (face = 2 d + positive). */
      template <typename Function>
      void
      for_each_face(const unsigned int dim, const Function &f)
      {
        for (unsigned int d = 0; d < dim; ++d)
          for (const bool positive : {false, true})
            f(d, positive, 2 * d + (positive ? 1 : 0));
      }

      // what a message about a centre beyond an open face advises
      const char *const free_body_advice
        = "Make it a wall with 'Domain walls' in subsection 'Particles' "
          "(its name, 'mantle' for a column's, or 'all'), or end the run "
          "('End time') before the particle reaches it.";
      const char *const hinged_part_advice
        = "Nothing stops a body whose motion the case gives: change its "
          "'Hinge angle', 'Hinge point' or start pose, or its parent's "
          "motion, so that it stays inside the domain.";
      const char *const prescribed_body_advice
        = "Nothing stops a body whose motion the case gives: change its "
          "prescribed motion or its start so that it stays inside the "
          "domain.";

      [[noreturn]] void
      stop(const std::ostringstream &message)
      {
        throw std::runtime_error(message.str());
      }
    } // namespace



    double
    body_size(const rigid::RigidBody &body, const unsigned int dim)
    {
      const geometry::BoundingBox box  = body.shape().bounding_box();
      double                      size = box.upper[0] - box.lower[0];
      for (unsigned int d = 1; d < dim; ++d)
        size = std::min(size, box.upper[d] - box.lower[d]);
      return size;
    }



    geometry::BoundingBox
    placed_extent(const rigid::RigidBody &body)
    {
      const geometry::Pose   pose(body.orientation, body.position);
      const geometry::Shape &shape = body.shape();
      geometry::BoundingBox  extent;
      if (shape.is_convex())
        {
          for (unsigned int d = 0; d < 3; ++d)
            for (const double sign : {-1., 1.})
              {
                Eigen::Vector3d axis = Eigen::Vector3d::Zero();
                axis[d]              = sign;
                extent.extend(pose.to_world(
                  shape.support(body.orientation.conjugate() * axis)));
              }
          return extent;
        }
      // a surface mesh reaches farthest at its vertices, where a turned
      // bounding box may reach well beyond it (another non-convex shape:
      // its surface points, as the narrow phase sees it)
      const std::vector<Eigen::Vector3d> points = shape.surface_points();
      if (points.empty())
        return pose.to_world(shape.bounding_box());
      for (const Eigen::Vector3d &p : points)
        extent.extend(pose.to_world(p));
      return extent;
    }



    double
    body_reach(const rigid::RigidBody &body,
               const unsigned int      d,
               const bool              positive)
    {
      const geometry::BoundingBox extent = placed_extent(body);
      return positive ? extent.upper[d] : extent.lower[d];
    }



    BodyStateGuard::BodyStateGuard(
      const DomainBox                   &domain,
      const std::vector<rigid::BodyId>  &particle_ids,
      const double                       contact_distance,
      const std::vector<ParticleMotion> &motions)
      : domain(domain)
      , ids(particle_ids)
      , contact_distance(contact_distance)
      , motions(motions)
    {
      if (!motions.empty() && motions.size() != ids.size())
        throw std::logic_error("BodyStateGuard: one motion per particle");
      for (unsigned int i = 0; i < ids.size(); ++i)
        {
          if (ids[i] >= particle_of.size())
            particle_of.resize(ids[i] + 1, -1);
          particle_of[ids[i]] = i;
        }
    }



    void
    BodyStateGuard::start_step(const rigid::World &world)
    {
      start_positions.resize(ids.size());
      for (unsigned int i = 0; i < ids.size(); ++i)
        start_positions[i] = world.body(ids[i]).position;
    }



    void
    BodyStateGuard::check_step(const rigid::World &world,
                               const double        t,
                               const double        dt) const
    {
      for (unsigned int i = 0; i < ids.size(); ++i)
        {
          const rigid::RigidBody &body = world.body(ids[i]);
          if (body.is_fixed())
            continue;
          check_finite(body, i, t);
          check_displacement(body, i, t, dt);
          check_walls(body, i, t, dt);
          check_inside(body, i, t, free_body_advice);
        }
      check_overlaps(world, t);
    }



    void
    BodyStateGuard::check_given_motions(const rigid::World &world,
                                        const double        t) const
    {
      for (unsigned int i = 0; i < motions.size(); ++i)
        {
          if (motions[i] != ParticleMotion::prescribed
              && motions[i] != ParticleMotion::hinged)
            continue;
          const bool  hinged = motions[i] == ParticleMotion::hinged;
          const char *advice
            = hinged ? hinged_part_advice : prescribed_body_advice;
          const rigid::RigidBody     &body      = world.body(ids[i]);
          const std::array<double, 6> beyond    = reach_beyond_walls(body);
          const double                tolerance = wall_tolerance(body);
          for (unsigned int face = 0; face < 2 * domain.dim; ++face)
            if (beyond[face] > tolerance)
              {
                std::ostringstream message;
                message << "Particle " << i
                        << " (Motion = " << (hinged ? "hinged" : "prescribed")
                        << ") reaches " << beyond[face] << " m beyond the wall "
                        << (domain.is_column() && face < 4 ? "mantle" :
                                                             face_names[face])
                        << " at t = " << t << " s, more than the tolerance "
                        << tolerance << " m. " << advice;
                stop(message);
              }
          check_inside(body, i, t, advice);
        }
    }



    void
    BodyStateGuard::check_finite(const rigid::RigidBody &body,
                                 const unsigned int      i,
                                 const double            t) const
    {
      if (finite(body.position) && finite(body.linear_velocity)
          && finite(body.angular_velocity)
          && body.orientation.coeffs().allFinite())
        return;
      std::ostringstream message;
      message << "Particle " << i << " has a position or velocity that is "
              << "no longer finite (NaN or Inf) at t = " << t
              << " s: the coupling of the particle and the fluid diverged. "
                 "Reduce 'Time step' in subsection 'Time', or raise 'Added "
                 "mass coefficient' in subsection 'Particles' for a light "
                 "particle.";
      stop(message);
    }



    void
    BodyStateGuard::check_displacement(const rigid::RigidBody &body,
                                       const unsigned int      i,
                                       const double            t,
                                       const double            dt) const
    {
      if (start_positions.size() != ids.size())
        return;
      const double size = body_size(body, domain.dim);
      const double moved
        = (body.position - start_positions[i]).head(domain.dim).norm();
      if (moved <= size)
        return;
      const double       speed = moved / dt;
      std::ostringstream message;
      message << "Particle " << i << " moved " << moved
              << " m in the step from t = " << t - dt << " to " << t
              << " s, more than its size " << size
              << " m (the smallest edge of its bounding box): the time "
                 "step is too large for it (or the coupling diverged). At "
                 "its mean speed in the step, "
              << speed
              << " m/s, a time step below size / speed = " << size / speed
              << " s keeps it within its size; the fictitious boundary "
                 "method needs a much smaller one, of the order of a cell "
                 "size / speed. Reduce 'Time step' in subsection 'Time'; "
                 "if its speed grew from step to step (the coupling "
                 "diverged, see particle_"
              << i
              << ".dat), raise 'Added mass coefficient' in subsection "
                 "'Particles' instead.";
      stop(message);
    }



    double
    BodyStateGuard::wall_tolerance(const rigid::RigidBody &body) const
    {
      return std::max(contact_distance, 0.01 * body_size(body, domain.dim));
    }



    std::array<double, 6>
    BodyStateGuard::reach_beyond_walls(const rigid::RigidBody &body) const
    {
      std::array<double, 6> beyond;
      beyond.fill(-std::numeric_limits<double>::infinity());
      const geometry::BoundingBox extent = placed_extent(body);
      for_each_face(domain.dim,
                    [&](const unsigned int d,
                        const bool         positive,
                        const unsigned int face) {
                      if (!domain.walls[face]
                          || (domain.is_column() && d < 2 && face > 0))
                        return;
                      const bool   mantle = domain.is_column() && d < 2;
                      const double wall   = domain.wall_position(face);
                      beyond[face]        = mantle ? reach_from_axis(domain,
                                                              body.shape(),
                                                              body.orientation,
                                                              body.position)
                                                - domain.column_radius :
                                            positive ? extent.upper[d] - wall :
                                                       wall - extent.lower[d];
                    });
      return beyond;
    }



    void
    BodyStateGuard::check_walls(const rigid::RigidBody &body,
                                const unsigned int      i,
                                const double            t,
                                const double            dt) const
    {
      const double                tolerance = wall_tolerance(body);
      const std::array<double, 6> beyond    = reach_beyond_walls(body);
      for (unsigned int face = 0; face < 2 * domain.dim; ++face)
        {
          if (beyond[face] <= tolerance)
            continue;
          std::ostringstream message;
          message << "Particle " << i << " crossed the wall "
                  << (domain.is_column() && face < 4 ? "mantle" :
                                                       face_names[face])
                  << " at t = " << t << " s: it reaches " << beyond[face]
                  << " m beyond it, more than the tolerance " << tolerance
                  << " m (the contact distance, at least 1 % of its size). "
                     "Its contact with the wall failed at its speed of "
                  << body.linear_velocity.norm() << " m/s ("
                  << body.linear_velocity.norm() * dt
                  << " m per time step, against a contact distance of "
                  << contact_distance
                  << " m). Reduce 'Time step' in subsection 'Time' or "
                     "raise 'Rigid substeps' "
                     "in subsection 'Particles'.";
          stop(message);
        }
    }



    void
    BodyStateGuard::check_inside(const rigid::RigidBody &body,
                                 const unsigned int      i,
                                 const double            t,
                                 const char             *advice) const
    {
      const double tolerance
        = 1e-9 * (domain.upper - domain.lower).head(domain.dim).norm();
      for_each_face(domain.dim,
                    [&](const unsigned int d,
                        const bool         positive,
                        const unsigned int face) {
                      if (domain.mirror_planes[face])
                        return;
                      if (domain.is_column() && d < 2)
                        {
                          if (face == 0)
                            check_inside_column(body, i, t, advice);
                          return;
                        }
                      const double x       = body.position[d];
                      const bool   outside = positive ?
                                               x > domain.upper[d] + tolerance :
                                               x < domain.lower[d] - tolerance;
                      if (!outside)
                        return;
                      std::ostringstream message;
                      message
                        << "Particle " << i << " left the domain at t = " << t
                        << " s: its centre is at "
                        << "xyz"[d] << " = " << x << " m, beyond the face "
                        << face_names[face] << " at "
                        << (positive ? domain.upper[d] : domain.lower[d])
                        << " m, which is not a wall. " << advice;
                      stop(message);
                    });
    }



    void
    BodyStateGuard::check_inside_column(const rigid::RigidBody &body,
                                        const unsigned int      i,
                                        const double            t,
                                        const char             *advice) const
    {
      const double rho = domain.distance_from_axis(body.position);
      if (rho <= domain.column_radius * (1. + 1e-9))
        return;
      std::ostringstream message;
      message << "Particle " << i << " left the domain at t = " << t
              << " s: its centre is " << rho
              << " m from the column's axis, beyond the mantle at "
              << domain.column_radius << " m, which is not a wall. " << advice;
      stop(message);
    }



    void
    BodyStateGuard::check_overlaps(const rigid::World &world,
                                   const double        t) const
    {
      const auto particle = [&](const rigid::BodyId id) {
        return id < particle_of.size() ? particle_of[id] : -1;
      };
      for (const rigid::ContactEdge &edge : world.contact_graph().edges())
        {
          const int i = particle(edge.manifold.a);
          const int j = particle(edge.manifold.b);
          if (i < 0 || j < 0) // walls have their own check
            continue;
          const rigid::RigidBody &a = world.body(edge.manifold.a);
          const rigid::RigidBody &b = world.body(edge.manifold.b);
          if (a.is_fixed() && b.is_fixed())
            continue;
          // the graph's points are those of the start of the last substep:
          // measure where the bodies are now
          rigid::ContactEdge now = edge;
          rigid::NarrowPhase::collide(a, b, 0., now);
          double overlap = 0.;
          for (const rigid::ContactPoint &p : now.manifold.points)
            overlap = std::max(overlap, -p.distance);
          const double size
            = std::min(body_size(a, domain.dim), body_size(b, domain.dim));
          if (overlap <= max_overlap_fraction * size)
            continue;
          std::ostringstream message;
          message << "Particles " << std::min(i, j) << " and " << std::max(i, j)
                  << " overlap by " << overlap << " m at t = " << t
                  << " s, more than " << 100. * max_overlap_fraction
                  << " % of the smaller one's size " << size
                  << " m: their contact failed. Their relative speed is "
                  << (a.linear_velocity - b.linear_velocity).norm()
                  << " m/s; the contact distance is " << contact_distance
                  << " m. Reduce 'Time step' in subsection 'Time' or raise "
                     "'Rigid substeps' in subsection 'Particles'.";
          stop(message);
        }
    }
  } // namespace fbm
} // namespace particulate
