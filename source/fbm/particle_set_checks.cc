#include <particulate/fbm/articulated_assembly.h>
#include <particulate/fbm/particle_set_checks.h>
#include <particulate/geometry/pose.h>
#include <particulate/rigid/narrow_phase.h>
#include <particulate/rigid/rigid_body.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace fbm {
    namespace {
      /** The placed body of @p p, immovable (no mass properties needed). */
      rigid::RigidBody
      placed_body(const ParticleDescription &p)
      {
        rigid::RigidBody body(p.shape, 0, 1., true);
        body.position    = p.position;
        body.orientation = p.orientation;
        return body;
      }

      /** The smallest gap between @p a and @p b up to @p margin [m]
       *  (negative: they overlap; infinite: farther apart than
       *  @p margin). */
      double
      smallest_gap(const rigid::RigidBody &a,
                   const rigid::RigidBody &b,
                   const double            margin)
      {
        rigid::ContactEdge edge;
        edge.manifold.a = 0;
        edge.manifold.b = 1;
        rigid::NarrowPhase::collide(a, b, margin, edge);
        double gap = std::numeric_limits<double>::infinity();
        for (const auto &c : edge.manifold.points)
          gap = std::min(gap, c.distance);
        return gap;
      }

      /** The face of the box (x-, x+, y-, ...) that the wall @p body, a
       *  half-space whose outward normal points into the fluid, lies on;
       *  "mantle" for the tube around a column. */
      std::string
      wall_face(const rigid::RigidBody &body)
      {
        if (body.shape().is_bounded())
          return "mantle"; // the only bounded wall: a column's tube
        Eigen::Vector3d n;
        body.shape().signed_distance(body.to_body(Eigen::Vector3d::Zero()), &n);
        n = body.rotation() * n;
        Eigen::Index axis;
        n.cwiseAbs().maxCoeff(&axis);
        return std::string(1, "xyz"[axis]) + (n[axis] > 0. ? "-" : "+");
      }

      /**
       * Calls @p visit(i, j) once for every pair i != j of balls (centres
       * @p centres, radii @p radii) that come closer than @p reach: a sweep
       * along x over the balls sorted by their lowest x, so the cost grows
       * with the number of balls and of pairs that overlap in x, not with
       * their square. A 2D set (@p dim = 2) ignores z.
       */
      template <typename Visit>
      void
      for_each_close_pair(const std::vector<Eigen::Vector3d> &centres,
                          const std::vector<double>          &radii,
                          const double                        reach,
                          const unsigned int                  dim,
                          const Visit                        &visit)
      {
        const unsigned int        n = centres.size();
        std::vector<unsigned int> order(n);
        std::iota(order.begin(), order.end(), 0u);
        std::sort(order.begin(),
                  order.end(),
                  [&](unsigned int i, unsigned int j) {
                    return centres[i][0] - radii[i] < centres[j][0] - radii[j];
                  });
        for (unsigned int s = 0; s < n; ++s)
          for (unsigned int t = s + 1; t < n; ++t)
            {
              const unsigned int i = order[s], j = order[t];
              if (centres[j][0] - radii[j] >= centres[i][0] + radii[i] + reach)
                break;
              Eigen::Vector3d d = centres[j] - centres[i];
              if (dim == 2)
                d[2] = 0.;
              if (d.norm() < radii[i] + radii[j] + reach)
                visit(i, j);
            }
      }

      /** The deepest penetration of two placed particles [m] (0 if they
       *  are apart or touch). */
      double
      penetration(const ParticleDescription &a, const ParticleDescription &b)
      {
        return std::max(0., -smallest_gap(placed_body(a), placed_body(b), 0.));
      }
    } // namespace



    void
    check_no_overlap(const std::vector<ParticleDescription> &particles,
                     const unsigned int                      dim)
    {
      // the bounding balls first, then the exact test
      std::vector<Eigen::Vector3d> centres;
      std::vector<double>          radii;
      for (const ParticleDescription &p : particles)
        {
          centres.push_back(p.position);
          radii.push_back(p.shape->bounding_radius());
        }
      for_each_close_pair(centres,
                          radii,
                          0.,
                          dim,
                          [&](unsigned int i, unsigned int j) {
                            // the parts of an articulated body may overlap
                            if (assembly_head(particles, i)
                                == assembly_head(particles, j))
                              return;
                            const double depth
                              = penetration(particles[i], particles[j]);
                            const double size = std::min(radii[i], radii[j]);
                            if (depth > 1e-9 * size)
                              {
                                std::ostringstream message;
                                message
                                  << "particles " << std::min(i, j) << " and "
                                  << std::max(i, j) << " overlap by " << depth
                                  << " m at the start:\n  "
                                  << particles[std::min(i, j)].origin << "\n  "
                                  << particles[std::max(i, j)].origin
                                  << "\nMove them apart (they may touch).";
                                throw std::runtime_error(message.str());
                              }
                          });
    }



    namespace {
      /** Refuse particle @p i where it reaches beyond a column's mantle. */
      void
      check_inside_column(const ParticleDescription &p,
                          const unsigned int         i,
                          const DomainBox           &domain)
      {
        const double reach
          = reach_from_axis(domain, *p.shape, p.orientation, p.position);
        if (reach <= domain.column_radius * (1. + 1e-9))
          return;
        std::ostringstream message;
        message << p.origin << ": particle " << i
                << " reaches outside the column: it reaches " << reach
                << " m from the axis, the mantle is " << domain.column_radius
                << " m from it. Move it inside.";
        throw std::runtime_error(message.str());
      }
    } // namespace



    void
    check_inside_domain(const std::vector<ParticleDescription> &particles,
                        const DomainBox                        &domain)
    {
      const Eigen::Vector3d     &lower = domain.lower, &upper = domain.upper;
      const std::array<bool, 6> &mirror_planes = domain.mirror_planes;
      const unsigned int         dim           = domain.dim;
      const double tolerance = 1e-9 * (upper - lower).head(dim).norm();
      for (unsigned int i = 0; i < particles.size(); ++i)
        {
          const ParticleDescription  &p = particles[i];
          const geometry::BoundingBox box
            = geometry::Pose(p.orientation, p.position)
                .to_world(p.shape->bounding_box());
          if (domain.is_column())
            check_inside_column(p, i, domain);
          for (unsigned int d = domain.is_column() ? 2 : 0; d < dim; ++d)
            {
              // wider than the domain along an axis without a mirror plane:
              // no position fits it
              if (!mirror_planes[2 * d] && !mirror_planes[2 * d + 1]
                  && box.upper[d] - box.lower[d]
                       > upper[d] - lower[d] + tolerance)
                {
                  std::ostringstream message;
                  message << p.origin << ": particle " << i
                          << " is larger than the domain: it spans "
                          << box.upper[d] - box.lower[d] << " m along "
                          << "xyz"[d] << ", the mesh " << upper[d] - lower[d]
                          << " m. Make the particle smaller or the domain "
                             "larger.";
                  throw std::runtime_error(message.str());
                }
              const bool below = box.lower[d] < lower[d] - tolerance
                                 && !(mirror_planes[2 * d]
                                      && p.position[d] >= lower[d] - tolerance);
              const bool above = box.upper[d] > upper[d] + tolerance
                                 && !(mirror_planes[2 * d + 1]
                                      && p.position[d] <= upper[d] + tolerance);
              if (below || above)
                {
                  std::ostringstream message;
                  message << p.origin << ": particle " << i
                          << " reaches outside the domain: it spans "
                          << box.lower[d] << " to " << box.upper[d]
                          << " m along "
                          << "xyz"[d] << ", the mesh " << lower[d] << " to "
                          << upper[d] << " m. Move it inside.";
                  throw std::runtime_error(message.str());
                }
            }
        }
    }



    void
    check_on_mirror_planes(const std::vector<ParticleDescription> &particles,
                           const Eigen::Vector3d                  &lower,
                           const Eigen::Vector3d                  &upper,
                           const std::array<bool, 6> &mirror_planes,
                           const unsigned int         dim)
    {
      for (unsigned int f = 0; f < 2 * dim; ++f)
        if (mirror_planes[f])
          {
            const unsigned int a     = f / 2;
            const double       plane = f % 2 ? upper[a] : lower[a];
            for (unsigned int i = 0; i < particles.size(); ++i)
              if (std::abs(particles[i].position[a] - plane)
                  > 1e-9 * (upper[a] - lower[a]))
                {
                  std::ostringstream message;
                  message << particles[i].origin << ": particle " << i
                          << " does not lie on the mirror plane "
                          << "xyz"[a] << " = " << plane
                          << " of 'Symmetry planes'; put its centre there or "
                             "remove the plane.";
                  throw std::runtime_error(message.str());
                }
          }
    }



    void
    check_contact_clearance(const rigid::World               &world,
                            const std::vector<rigid::BodyId> &particle_ids,
                            const std::vector<ParticleDescription> &particles,
                            const double                            clearance)
    {
      std::vector<int> particle_of(world.n_bodies(), -1);
      for (unsigned int i = 0; i < particle_ids.size(); ++i)
        particle_of[particle_ids[i]] = static_cast<int>(i);
      const auto describe = [&](const rigid::BodyId id) {
        return particle_of[id] >= 0 ?
                 "particle " + std::to_string(particle_of[id]) + " ("
                   + particles[particle_of[id]].origin + ")" :
                 "the domain wall " + wall_face(world.body(id));
      };
      const auto check = [&](const rigid::BodyId a, const rigid::BodyId b) {
        const rigid::RigidBody &A = world.body(a), &B = world.body(b);
        // nor the parts of an articulated body, which meet at their hinges
        if ((A.is_fixed() && B.is_fixed())
            || (world.collision_group(a) != 0
                && world.collision_group(a) == world.collision_group(b)))
          return;
        const bool   a_first = A.shape().kind() <= B.shape().kind();
        const double gap     = a_first ? smallest_gap(A, B, clearance) :
                                         smallest_gap(B, A, clearance);
        if (gap < clearance * (1. - 1e-6))
          {
            std::ostringstream message;
            if (gap < 0.)
              message << describe(a) << " and " << describe(b) << " overlap by "
                      << -gap << " m at the start"
                      << (particle_of[a] < 0 || particle_of[b] < 0 ?
                            " (the particle lies partly or wholly beyond the "
                            "wall)" :
                            "")
                      << ". Move them apart by at least the contact "
                         "distance "
                      << clearance << " m.";
            else
              message << describe(a) << " and " << describe(b) << " start "
                      << gap << " m apart, closer than the contact distance "
                      << clearance
                      << " m that the rigid engine keeps between surfaces: "
                         "it would push them apart in the first step. "
                         "Space them at least that far apart (a random "
                         "fill: its 'Clearance'), or set a smaller 'Contact "
                         "distance' in subsection 'Particles' (a finer mesh "
                         "lowers 'auto').";
            throw std::runtime_error(message.str());
          }
      };
      // bounded bodies pairwise by their bounding balls; each against every
      // unbounded one (the walls)
      std::vector<rigid::BodyId>   bounded, unbounded;
      std::vector<Eigen::Vector3d> centres;
      std::vector<double>          radii;
      for (rigid::BodyId id = 0; id < world.n_bodies(); ++id)
        if (world.body(id).shape().is_bounded())
          {
            bounded.push_back(id);
            centres.push_back(world.body(id).position);
            radii.push_back(world.body(id).bounding_radius());
          }
        else
          unbounded.push_back(id);
      for_each_close_pair(centres,
                          radii,
                          clearance,
                          3,
                          [&](unsigned int i, unsigned int j) {
                            check(std::min(bounded[i], bounded[j]),
                                  std::max(bounded[i], bounded[j]));
                          });
      for (const rigid::BodyId b : bounded)
        for (const rigid::BodyId w : unbounded)
          check(std::min(b, w), std::max(b, w));
    }
  } // namespace fbm
} // namespace particulate
