#ifndef particulate_fbm_particle_world_h
#define particulate_fbm_particle_world_h

#include <particulate/fbm/articulated_assembly.h>
#include <particulate/fbm/body_state_guard.h>
#include <particulate/fbm/particle_parameters.h>
#include <particulate/rigid/world.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <memory>
#include <vector>

namespace particulate {
  namespace fbm {
    /** What the rigid engine needs beyond the particle set. */
    struct ParticleWorldFrame
    {
      /// the mesh's box; its faces marked in ParticleParameters::walls
      /// become half-spaces
      DomainBox domain;
      /// the engine's contact distance [m]
      double contact_offset = 0.;
      /// gravity inside the engine [m/s^2] (zero where the coupling
      /// applies the buoyancy-corrected weight itself)
      Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
      /// added to each particle's density inside the engine: C rho_f for
      /// the coupling's added-mass correction, 0 without a fluid [kg/m^3]
      double added_density = 0.;
    };

    /** The engine with the particles (body i is particle i) and the walls
     *  after them. */
    struct ParticleWorld
    {
      std::unique_ptr<rigid::World> world;
      std::vector<rigid::BodyId>    ids;
    };

    /**
     * The rigid engine of a case: the particles as @p particles describes
     * them, at @p starts (one per particle), fixed, prescribed and hinged
     * ones immovable, rotations locked as the case locks them, with one
     * material per density the engine sees (restitution and friction of the
     * case); then the walls of @p frame's box. The head of an articulated
     * body carries its parts' mass and inertia (assembly_inertia()), and
     * its parts do not collide with it or with each other.
     */
    ParticleWorld
    build_particle_world(const ParticleParameters     &particles,
                         const std::vector<BodyStart> &starts,
                         const ParticleWorldFrame     &frame);

    /** Undo what a step did to @p body along the locked axes (translation
     *  and rotation about each world axis), from its pose before the step;
     *  with all three rotations locked, its orientation too. */
    void
    restore_locked_axes(rigid::RigidBody          &body,
                        const Eigen::Vector3d     &old_position,
                        const Eigen::Quaterniond  &old_orientation,
                        const std::array<bool, 3> &locked_translation,
                        const std::array<bool, 3> &locked_rotation);

    /** The indices in @p particles of the bodies that move freely, as
     *  engine ids. */
    std::vector<rigid::BodyId>
    free_body_ids(const ParticleParameters         &particles,
                  const std::vector<rigid::BodyId> &ids);

    /** Each particle's motion, in the order of the particle set. */
    std::vector<ParticleMotion>
    particle_motions(const ParticleParameters &particles);
  } // namespace fbm
} // namespace particulate

#endif
