#ifndef particulate_fbm_body_state_guard_h
#define particulate_fbm_body_state_guard_h

#include <particulate/fbm/domain_box.h>
#include <particulate/fbm/particle_description.h>
#include <particulate/geometry/bounding_box.h>
#include <particulate/rigid/world.h>

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * The physical sanity checks of the bodies after each coupled step. A
     * run that fails one stops with a message saying what happened, to
     * which particle, and what to do, before the step's state is written
     * anywhere. In the order checked:
     * - a position, orientation or velocity that is no longer finite;
     * - a body that moved farther in one step than its size (the smallest
     *   edge of its bounding box): the time step is too large for it, and
     *   the message gives the step that its speed allows;
     * - a body that crossed a wall of the rigid engine by more than the
     *   contact distance (at least 1 % of its size, since DEM contacts
     *   overlap by design): its contacts failed;
     * - a body whose centre left the domain through a face that is not a
     *   wall or a mirror plane;
     * - two bodies that overlap by more than max_overlap_fraction of the
     *   smaller one's size (the contact pairs of the engine's contact
     *   graph, their overlap measured anew at the end of the step).
     * Bodies that are immovable in the engine (fixed and prescribed
     * particles, hinged parts, walls) are not checked there: nothing in
     * the engine moves them. Those whose motion the case gives (prescribed
     * particles and hinged parts) are checked by check_given_motions(),
     * at the start and after each step: a motion that takes one through a
     * wall or out of the domain is the case's error.
     */
    class BodyStateGuard
    {
    public:
      /**
       * The overlap of two bodies, as a fraction of the smaller one's
       * size, that stops a run. DEM springs overlap by design, by
       * v sqrt(m / k) at an impact speed v: 0.1 % of the size for a sphere
       * of radius 5 mm and density 2500 kg/m^3 at 0.1 m/s and the default
       * stiffness; a velocity solver keeps the overlap below the contact
       * distance. Fifty times the first means the contact failed.
       */
      static constexpr double max_overlap_fraction = 0.05;

      /**
       * @param particle_ids The particles' bodies in the world, in the
       *   order of the particle set (the messages name particle i).
       * @param contact_distance The rigid engine's contact distance [m].
       * @param motions Each particle's motion, in the same order (empty:
       *   check_given_motions() checks nothing).
       */
      BodyStateGuard(const DomainBox                   &domain,
                     const std::vector<rigid::BodyId>  &particle_ids,
                     const double                       contact_distance,
                     const std::vector<ParticleMotion> &motions = {});

      /** Remembers where the bodies are at the start of a step. */
      void
      start_step(const rigid::World &world);

      /**
       * Checks the bodies at the end of the step from @p t - @p dt to
       * @p t.
       * @throw std::runtime_error saying what happened, to which particle,
       *   and what to do
       */
      void
      check_step(const rigid::World &world,
                 const double        t,
                 const double        dt) const;

      /**
       * Checks the particles whose motion the case gives (prescribed,
       * hinged) where they are at @p t: within the walls (to the tolerance
       * of check_step()) and with their centres inside the domain.
       * @throw std::runtime_error naming the particle, its motion, the
       *   face and the time
       */
      void
      check_given_motions(const rigid::World &world, const double t) const;

    private:
      void
      check_finite(const rigid::RigidBody &body,
                   const unsigned int      i,
                   const double            t) const;
      void
      check_displacement(const rigid::RigidBody &body,
                         const unsigned int      i,
                         const double            t,
                         const double            dt) const;
      void
      check_walls(const rigid::RigidBody &body,
                  const unsigned int      i,
                  const double            t,
                  const double            dt) const;
      /** How far @p body reaches beyond each wall face (x-, x+, y-, ...;
       *  a column's mantle at x-); faces that are not walls: -inf. */
      std::array<double, 6>
      reach_beyond_walls(const rigid::RigidBody &body) const;
      /** How far a body may reach beyond a wall: the contact distance, at
       *  least 1 % of its size. */
      double
      wall_tolerance(const rigid::RigidBody &body) const;
      /** @p advice: what the message tells the user to do. */
      void
      check_inside(const rigid::RigidBody &body,
                   const unsigned int      i,
                   const double            t,
                   const char             *advice) const;
      void
      check_inside_column(const rigid::RigidBody &body,
                          const unsigned int      i,
                          const double            t,
                          const char             *advice) const;
      void
      check_overlaps(const rigid::World &world, const double t) const;

      DomainBox                  domain;
      std::vector<rigid::BodyId> ids;
      /// the particle of each body id (-1 for walls and other bodies)
      std::vector<int>             particle_of;
      double                       contact_distance;
      std::vector<ParticleMotion>  motions;
      std::vector<Eigen::Vector3d> start_positions;
    };

    /** The smallest edge of the body's bounding box among the first
     *  @p dim axes [m]: the size that a step may not move it by. */
    double
    body_size(const rigid::RigidBody &body, const unsigned int dim);

    /** The box of the world axes that the body fills at its pose: exact
     *  for convex shapes (their support points) and surface meshes (their
     *  vertices); for other non-convex shapes the box of their surface
     *  points, for those without, the placed bounding box. */
    geometry::BoundingBox
    placed_extent(const rigid::RigidBody &body);

    /** The coordinate of the body's furthest point along the world axis
     *  @p d, towards + (@p positive) or - (exact for convex shapes and
     *  surface meshes, whose farthest point is a vertex; the farthest of the
     *  surface points for other non-convex shapes, the placed bounding box
     *  for those without). */
    double
    body_reach(const rigid::RigidBody &body,
               const unsigned int      d,
               const bool              positive);

  } // namespace fbm
} // namespace particulate

#endif
