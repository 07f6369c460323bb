#include <particulate/fbm/particle_world.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/tube.h>

#include <map>
#include <stdexcept>

namespace particulate {
  namespace fbm {
    namespace {
      /** The mantle of a column @p domain as a fixed tube, its bore the
       *  column, its ends a radius beyond the column's. */
      void
      add_mantle(rigid::World      &world,
                 const DomainBox   &domain,
                 const unsigned int material)
      {
        const double R = domain.column_radius;
        world.add_body(std::make_shared<geometry::Tube>(
                         R,
                         R,
                         0.5 * (domain.upper[2] - domain.lower[2]) + R),
                       material,
                       0.5 * (domain.lower + domain.upper),
                       Eigen::Quaterniond::Identity(),
                       true);
      }

      /** The walls of @p domain that the case marks, as fixed half-spaces
       *  {n.p <= offset} with n pointing into the domain, and a column's
       *  mantle. */
      void
      add_walls(rigid::World      &world,
                const DomainBox   &domain,
                const unsigned int material)
      {
        if (domain.is_column() && domain.walls[0])
          add_mantle(world, domain, material);
        for (unsigned int d = domain.is_column() ? 2 : 0; d < domain.dim; ++d)
          {
            Eigen::Vector3d n = Eigen::Vector3d::Zero();
            n[d]              = 1.;
            if (domain.walls[2 * d])
              world.add_body(std::make_shared<geometry::HalfSpace>(
                               n,
                               domain.wall_position(2 * d)),
                             material,
                             Eigen::Vector3d::Zero(),
                             Eigen::Quaterniond::Identity(),
                             true);
            if (domain.walls[2 * d + 1])
              world.add_body(std::make_shared<geometry::HalfSpace>(
                               -n,
                               -domain.wall_position(2 * d + 1)),
                             material,
                             Eigen::Vector3d::Zero(),
                             Eigen::Quaterniond::Identity(),
                             true);
          }
      }

      /** Each articulated body's head carries its parts' mass and inertia;
       *  its parts and it share a collision group, as they overlap at the
       *  hinges. */
      void
      join_assemblies(rigid::World                           &world,
                      const std::vector<rigid::BodyId>       &ids,
                      const std::vector<ParticleDescription> &particles,
                      const std::vector<BodyStart>           &starts,
                      const ParticleWorldFrame               &frame)
      {
        const auto   parts = hinged_parts(particles);
        unsigned int group = 0;
        for (unsigned int i = 0; i < particles.size(); ++i)
          {
            if (parts[i].empty())
              continue;
            world.set_collision_group(ids[i], ++group);
            for (const unsigned int j : parts[i])
              world.set_collision_group(ids[j], group);
            if (particles[i].motion != ParticleMotion::free)
              continue;
            const AssemblyInertia a = assembly_inertia(particles,
                                                       starts,
                                                       i,
                                                       parts[i],
                                                       frame.added_density);
            world.body(ids[i]).set_mass_properties(a.mass,
                                                   a.inertia.diagonal());
          }
      }
    } // namespace



    ParticleWorld
    build_particle_world(const ParticleParameters     &particles,
                         const std::vector<BodyStart> &starts,
                         const ParticleWorldFrame     &frame)
    {
      if (starts.size() != particles.n_particles())
        throw std::logic_error("build_particle_world: one start per particle");
      rigid::WorldParameters world_p;
      world_p.gravity        = frame.gravity;
      world_p.contact_solver = particles.contact_solver;
      world_p.substeps       = particles.substeps;
      world_p.contact_offset = frame.contact_offset;
      ParticleWorld result;
      result.world        = std::make_unique<rigid::World>(world_p);
      rigid::World &world = *result.world;

      rigid::Material material;
      material.restitution     = particles.restitution;
      material.static_friction = material.dynamic_friction = particles.friction;
      std::map<double, unsigned int> material_of_density;
      const auto material_for = [&](const double engine_density) {
        const auto it = material_of_density.find(engine_density);
        if (it != material_of_density.end())
          return it->second;
        rigid::Material m     = material;
        m.name                = "particle";
        m.density             = engine_density;
        const unsigned int id = world.add_material(m);
        material_of_density.emplace(engine_density, id);
        return id;
      };

      for (unsigned int i = 0; i < particles.n_particles(); ++i)
        {
          const ParticleDescription &p     = particles.bodies[i];
          const BodyStart           &start = starts[i];
          const bool                 free  = p.motion == ParticleMotion::free;
          result.ids.push_back(
            world.add_body(p.shape,
                           material_for(p.density + frame.added_density),
                           start.position,
                           start.orientation,
                           !free));
          rigid::RigidBody &b = world.body(result.ids.back());
          // locked inside the engine, so that contacts cannot spend their
          // impulse on a rotation that is not allowed
          b.lock_rotation(particles.locked_rotation);
          if (p.motion != ParticleMotion::fixed)
            {
              b.linear_velocity  = start.velocity;
              b.angular_velocity = start.angular_velocity;
            }
        }
      join_assemblies(world, result.ids, particles.bodies, starts, frame);
      // walls are immovable: their density does not enter
      rigid::Material wall_material = material;
      wall_material.name            = "wall";
      add_walls(world, frame.domain, world.add_material(wall_material));
      return result;
    }



    void
    restore_locked_axes(rigid::RigidBody          &b,
                        const Eigen::Vector3d     &old_position,
                        const Eigen::Quaterniond  &old_orientation,
                        const std::array<bool, 3> &locked_translation,
                        const std::array<bool, 3> &locked_rotation)
    {
      for (unsigned int d = 0; d < 3; ++d)
        {
          if (locked_translation[d])
            {
              b.linear_velocity[d] = 0.;
              b.position[d]        = old_position[d];
            }
          if (locked_rotation[d])
            b.angular_velocity[d] = 0.;
        }
      if (locked_rotation[0] && locked_rotation[1] && locked_rotation[2])
        b.orientation = old_orientation;
    }



    std::vector<rigid::BodyId>
    free_body_ids(const ParticleParameters         &particles,
                  const std::vector<rigid::BodyId> &ids)
    {
      std::vector<rigid::BodyId> free;
      for (unsigned int i = 0; i < ids.size(); ++i)
        if (particles.bodies[i].motion == ParticleMotion::free)
          free.push_back(ids[i]);
      return free;
    }



    std::vector<ParticleMotion>
    particle_motions(const ParticleParameters &particles)
    {
      std::vector<ParticleMotion> motions;
      for (const ParticleDescription &p : particles.bodies)
        motions.push_back(p.motion);
      return motions;
    }
  } // namespace fbm
} // namespace particulate
