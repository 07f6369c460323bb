#include <particulate/fbm/particle_world.h>
#include <particulate/fbm/rigid_body_update.h>

#include <stdexcept>
#include <string>

namespace particulate {
  namespace fbm {
    RigidBodyUpdate::RigidBodyUpdate(const ParticleParameters &particles,
                                     const double              fluid_density,
                                     const std::vector<BodyStart> &starts)
      : fluid_density(fluid_density)
      , gravity(particles.gravity)
      , locked_translation(particles.locked_translation)
      , locked_rotation(particles.locked_rotation)
      , parts(hinged_parts(particles.bodies))
      , assembly(particles.n_particles())
    {
      for (const ParticleDescription &p : particles.bodies)
        {
          particle_density.push_back(p.density);
          free.push_back(p.motion == ParticleMotion::free);
        }
      for (unsigned int i = 0; i < particles.n_particles(); ++i)
        if (free[i] && !parts[i].empty())
          {
            if (starts.size() != particles.n_particles())
              throw std::logic_error(
                "RigidBodyUpdate: an articulated body needs the starts");
            assembly[i]
              = assembly_inertia(particles.bodies, starts, i, parts[i], 0.);
          }
    }



    double
    RigidBodyUpdate::true_mass(const unsigned int      i,
                               const rigid::RigidBody &body) const
    {
      if (assembly[i].mass > 0.)
        return assembly[i].mass;
      return particle_density[i] * body.volume();
    }



    Eigen::Matrix3d
    RigidBodyUpdate::true_inertia_world(const unsigned int      i,
                                        const rigid::RigidBody &body) const
    {
      // from the shape, not the engine's body: a fixed or prescribed
      // particle is an immovable body of infinite inertia in the engine
      const Eigen::Matrix3d R = body.rotation();
      const Eigen::Matrix3d I
        = assembly[i].mass > 0. ?
            Eigen::Matrix3d(assembly[i].inertia.diagonal().asDiagonal()) :
            Eigen::Matrix3d(particle_density[i] * body.shape().unit_inertia());
      return R * I * R.transpose();
    }



    double
    RigidBodyUpdate::kinetic_energy(const unsigned int      i,
                                    const rigid::RigidBody &body) const
    {
      // its own mass and inertia, also for the head of an articulated body:
      // each part counts its own energy with the velocity it has
      const Eigen::Matrix3d R = body.rotation();
      const Eigen::Matrix3d I
        = R * (particle_density[i] * body.shape().unit_inertia())
          * R.transpose();
      return 0.5 * particle_density[i] * body.volume()
               * body.linear_velocity.squaredNorm()
             + 0.5 * body.angular_velocity.dot(I * body.angular_velocity);
    }



    void
    RigidBodyUpdate::apply_loads(
      rigid::World                         &world,
      const unsigned int                    i,
      const std::vector<rigid::BodyId>     &ids,
      const std::vector<BodyCouplingState> &states) const
    {
      const rigid::RigidBody  &b     = world.body(ids[i]);
      const BodyCouplingState &state = states[i];
      const double             m_a   = b.mass() - true_mass(i, b);
      Eigen::Vector3d          force
        = state.fluid_load.force
          + (particle_density[i] - fluid_density) * b.volume() * gravity
          + m_a * state.acceleration;
      // the engine turns the body with I + I_a, gyroscopic term included:
      // I_a alpha_n + omega x (I_a omega) leaves I's own dynamics
      const Eigen::Matrix3d  I_a = b.inertia_world() - true_inertia_world(i, b);
      const Eigen::Vector3d &omega  = b.angular_velocity;
      Eigen::Vector3d        torque = state.fluid_load.torque
                               + I_a * state.angular_acceleration
                               + omega.cross(I_a * omega);
      for (const unsigned int j : parts[i])
        {
          const rigid::RigidBody &part = world.body(ids[j]);
          const Eigen::Vector3d   weight
            = (particle_density[j] - fluid_density) * part.volume() * gravity;
          const HydrodynamicLoad &load = states[j].fluid_load;
          force += load.force + weight;
          torque
            += load.torque
               + (states[j].load_centre - state.load_centre).cross(load.force)
               + (part.position - b.position).cross(weight);
        }
      for (unsigned int d = 0; d < 3; ++d)
        {
          if (locked_translation[d])
            force[d] = 0.;
          if (locked_rotation[d])
            torque[d] = 0.;
        }
      world.set_external_force_and_torque(ids[i], force, torque);
    }



    void
    RigidBodyUpdate::clip_against_contacts(const rigid::World &world,
                                           const rigid::BodyId id,
                                           Eigen::Vector3d    &acceleration)
    {
      for (const auto &f : world.contact_forces(id))
        if (f.force.norm() > 0.)
          {
            const Eigen::Vector3d n = f.force.normalized();
            const double          a = acceleration.dot(n);
            if (a > 0.)
              acceleration -= a * n;
          }
    }



    void
    RigidBodyUpdate::advance(rigid::World                     &world,
                             const std::vector<rigid::BodyId> &ids,
                             std::vector<BodyCouplingState>   &states,
                             const double                      time_step,
                             const double                      time,
                             EnergyBalance                    *balance) const
    {
      const unsigned int           n = ids.size();
      std::vector<Eigen::Vector3d> old_velocity(n), old_angular(n),
        old_position(n);
      std::vector<Eigen::Quaterniond> old_orientation(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const rigid::RigidBody &b = world.body(ids[i]);
          old_velocity[i]           = b.linear_velocity;
          old_angular[i]            = b.angular_velocity;
          old_position[i]           = b.position;
          old_orientation[i]        = b.orientation;
          if (free[i])
            apply_loads(world, i, ids, states);
        }
      if (balance)
        balance->start_step(world);
      world.step(time_step);
      for (unsigned int i = 0; i < n; ++i)
        if (free[i])
          restore_locked_axes(world.body(ids[i]),
                              old_position[i],
                              old_orientation[i],
                              locked_translation,
                              locked_rotation);
      if (balance)
        balance->end_step(world);
      for (unsigned int i = 0; i < n; ++i)
        {
          if (!free[i])
            continue;
          rigid::RigidBody &b = world.body(ids[i]);
          if (!b.linear_velocity.allFinite() || !b.position.allFinite())
            throw std::runtime_error(
              "Particle " + std::to_string(i)
              + " has a non-finite velocity at t = " + std::to_string(time)
              + " s: the coupling diverged. Reduce 'Time step' in "
                "subsection 'Time' or raise 'Added mass coefficient' in "
                "subsection 'Particles'.");
          states[i].acceleration
            = (b.linear_velocity - old_velocity[i]) / time_step;
          states[i].angular_acceleration
            = (b.angular_velocity - old_angular[i]) / time_step;
          clip_against_contacts(world, ids[i], states[i].acceleration);
        }
    }
  } // namespace fbm
} // namespace particulate
