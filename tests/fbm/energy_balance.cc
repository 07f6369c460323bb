// The energy balance of the bodies (EnergyBalance) in the rigid engine
// without gravity, loads given as external force and torque:
// - a spheroid (semi-axes 0.3, 0.1, 0.05 m) pushed by a constant force and
//   torque for 200 steps, tumbling about no principal axis: the kinetic
//   energy it gains is at most the work of the loads (the integrator
//   loses some; the unexplained gain is at most 1e-3 of the energy
//   handled), and no warning; the same for a sphere pushed without
//   rotation, whose symplectic Euler step loses m |dv|^2 / 2 a step;
// - a sphere dropped on the floor with restitution 1 and with 0 by the
//   sequential impulses: the contact gives back at most what it took (the
//   gain stays below 1e-3 of the energy handled);
// - a sphere at rest, placed 0.05 m deep into the floor: the contact
//   pushes it out and it leaves with kinetic energy that no load paid
//   for; the warning names the gain.

#include <particulate/fbm/energy_balance.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/sphere.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace particulate;

namespace {
  int failures = 0;

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "ok: " : "FAILED: ") << what << std::endl;
    if (!ok)
      ++failures;
  }

  struct Scene
  {
    rigid::World  world;
    rigid::BodyId id = 0;

    Scene(std::shared_ptr<const geometry::Shape> shape,
          const Eigen::Vector3d                 &position,
          const double                           restitution,
          const bool                             with_floor)
      : world(parameters())
    {
      rigid::Material material;
      material.restitution = restitution;
      const unsigned int m = world.add_material(material);
      id                   = world.add_body(shape,
                          m,
                          position,
                          Eigen::Quaterniond::Identity(),
                          false);
      if (with_floor)
        world.add_body(
          std::make_shared<geometry::HalfSpace>(Eigen::Vector3d::UnitZ(), 0.),
          m,
          Eigen::Vector3d::Zero(),
          Eigen::Quaterniond::Identity(),
          true);
    }

    static rigid::WorldParameters
    parameters()
    {
      rigid::WorldParameters p;
      p.gravity = Eigen::Vector3d::Zero();
      return p;
    }

    /** Runs @p n steps of @p dt with the load @p force, @p torque and
     *  returns the first warning (or ""). */
    std::string
    run(fbm::EnergyBalance    &balance,
        const unsigned int     n,
        const double           dt,
        const Eigen::Vector3d &force,
        const Eigen::Vector3d &torque)
    {
      std::string first;
      for (unsigned int s = 0; s < n; ++s)
        {
          world.set_external_force_and_torque(id, force, torque);
          balance.start_step(world);
          world.step(dt);
          balance.end_step(world);
          const std::string w = balance.warning(world.time());
          if (first.empty())
            first = w;
        }
      return first;
    }
  };

  double
  relative_gain(const fbm::EnergyBalance &balance)
  {
    return balance.unexplained_gain() / balance.energy_handled();
  }
} // namespace



int
main()
{
  {
    Scene s(std::make_shared<geometry::Ellipsoid>(
              Eigen::Vector3d(0.3, 0.1, 0.05)),
            Eigen::Vector3d(0., 0., 1.),
            0.,
            false);
    s.world.body(s.id).angular_velocity = Eigen::Vector3d(1., 2., 3.);
    fbm::EnergyBalance balance({s.id});
    const std::string  warning = s.run(balance,
                                      200,
                                      1e-3,
                                      Eigen::Vector3d(1., 0., 2.),
                                      Eigen::Vector3d(0.1, -0.2, 0.05));
    std::cout << "tumbling spheroid: gain " << balance.unexplained_gain()
              << " J of " << balance.energy_handled() << " J" << std::endl;
    check(relative_gain(balance) < 1e-3,
          "a pushed, tumbling spheroid: kinetic energy <= work");
    check(warning.empty(), "no warning for it");
  }
  {
    Scene                 s(std::make_shared<geometry::Sphere>(0.1),
            Eigen::Vector3d(0., 0., 1.),
            0.,
            false);
    fbm::EnergyBalance    balance({s.id});
    const double          dt = 1e-3;
    const Eigen::Vector3d force(3., -1., 2.);
    s.run(balance, 100, dt, force, Eigen::Vector3d::Zero());
    // the symplectic Euler step loses m |F dt / m|^2 / 2 in each step
    const double m    = s.world.body(s.id).mass();
    const double loss = 100 * 0.5 * (force * dt).squaredNorm() / m;
    std::cout << "pushed sphere: gain " << balance.unexplained_gain()
              << " J, the integrator's loss " << loss << " J" << std::endl;
    check(std::abs(balance.unexplained_gain() + loss) < 1e-12,
          "a pushed sphere: kinetic energy = work - the integrator's loss");
  }
  for (const double restitution : {1., 0.})
    {
      Scene s(std::make_shared<geometry::Sphere>(0.1),
              Eigen::Vector3d(0., 0., 0.2),
              restitution,
              true);
      s.world.body(s.id).linear_velocity = Eigen::Vector3d(0., 0., -1.);
      fbm::EnergyBalance balance({s.id});
      const std::string  warning = s.run(balance,
                                        400,
                                        1e-3,
                                        Eigen::Vector3d::Zero(),
                                        Eigen::Vector3d::Zero());
      std::cout << "sphere on the floor, e = " << restitution
                << ": speed after " << s.world.body(s.id).linear_velocity[2]
                << " m/s, gain " << balance.unexplained_gain() << " J of "
                << balance.energy_handled() << " J" << std::endl;
      check(relative_gain(balance) < 1e-3,
            "a bounce gives back at most what it took, e = "
              + std::to_string(restitution));
      check(warning.empty(), "no warning for the bounce");
    }
  {
    Scene              s(std::make_shared<geometry::Sphere>(0.1),
            Eigen::Vector3d(0., 0., 0.05),
            0.,
            true);
    fbm::EnergyBalance balance({s.id});
    const std::string  warning = s.run(balance,
                                      100,
                                      1e-3,
                                      Eigen::Vector3d::Zero(),
                                      Eigen::Vector3d::Zero());
    std::cout << "sphere pushed out of the floor: speed "
              << s.world.body(s.id).linear_velocity.norm() << " m/s, gain "
              << balance.unexplained_gain() << " J; " << warning << std::endl;
    check(warning.find("gained") != std::string::npos,
          "a sphere thrown out of a deep overlap is reported");
  }
  std::cout << (failures == 0 ? "OK" : "FAILED") << std::endl;
  return failures == 0 ? 0 : 1;
}
