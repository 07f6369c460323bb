#ifndef particulate_rigid_world_h
#define particulate_rigid_world_h

#include <particulate/rigid/contact.h>
#include <particulate/rigid/contact_graph.h>
#include <particulate/rigid/contact_solver.h>
#include <particulate/rigid/hierarchical_hash_grid.h>
#include <particulate/rigid/material.h>
#include <particulate/rigid/rigid_body.h>
#include <particulate/rigid/sphere_dem.h>

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <memory>
#include <vector>

namespace particulate {
  namespace rigid {
    /** Settings of a World (SI units). */
    struct WorldParameters
    {
      /** Gravitational acceleration in m/s^2. */
      Eigen::Vector3d gravity = Eigen::Vector3d(0., 0., -9.81);
      /** Contact model (thesis §4.4). */
      ContactSolverType contact_solver = ContactSolverType::sequential_impulses;
      /** Tuning of the contact solver. */
      ContactSolverParameters solver;
      /** Substeps per step(dt) (at least 1). The DEM raises this so that a
       * substep resolves the contact time (see dem_steps_per_contact). */
      unsigned int substeps = 1;
      /** Contact margin in m: gaps below it give contact points. 0 selects 2 %
       * of the smallest bounding radius. */
      double contact_margin = 0.;
      /** Contact offset in m: surfaces closer than this count as touching,
       * i.e. every contact model acts on the gap minus the offset, as if each
       * shape were inflated by half of it (0: the shapes themselves). A fluid
       * coupling sets it to the film thickness its mesh can still resolve, so
       * that the contact model, not an unresolved squeeze film, stops the
       * approach. */
      double contact_offset = 0.;
      /** Density in kg/m^3 of a fluid the bodies are fully immersed in; adds
       * the buoyancy -rho_f V g. Leave 0 when the fluid solver's pressure
       * already contains the hydrostatic part. */
      double fluid_density = 0.;
      /** DEM: substeps per binary contact time t_c = pi sqrt(m_eff / k_n). */
      double dem_steps_per_contact = 20.;
      /** Ratio of cell sizes of successive hash-grid levels. */
      double grid_level_ratio = 2.;
      /** DEM only: Verlet skin in m added to the bounding spheres; the broad
       * phase reruns only when some body has moved more than half of it. 0
       * selects 20 % of the smallest bounding radius. */
      double broad_phase_skin = 0.;
      /** DEM only: step worlds of spheres and half-space walls with the
       * sphere-only path (SphereDem: same physics, several times faster).
       * false keeps the general path (for comparisons and tests). */
      bool sphere_fast_path = true;
      /** Whether steps sum the impulse of every contact for contact_forces()
       * and all_contact_forces() (the fluid coupling and the body output need
       * them). false saves that work (about a tenth of a DEM step of packed
       * spheres); those calls then throw. */
      bool record_contact_forces = true;

      /** Throws std::invalid_argument naming the bad entry. */
      void
      check() const;
    };

    /** What the last step did, with wall times per stage in s. */
    struct StepStatistics
    {
      unsigned int substeps = 0, pairs = 0, contacts = 0, groups = 0,
                   solver_iterations = 0;
      double time_broad = 0., time_narrow = 0., time_solve = 0.,
             time_integrate = 0.;
    };

    /**
     * The rigid-body world: bodies, materials and the step recipe
     *
     *   for each substep:
     *     broad phase   (HierarchicalHashGrid → pairs → ContactGraph)
     *     narrow phase  (NarrowPhase → contact points, warm-start cache)
     *     contact groups (ContactGraph, Algorithm 3)
     *     solve         (ContactSolver: impulses or DEM forces, velocity kick)
     *     integrate     (NewtonEulerIntegrator: positions and rotations)
     *
     * For the fluid coupling: set the hydrodynamic force and torque of each
     * body with body(i).add_force() / add_torque() (or
     * set_external_force_and_torque()) before step(dt); they act over the
     * whole step and are cleared afterwards. Read per body position X,
     * orientation, U, omega (world frame), mass(), inertia_world(),
     * volume(), bounding_radius() from RigidBody, and after the step the
     * contact forces with contact_forces(id).
     *
     * On the sphere-only DEM path the World keeps the state of the spheres
     * in SphereDem's arrays and copies it into the RigidBody objects only
     * when they are asked for (body(), bodies() and the functions that read
     * them). A reference or pointer to a body kept across a step therefore
     * shows the new state once any of these has been called after the step
     * (any body() call copies all bodies), and changes made through it count
     * when they follow a call of the non-const body() after the last step.
     */
    class World
    {
    public:
      /** @param parameters Settings; checked here. */
      explicit World(const WorldParameters &parameters = WorldParameters());

      /** Adds a material, returns its index. */
      unsigned int
      add_material(const Material &material);

      /**
       * Adds a body and returns its id (ids are 0, 1, 2, ... in order).
       * @param shape Geometry in the body frame.
       * @param material Material index from add_material().
       * @param position Centre of mass in m.
       * @param orientation Body-to-world rotation.
       * @param fixed Whether the body is immovable (walls, obstacles;
       * half-spaces must be fixed).
       */
      BodyId
      add_body(std::shared_ptr<const geometry::Shape> shape,
               unsigned int                           material,
               const Eigen::Vector3d                 &position,
               const Eigen::Quaterniond              &orientation
               = Eigen::Quaterniond::Identity(),
               bool fixed = false);

      /**
       * Puts body @p id into collision group @p group: bodies of the same
       * non-zero group never touch (the parts of one articulated body, which
       * overlap where they are hinged). Group 0, every body's at first,
       * collides with everything.
       */
      void
      set_collision_group(BodyId id, unsigned int group);

