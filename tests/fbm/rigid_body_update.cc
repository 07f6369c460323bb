// The bodies' stage of the coupled step (fbm::RigidBodyUpdate) alone, without
// a fluid:
// 1. added mass: a free sphere under buoyancy-corrected gravity and no fluid
//    load; the explicit correction m_a a_n makes its acceleration converge to
//    the true one, a_n = a (1 - r^n) with r = m_a / (m + m_a) and
//    a = (rho_p - rho_f) / rho_p g (closed form, 1e-12 relative);
// 2. locked axes: a load along a locked axis moves nothing there;
// 3. contacts: a sphere hitting the floor at restitution 0 keeps no
//    acceleration into the wall, so the added-mass term does not throw it
//    off again: it stays on the floor (to 1 % of its radius);
// 4. a fixed particle stays where it is, and a non-finite load stops the run
//    with a message naming the time step;
// 5. gyroscopic term: a neutrally buoyant spheroid (semi-axes 2:1:1) in a
//    model fluid that turns at a constant Omega, not about a principal
//    axis, with the viscous torque -k (omega - Omega) at a ratio
//    I |Omega| / k = 0.01 (a particle Stokes number): omega lags Omega by
//    about omega x (I omega) / k. With added-mass coefficients 10 and 50
//    the engine's inertia is 11 and 51 times the body's; the correction
//    I_a alpha_n + omega_n x (I_a omega_n) must keep the lag (its RMS over
//    the second of two seconds) that of the true inertia (C = 0) to 5 % of
//    it. Without its gyroscopic part the lag grows with 1 + C.
#include <particulate/fbm/rigid_body_update.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/sphere.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>

namespace {
  using namespace particulate;

  int failures = 0;

  void
  check(const bool ok, const std::string &what)
  {
    if (!ok)
      {
        ++failures;
        std::cerr << "FAILED: " << what << std::endl;
      }
  }

  constexpr double rho_p = 1120., rho_f = 960., radius = 0.0075;

  fbm::ParticleParameters
  particles()
  {
    fbm::ParticleParameters  p;
    fbm::ParticleDescription particle;
    particle.shape   = std::make_shared<geometry::Sphere>(radius);
    particle.density = rho_p;
    p.bodies.push_back(particle);
    p.gravity                = Eigen::Vector3d(0., 0., -9.81);
    p.added_mass_coefficient = 1.;
    return p;
  }

  /** A world as the coupled loop builds it: the engine's density includes
   *  the added mass, gravity enters as a force. */
  rigid::World
  make_world(const fbm::ParticleParameters &p, const bool floor)
  {
    rigid::WorldParameters world_p;
    world_p.gravity = Eigen::Vector3d::Zero();
    rigid::World    world(world_p);
    rigid::Material material;
    material.density = rho_p + p.added_mass_coefficient * rho_f;
    world.add_material(material);
    if (floor)
      world.add_body(
        std::make_shared<geometry::HalfSpace>(Eigen::Vector3d::UnitZ(), 0.),
        0,
        Eigen::Vector3d::Zero(),
        Eigen::Quaterniond::Identity(),
        true);
    return world;
  }

  void
  added_mass_converges()
  {
    const auto          p     = particles();
    rigid::World        world = make_world(p, false);
    const rigid::BodyId id
      = world.add_body(std::make_shared<geometry::Sphere>(radius),
                       0,
                       Eigen::Vector3d(0, 0, 1));
    std::vector<fbm::BodyCouplingState> states(1);
    const fbm::RigidBodyUpdate          update(p, rho_f);
    const double                        r = rho_f / (rho_p + rho_f);
    const double a = (rho_p - rho_f) / rho_p * 9.81, dt = 1e-3;
    double       worst = 0.;
    for (int n = 1; n <= 40; ++n)
      {
        update.advance(world, {id}, states, dt, n * dt);
        const double expected = -a * (1. - std::pow(r, n));
        worst                 = std::max(worst,
                         std::abs(states[0].acceleration[2] - expected)
                           / std::abs(expected));
      }
    std::printf("added mass: worst relative deviation from a (1 - r^n) "
                "over 40 steps %.2e (r = %.4f)\n",
                worst,
                r);
    check(worst < 1e-12, "acceleration follows a (1 - r^n)");
    check(std::abs(update.true_mass(0, world.body(id))
                   - rho_p * 4. / 3. * M_PI * std::pow(radius, 3))
            < 1e-15,
          "true mass");
  }

  void
  locked_axes_stay()
  {
    auto p                    = particles();
    p.locked_translation[0]   = true;
    rigid::World        world = make_world(p, false);
    const rigid::BodyId id
      = world.add_body(std::make_shared<geometry::Sphere>(radius),
                       0,
                       Eigen::Vector3d(0.1, 0, 1));
    std::vector<fbm::BodyCouplingState> states(1);
    states[0].fluid_load.force = Eigen::Vector3d(1e-3, 0., 0.);
    const fbm::RigidBodyUpdate update(p, rho_f);
    for (int n = 1; n <= 10; ++n)
      update.advance(world, {id}, states, 1e-3, n * 1e-3);
    const rigid::RigidBody &b = world.body(id);
    check(b.position[0] == 0.1 && b.linear_velocity[0] == 0.,
          "no motion along a locked axis");
    check(b.linear_velocity[2] < 0., "free fall along the free axis");
  }

