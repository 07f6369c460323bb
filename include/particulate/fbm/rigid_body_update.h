#ifndef particulate_fbm_rigid_body_update_h
#define particulate_fbm_rigid_body_update_h

#include <particulate/fbm/articulated_assembly.h>
#include <particulate/fbm/body_coupling_state.h>
#include <particulate/fbm/energy_balance.h>
#include <particulate/fbm/particle_parameters.h>
#include <particulate/rigid/world.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * The bodies' half of a coupled step (thesis §5.3 step 4, eq. 5.3):
     * the fluid's loads, buoyancy-corrected gravity and contacts move the
     * free bodies in the rigid engine.
     *
     * The explicit coupling is stabilised by an added-mass correction: the
     * engine integrates each body with the mass m + m_a and the inertia
     * I + I_a (its material density is rho_p + C rho_f), and the force gets
     * m_a a_n, the torque I_a alpha_n + omega_n x (I_a omega_n), with the
     * accelerations and the angular velocity of the step before. Where the
     * loads do not change, the accelerations converge to those of the true
     * mass geometrically, with the ratio m_a / (m + m_a). The gyroscopic
     * part matters for a body that is not a sphere turning about an axis
     * that is not a principal one: the engine's Euler equations carry
     * omega x ((I + I_a) omega), and without it the body would turn as if
     * it were 1 + C times as heavy against the fluid's torque (a spheroid in
     * shear flow drifted off its Jeffery orbit).
     *
     * Locked axes (symmetry planes, planar motion) get no force or torque,
     * and what contacts or rounding did along them is undone. A contact
     * that stops a body stops its added mass too: the component of the
     * acceleration into a touching surface is dropped, which would
     * otherwise, fed back as m_a a_n, throw the body off the wall in the
     * next step.
     *
     * The head of an articulated body moves with the loads of all its
     * parts (forces summed, torques taken about the head's centre) and
     * with their mass and inertia (assembly_inertia(), products of inertia
     * left out as the engine turns bodies about principal axes).
     */
    class RigidBodyUpdate
    {
    public:
      /**
       * @param particles the particles' densities and motions (body i of
       *   advance() is particle i), gravity and locked axes
       * @param fluid_density rho_f [kg/m^3]
       * @param starts where the particles start: needed where some are
       *   hinged, for their assemblies' inertia
       */
      RigidBodyUpdate(const ParticleParameters     &particles,
                      const double                  fluid_density,
                      const std::vector<BodyStart> &starts = {});

      /**
       * Advance @p world by @p time_step with the loads of @p states (one
       * per body of @p ids) and store each free body's new accelerations
       * there. Bodies that are not free only see the engine step.
       * @param time the time the step ends at, for messages [s]
       * @param balance if given, gets the step between the loads and the
       *   engine's step (start_step) and after it (end_step)
       * @throw std::runtime_error if a body's state is no longer finite
       */
      void
      advance(rigid::World                     &world,
              const std::vector<rigid::BodyId> &ids,
              std::vector<BodyCouplingState>   &states,
              const double                      time_step,
              const double                      time,
              EnergyBalance                    *balance = nullptr) const;

      /** The true mass of particle @p i, whose body is @p body, rho_p V
       *  [kg] (the engine's includes the added mass, or is infinite for a
       *  body that does not move). */
      double
      true_mass(const unsigned int i, const rigid::RigidBody &body) const;

      /** Its true inertia tensor in the world frame [kg m^2]. */
      Eigen::Matrix3d
      true_inertia_world(const unsigned int      i,
                         const rigid::RigidBody &body) const;

      /** Its kinetic energy with its own true mass and inertia [J] (a head
       *  of an articulated body without its parts, which count their own). */
      double
      kinetic_energy(const unsigned int i, const rigid::RigidBody &body) const;

    private:
      /** Force and torque the engine gets for particle @p i over the step
       *  (with those of the parts hinged to it). */
      void
      apply_loads(rigid::World                         &world,
                  const unsigned int                    i,
                  const std::vector<rigid::BodyId>     &ids,
                  const std::vector<BodyCouplingState> &states) const;

      /** Drop the acceleration's components into touching surfaces. */
      static void
      clip_against_contacts(const rigid::World &world,
                            const rigid::BodyId id,
                            Eigen::Vector3d    &acceleration);

      /// rho_p of each particle [kg/m^3]
      std::vector<double> particle_density;
      /// whether each particle moves freely
      std::vector<bool>   free;
      double              fluid_density;
      Eigen::Vector3d     gravity;
      std::array<bool, 3> locked_translation;
      std::array<bool, 3> locked_rotation;
      /// the parts hinged to each particle
      std::vector<std::vector<unsigned int>> parts;
      /// for each free head of an articulated body: its assembly's true
      /// mass and inertia (without added mass)
      std::vector<AssemblyInertia> assembly;
    };
  } // namespace fbm
} // namespace particulate

#endif