      /** The collision group of body @p id (0: none). */
      unsigned int
      collision_group(const BodyId id) const
      {
        return collision_group_.at(id);
      }

      /** Number of bodies. */
      unsigned int
      n_bodies() const
      {
        return bodies_.size();
      }
      /** Body @p id. */
      RigidBody &
      body(BodyId id);
      /** Body @p id. */
      const RigidBody &
      body(BodyId id) const;
      /** All bodies, indexed by id. */
      const std::vector<RigidBody> &
      bodies() const
      {
        sync_bodies();
        return bodies_;
      }
      /** Material @p i. */
      const Material &
      material(unsigned int i) const
      {
        return materials_.at(i);
      }

      /** Sets (replaces) the external force (N) and torque (N m) of a body
       * for the next step, e.g. the hydrodynamic load. */
      void
      set_external_force_and_torque(BodyId                 id,
                                    const Eigen::Vector3d &force,
                                    const Eigen::Vector3d &torque);

      /** Advances the world by @p dt seconds. */
      void
      step(double dt);

      /** Simulated time in s. */
      double
      time() const
      {
        return time_;
      }
      /** Steps taken. */
      unsigned long
      step_number() const
      {
        return step_number_;
      }

      /** Contact forces on body @p id averaged over the last step (one entry
       * per touching partner; the point is the impulse-weighted centre). */
      std::vector<ContactForce>
      contact_forces(BodyId id) const;
      /** All contact forces of the last step, sorted by body. */
      const std::vector<ContactForce> &
      all_contact_forces() const;

      /** Total kinetic energy in J. */
      double
      kinetic_energy() const;
      /** Largest penetration depth in m among the current contact points (0
       * if none overlaps), measured against the contact offset: with an offset
       * it is how far the surfaces came closer than the offset. */
      double
      max_penetration() const;
      /** FNV-1a hash of the bit patterns of all positions, orientations and
       * velocities (determinism checks). */
      std::uint64_t
      state_hash() const;

      /**
       * Checkpoint: writes the dynamic state in binary (time, step count, each
       * body's position, orientation and velocities, and the contact graph
       * with its cached impulses, which warm-start the next solve). Shapes,
       * materials and settings are not written: a restart rebuilds the world
       * as before and then calls load_state(), which checks that the bodies
       * match. Stepping on from a loaded state gives the same numbers as
       * stepping on from the saved one.
       */
      void
      save_state(std::ostream &out) const;
      /** Reads what save_state() wrote; throws std::runtime_error when the
       * bodies differ. */
      void
      load_state(std::istream &in);

      /** The contact graph (edges, contact points, groups). While the DEM
       * runs on the sphere-only path this is a snapshot made on request:
       * edges and contact points, no groups. */
      const ContactGraph &
      contact_graph() const;
      /** Whether the last step ran on the sphere-only DEM path. */
      bool
      uses_sphere_fast_path() const
      {
        return sphere_dem_ != nullptr;
      }
      /** Statistics of the last step. */
      const StepStatistics &
      statistics() const
      {
        return stats_;
      }
      /** The settings. */
      const WorldParameters &
      parameters() const
      {
        return parameters_;
      }

    private:
      void
      broad_phase(double horizon);
      bool
      skin_exceeded() const;
      void
      narrow_phase(double h);
      unsigned int
      substeps_for(double dt) const;
      bool
      sphere_fast_path_applies() const;
      void
      hand_back_sphere_dem();
      void
      step_sphere_dem(unsigned int n_sub, double h);
      void
      step_general(unsigned int n_sub, double h);
      /** Copies the sphere-only path's state into bodies_ if it is newer. */
      void
      sync_bodies() const;

      WorldParameters parameters_;
      /** The bodies; on the sphere-only path a copy of its state, brought up
       * to date by sync_bodies() (hence mutable). */
      mutable std::vector<RigidBody> bodies_;
      /** bodies_ are older than the sphere-only path's state. */
      mutable bool bodies_behind_ = false;
      /** bodies_ may have been changed since the sphere-only path last read
       * them (a non-const body() call): the next step reads them. */
      bool                         bodies_written_ = true;
      std::vector<Material>        materials_;
      std::vector<ContactMaterial> pair_materials_;
      HierarchicalHashGrid         grid_;
      ContactGraph                 graph_;
      /** The sphere-only DEM path while it holds the contact state. */
      std::unique_ptr<SphereDem> sphere_dem_;
      /** Bodies that the sphere-only path cannot take (by shape). */
      unsigned int n_general_only_ = 0;
      /** Each body's collision group (0: none). */
      std::vector<unsigned int> collision_group_;
      /** Some body is in a non-zero group (the sphere-only path has none). */
      bool any_collision_group_ = false;
      /** Smallest effective contact mass of a dynamic body in kg (DEM). */
      double smallest_contact_mass_ = std::numeric_limits<double>::infinity();
      mutable ContactGraph           graph_snapshot_;
      std::unique_ptr<ContactSolver> solver_;
      std::vector<BroadPhaseProxy>   proxies_;
      std::vector<BodyPair>          pairs_;
      std::vector<ContactEdge>       dropped_;
      void
                                        assemble_contact_forces() const;
      mutable std::vector<ContactForce> contact_forces_;
      mutable std::vector<std::size_t>  force_offsets_;
      mutable bool                      forces_valid_ = true;
      double                            last_dt_      = 0.;
      std::vector<Eigen::Vector3d>      applied_force_, applied_torque_;
      std::vector<Eigen::Vector3d>      broad_positions_;
      double                            skin_        = 0.;
      double                            margin_      = 0.;
      double                            min_radius_  = 0.;
      double                            time_        = 0.;
      unsigned long                     step_number_ = 0;
      StepStatistics                    stats_;
    };
  } // namespace rigid
} // namespace particulate

#endif