  void
  contact_stops_added_mass()
  {
    auto p                    = particles();
    p.restitution             = 0.;
    rigid::World        world = make_world(p, true);
    const rigid::BodyId id
      = world.add_body(std::make_shared<geometry::Sphere>(radius),
                       0,
                       Eigen::Vector3d(0., 0., radius + 0.002));
    world.body(id).linear_velocity = Eigen::Vector3d(0., 0., -0.1);
    std::vector<fbm::BodyCouplingState> states(1);
    const fbm::RigidBodyUpdate          update(p, rho_f);
    double highest_after_landing = -1., largest_into_wall = -1e300;
    bool   landed = false;
    for (int n = 1; n <= 200; ++n)
      {
        update.advance(world, {id}, states, 1e-3, n * 1e-3);
        const double z = world.body(id).position[2];
        landed |= z <= 1.01 * radius;
        if (landed)
          highest_after_landing = std::max(highest_after_landing, z);
        if (!world.contact_forces(id).empty())
          largest_into_wall
            = std::max(largest_into_wall, states[0].acceleration[2]);
      }
    std::printf("contact: highest centre after landing %.6f m (radius "
                "%.4f m), largest upward acceleration kept at a contact "
                "%.3g m/s^2\n",
                highest_after_landing,
                radius,
                largest_into_wall);
    check(landed, "the sphere reaches the floor");
    check(highest_after_landing <= 1.01 * radius,
          "the sphere is not thrown off the floor");
    check(largest_into_wall <= 1e-12, "no acceleration into the wall is kept");
  }

  void
  fixed_and_diverging()
  {
    auto p             = particles();
    p.bodies[0].motion = fbm::ParticleMotion::fixed;
    {
      rigid::World        world = make_world(p, false);
      const rigid::BodyId id
        = world.add_body(std::make_shared<geometry::Sphere>(radius),
                         0,
                         Eigen::Vector3d(0, 0, 1),
                         Eigen::Quaterniond::Identity(),
                         true);
      std::vector<fbm::BodyCouplingState> states(1);
      states[0].fluid_load.force = Eigen::Vector3d(1., 1., 1.);
      fbm::RigidBodyUpdate(p, rho_f).advance(world, {id}, states, 1e-3, 1e-3);
      check(world.body(id).position == Eigen::Vector3d(0, 0, 1)
              && states[0].acceleration.isZero(),
            "a fixed particle stays");
    }
    p.bodies[0].motion        = fbm::ParticleMotion::free;
    rigid::World        world = make_world(p, false);
    const rigid::BodyId id
      = world.add_body(std::make_shared<geometry::Sphere>(radius),
                       0,
                       Eigen::Vector3d(0, 0, 1));
    std::vector<fbm::BodyCouplingState> states(1);
    states[0].fluid_load.force[1] = std::numeric_limits<double>::quiet_NaN();
    bool stopped                  = false;
    try
      {
        fbm::RigidBodyUpdate(p, rho_f).advance(world, {id}, states, 1e-3, 1e-3);
      }
    catch (const std::runtime_error &e)
      {
        std::cout << "expected error: " << e.what() << std::endl;
        stopped = std::string(e.what()).find("Time step") != std::string::npos;
      }
    check(stopped, "a non-finite state stops the run and names the time step");
  }
  /** The RMS of |omega - Omega| over the second of two seconds (after the
   *  start) of a spheroid in a fluid turning at Omega, with added-mass
   *  coefficient @p C. */
  double
  largest_lag(const double C)
  {
    const double             rho = 1000.;
    fbm::ParticleParameters  p;
    fbm::ParticleDescription particle;
    particle.shape = std::make_shared<geometry::Ellipsoid>(
      Eigen::Vector3d(0.02, 0.01, 0.01));
    particle.density = rho;
    p.bodies.push_back(particle);
    p.gravity                = Eigen::Vector3d::Zero();
    p.added_mass_coefficient = C;
    rigid::WorldParameters world_p;
    world_p.gravity = Eigen::Vector3d::Zero();
    rigid::World    world(world_p);
    rigid::Material material;
    material.density = rho * (1. + C);
    world.add_material(material);
    const Eigen::Vector3d omega_fluid
      = Eigen::Vector3d(1., 0.5, 2.).normalized();
    const rigid::BodyId id
      = world.add_body(particle.shape, 0, Eigen::Vector3d::Zero());
    world.body(id).angular_velocity = omega_fluid;
    const fbm::RigidBodyUpdate update(p, rho);
    const double k = 100. * update.true_inertia_world(0, world.body(id)).norm();
    std::vector<fbm::BodyCouplingState> states(1);
    const double                        dt  = 1e-4;
    double                              sum = 0.;
    for (int n = 1; n <= 20000; ++n)
      {
        states[0].fluid_load.torque
          = -k * (world.body(id).angular_velocity - omega_fluid);
        update.advance(world, {id}, states, dt, n * dt);
        if (n > 10000)
          sum += (world.body(id).angular_velocity - omega_fluid).squaredNorm();
      }
    return std::sqrt(sum / 10000.);
  }

  void
  gyroscopic_term_of_the_true_inertia()
  {
    const double lag_true = largest_lag(0.);
    for (const double C : {10., 50.})
      {
        const double lag = largest_lag(C);
        std::printf(
          "gyroscopic: RMS of |omega - Omega| over t = 1..2 s %.4e rad/s with "
          "C = %g, %.4e with the true inertia\n",
          lag,
          C,
          lag_true);
        check(std::abs(lag / lag_true - 1.) < 0.05,
              "the added mass keeps the true inertia's gyroscopic lag");
      }
  }
} // namespace

int
main()
{
  added_mass_converges();
  locked_axes_stay();
  contact_stops_added_mass();
  fixed_and_diverging();
  gyroscopic_term_of_the_true_inertia();
  if (failures > 0)
    {
      std::cerr << failures << " check(s) failed" << std::endl;
      return 1;
    }
  std::cout << "OK" << std::endl;
  return 0;
}
