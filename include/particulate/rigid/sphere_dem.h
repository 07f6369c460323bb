#ifndef particulate_rigid_sphere_dem_h
#define particulate_rigid_sphere_dem_h

#include <particulate/rigid/contact.h>
#include <particulate/rigid/contact_graph.h>
#include <particulate/rigid/contact_solver.h>
#include <particulate/rigid/rigid_body.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace particulate {
  namespace rigid {
    struct StepStatistics;

    /**
     * The DEM (thesis §4.4.4, Algorithm 7) for worlds made only of spheres and
     * half-space walls: the same physics as DemSolver on the World's general
     * path, without its generality.
     *
     * The general path keeps an array of RigidBody objects, a contact graph
     * with a vector of contact points per edge, a virtual narrow-phase
     * dispatch and 3x3 world inertia tensors, and it pays for them on every
     * contact and substep (~430 ns per particle-step). Spheres need none of
     * it. This class holds
     *   - positions, velocities, angular velocities, orientations and force
     *     accumulators in one array per quantity, re-sorted in space
     *     (SphereNeighbourSearch) whenever the Verlet list is rebuilt;
     *   - a flat Verlet list of sphere pairs and one of sphere-wall pairs,
     *     each entry carrying the tangential spring (the contact history);
     *   - per entry, the impulse accumulated over the current step, for the
     *     contact forces that the coupling reads (World::contact_forces),
     *     unless Settings::record_contact_forces is off.
     * These arrays are the state of the spheres between steps: the World
     * copies them to its RigidBody objects (write_bodies()) only when they
     * are read, and back (read_bodies()) only when they may have been
     * changed.
     * A substep is one pass over each list (forces) and one over the spheres
     * (velocity kick, then drift and rotation), as in Algorithm 7.
     *
     * Same physics: each contact gets the spring-dashpot normal force and the
     * Coulomb-limited tangential spring of DemSolver, with the same material
     * pair values, damping formula and effective mass; spheres rotate as
     * NewtonEulerIntegrator rotates isotropic bodies; the Verlet list is
     * rebuilt by the same skin rule as the general path. What differs is
     * rounding, and one rule:
     *   - forces on a sphere are summed in another order; terms that vanish
     *     for spheres are left out (the lever arm of a sphere-sphere contact
     *     is parallel to the normal, so the normal force has no torque and the
     *     rotational terms of the effective mass are zero; on the general
     *     path they are rounding noise); the relative velocity and the
     *     torques are computed with one cross product each; the Coulomb tests
     *     compare squares. The test rigid_sphere_fast_path holds both paths
     *     to 1e-11 relative.
     *   - The general narrow phase starts a fresh contact (spring zero) when
     *     the normal turns by more than ~25 degrees within one substep; only a
     *     contact time far from resolved can do that, and this class keeps
     *     the spring.
     *
     * The World uses this class when the DEM is selected and every body
     * qualifies (can_handle()); it hands the state back as contact-graph
     * edges (export_state()) when that stops being so, and for checkpoints.
     */
    class SphereDem
    {
    public:
      /** Lengths that the World derives from its settings, in m. */
      struct Settings
      {
        /** Gaps up to this count as contacts (statistics, contact graph). */
        double margin = 0.;
        /** Contact offset (WorldParameters::contact_offset). */
        double offset = 0.;
        /** Verlet skin: the list is rebuilt when a sphere has moved more than
         * half of it. */
        double skin = 0.;
        /** Gravitational acceleration in m/s^2. */
        Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
        /** Density in kg/m^3 of the surrounding fluid, for the buoyancy
         * (WorldParameters::fluid_density). */
        double fluid_density = 0.;
        /** Whether to sum the impulses per pair for contact forces(). */
        bool record_contact_forces = true;
      };

      /** Whether this class can move @p body: a dynamic sphere free to
       * rotate about every axis, a fixed sphere or a fixed half-space. */
      static bool
      can_handle(const RigidBody &body);

      /**
       * Takes over the DEM state of a world whose bodies all qualify.
       * @param bodies The bodies.
       * @param pair_materials Pair materials, index ma * n_materials + mb.
       * @param n_materials Number of materials.
       * @param settings Lengths and gravity.
       * @param edges Contact-graph edges whose springs (single-point edges)
       * carry over (their step loads do not: the next step starts afresh).
       * @param list_positions Where the bodies were (by id) when the last
       * Verlet list was built; the list is rebuilt there, so that a restart
       * continues with the same list and the same summation order. Of
       * another size than @p bodies: the current positions.
       */
      SphereDem(const std::vector<RigidBody>       &bodies,
                const std::vector<ContactMaterial> &pair_materials,
                unsigned int                        n_materials,
                const Settings                     &settings,
                const std::vector<ContactEdge>     &edges,
                const std::vector<Eigen::Vector3d> &list_positions);

      /**
       * Takes the state of the spheres (positions, orientations, velocities)
       * and of the walls from @p bodies, and their force and torque
       * accumulators as the applied loads of the next step (plus buoyancy,
       * constant over the step); clears the accumulators. The World calls
       * this before a step when the bodies may have changed since the last
       * one.
       */
      void
      read_bodies(std::vector<RigidBody> &bodies);

      /** Writes positions, orientations and velocities of the dynamic spheres
       * to @p bodies. */
      void
      write_bodies(std::vector<RigidBody> &bodies) const;

      /**
       * Advances the spheres held here by @p n_substeps substeps of @p h
       * seconds under the loads of the last read_bodies() (buoyancy only
       * without one), as World::step() does on the general path; the applied
       * loads then fall back to the buoyancy.
       * @param stats Receives pairs, contacts and the stage times.
       */
      void
      step(unsigned int n_substeps, double h, StepStatistics &stats);

      /** Appends the contact forces of the last step of length @p dt, two
       * entries per touching pair as in World::contact_forces(), unsorted. */
      void
      append_contact_forces(double dt, std::vector<ContactForce> &out) const;

      /** Deepest overlap in m at the last substep's force evaluation (0 when
       * nothing overlaps), measured against the contact offset. */
      double
      max_penetration() const
      {
        return max_penetration_;
      }

      /**
       * The state in the general path's terms: @p edges (sorted by pair, one
       * contact point per pair within the margin or with a spring), @p dropped
       * (pairs that left the list during the step with loads) and the
       * positions by id at which the list was built.
       */
      void
      export_state(const std::vector<RigidBody> &bodies,
                   std::vector<ContactEdge>     &edges,
                   std::vector<ContactEdge>     &dropped,
                   std::vector<Eigen::Vector3d> &list_positions) const;

    private:
      /** Pair material values as DemSolver uses them. */
      struct PairMaterial
      {
        double kn, kt, cn, ct, mu_s, mu_d;
      };
      /** Impulse on the second body summed over the step (N s), and the sums
       * of |impulse| x point and of |impulse| (for the point of action). */
      struct Load
      {
        Eigen::Vector3d impulse, moment;
        double          weight;
      };
      /** Two spheres; i has the smaller body id (the general path's body a),
       * the normal points from i to j, the spring and loads belong to j. */
      struct SpherePair
      {
        std::uint32_t   i, j, material;
        double          sqrt_mass; // sqrt(m_eff), m_eff = 1 / (1/m_i + 1/m_j)
        Eigen::Vector3d spring;
      };
      /** A sphere and a wall; the normal points from the wall to the sphere,
       * the spring and loads belong to the sphere (sign-flipped towards the
       * general path when the sphere has the smaller id). */
      struct WallPair
      {
        std::uint32_t   sphere, wall, material;
        double          sqrt_mass;
        Eigen::Vector3d spring;
      };
      /** Spring and load of a pair, keyed by its body ids (a < b). */
      struct History
      {
        std::uint64_t   key;
        Eigen::Vector3d spring;
        Load            load;
      };

      void
      read_walls(const std::vector<RigidBody> &bodies);
      /** Re-sorts the spheres and rebuilds both lists around @p list_x (by
       * value: it is often x_, which the sort permutes), carrying the springs
       * and loads of @p history over. */
      void
      rebuild(std::vector<Eigen::Vector3d> list_x,
              std::vector<History>         history,
              bool                         keep_dropped);
      std::vector<History>
      history() const;
      template <bool record>
      void
      contact_forces(double h, bool first_substep, bool last_substep);
      template <bool loads>
      bool
      integrate(double h);

      Settings                  settings_;
      std::vector<PairMaterial> materials_;
      unsigned int              n_materials_;

      // Spheres, in spatial order.
      std::vector<BodyId>          id_;
      std::vector<Eigen::Vector3d> x_, v_, w_, f_, t_, applied_f_, applied_t_;
      /** -rho_f V g of a dynamic sphere (0 for a fixed one). */
      std::vector<Eigen::Vector3d>    buoyancy_;
      std::vector<Eigen::Vector3d>    x_list_;
      std::vector<Eigen::Quaterniond> q_;
      std::vector<double>             radius_, inverse_mass_, inverse_inertia_;
      std::vector<unsigned int>       material_;

      // Walls: world plane n . x = offset; the body's velocity for the
      // relative velocity at the contact.
      std::vector<BodyId>          wall_id_;
      std::vector<Eigen::Vector3d> wall_normal_, wall_position_, wall_v_,
        wall_w_;
      std::vector<Eigen::Vector3d> wall_list_position_;
      std::vector<double>          wall_offset_;
      std::vector<unsigned int>    wall_material_;

      std::vector<SpherePair>                     pairs_;
      std::vector<Load>                           pair_loads_;
      std::vector<WallPair>                       walls_;
      std::vector<Load>                           wall_loads_;
      std::vector<std::pair<std::uint64_t, Load>> dropped_;

      bool rebuild_needed_ = false;
      /** Whether applied_f_, applied_t_ hold more than the buoyancy. */
      bool         loads_applied_   = false;
      double       max_penetration_ = 0.;
      unsigned int contacts_        = 0;
    };
  } // namespace rigid
} // namespace particulate

#endif
