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
// 6. viscous stiffness: a free sphere (C = 50) in a model fluid whose load is
//    a drag -k (U - U*) on the velocity U = U_n + dt a_n the loop imposes
//    (extrapolated), towards a force-free velocity U*. The error U - U*
//    follows (m + m_a) z^2 + (2 k dt - m - 2 m_a) z + (m_a - k dt) = 0
//    (doc/developer/fbm.md, "Viscous stiffness"): at k dt = 0.95 and 1.05
//    times the bound (2 m + 4 m_a) / 3 it shrinks and grows by the largest
//    root's modulus per step (measured over steps 20 to 60, to 1e-3); at
//    k dt = 0.01 m_a it rings with the roots' period 2 pi / arg z (zero
//    crossings over ten periods, to 1 %), which 2 pi sqrt(m_a dt / k)
//    approximates to 3 % (1.7 %).
#include <particulate/fbm/rigid_body_update.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/sphere.h>

#include <array>
#include <cmath>
#include <complex>
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
  /** The error U_n - U* of a free sphere (added-mass coefficient 50) under
   *  the drag -k (U_n + dt a_n - U*), from rest, over @p steps steps. */
  std::vector<double>
  drag_response(const double       k_dt_over_bound,
                const double       k_dt_over_m_a,
                const double       dt,
                const unsigned int steps,
                double            &m,
                double            &m_a)
  {
    auto p                    = particles();
    p.gravity                 = Eigen::Vector3d::Zero();
    p.added_mass_coefficient  = 50.;
    rigid::World        world = make_world(p, false);
    const rigid::BodyId id
      = world.add_body(std::make_shared<geometry::Sphere>(radius),
                       0,
                       Eigen::Vector3d(0, 0, 1));
    const fbm::RigidBodyUpdate update(p, rho_f);
    m   = update.true_mass(0, world.body(id));
    m_a = world.body(id).mass() - m;
    const double k
      = (k_dt_over_bound > 0. ? k_dt_over_bound * (2. * m + 4. * m_a) / 3. :
                                k_dt_over_m_a * m_a)
        / dt;
    const double                        u_star = 0.01;
    std::vector<fbm::BodyCouplingState> states(1);
    std::vector<double>                 error;
    for (unsigned int n = 0; n < steps; ++n)
      {
        const double imposed
          = world.body(id).linear_velocity[0] + dt * states[0].acceleration[0];
        states[0].fluid_load.force
          = Eigen::Vector3d(-k * (imposed - u_star), 0, 0);
        update.advance(world, {id}, states, dt, (n + 1) * dt);
        error.push_back(world.body(id).linear_velocity[0] - u_star);
      }
    return error;
  }

  /** The roots of the error's characteristic polynomial. */
  std::array<std::complex<double>, 2>
  stiffness_roots(const double m, const double m_a, const double k_dt)
  {
    const std::complex<double> a = m + m_a, b = 2. * k_dt - m - 2. * m_a,
                               c    = m_a - k_dt;
    const std::complex<double> root = std::sqrt(b * b - 4. * a * c);
    return {{(-b + root) / (2. * a), (-b - root) / (2. * a)}};
  }

  void
  viscous_stiffness()
  {
    const double dt = 1e-3;
    double       m = 0., m_a = 0.;
    for (const double ratio : {0.95, 1.05})
      {
        const auto   e        = drag_response(ratio, 0., dt, 60, m, m_a);
        const double k_dt     = ratio * (2. * m + 4. * m_a) / 3.;
        const auto   z        = stiffness_roots(m, m_a, k_dt);
        const double expected = std::max(std::abs(z[0]), std::abs(z[1]));
        const double measured
          = std::pow(std::abs(e[59]) / std::abs(e[19]), 1. / 40.);
        std::printf("viscous stiffness: k dt = %.2f (2 m + 4 m_a) / 3: error "
                    "x %.6f per step, largest root %.6f\n",
                    ratio,
                    measured,
                    expected);
        check(std::abs(measured - expected) < 1e-3,
              "the error changes by the largest root per step");
        check((ratio < 1.) == (measured < 1.),
              "stable below the bound, unstable above");
      }
    const auto                e = drag_response(0., 0.01, dt, 20000, m, m_a);
    std::vector<unsigned int> crossings;
    for (unsigned int n = 1; n < e.size() && crossings.size() < 21; ++n)
      if ((e[n - 1] < 0.) != (e[n] < 0.))
        crossings.push_back(n);
    const double period_steps = crossings.size() == 21 ?
                                  (crossings[20] - crossings[0]) / 10. :
                                  std::numeric_limits<double>::quiet_NaN();
    const auto   z            = stiffness_roots(m, m_a, 0.01 * m_a);
    const double exact        = 2. * M_PI / std::abs(std::arg(z[0]));
    const double estimate     = 2. * M_PI * std::sqrt(1. / 0.01);
    std::printf("viscous stiffness: rings with a period of %.2f steps; the "
                "roots give %.2f, 2 pi sqrt(m_a dt / k) %.2f\n",
                period_steps,
                exact,
                estimate);
    check(std::abs(period_steps - exact) < 0.01 * exact,
          "the ringing period is that of the roots");
    check(std::abs(estimate - exact) < 0.03 * exact,
          "2 pi sqrt(m_a dt / k) approximates it");
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
  viscous_stiffness();
  if (failures > 0)
    {
      std::cerr << failures << " check(s) failed" << std::endl;
      return 1;
    }
  std::cout << "OK" << std::endl;
  return 0;
}
