// The sphere-only DEM path (SphereDem) against the general DEM path
// (contact graph + DemSolver) on a small random packing: 64 spheres of
// random radii and two materials on a lattice in a box of five walls,
// overlapping their neighbours, with random velocities and spins, one fixed
// sphere, buoyancy, a contact offset and an applied force and torque on one
// sphere. Over 50 steps (1100 substeps of sticking, sliding, opening and
// closing contacts) positions, orientations, velocities and the contact
// forces reported to the coupling must agree to 1e-11 relative: the paths
// differ only in the order in which they sum the forces on a sphere
// (rounding, which the contacts amplify). Also: a checkpoint of the fast
// path continues bit for bit on the fast path and to 1e-11 on the general
// path, and adding a box hands the state back to the general path.
#include <particulate/geometry/box.h>
#include <particulate/rigid/scene.h>

#include <random>
#include <sstream>

#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

namespace {
  const double dt = 1.e-3;

  World
  make_world(const bool fast)
  {
    SceneDescription scene;
    scene.world.contact_solver   = ContactSolverType::dem;
    scene.world.sphere_fast_path = fast;
    scene.world.contact_offset   = 2.e-5;
    scene.world.fluid_density    = 300.;
    Material &a                  = scene.materials[0];
    a.density                    = 2500.;
    a.restitution                = 0.4;
    a.static_friction            = 0.5;
    a.dynamic_friction           = 0.4;
    a.dem_stiffness              = 2.e3;
    a.dem_tangential_stiffness   = 1.e3;
    Material b                   = a;
    b.density                    = 1500.;
    b.restitution                = 0.7;
    b.static_friction = b.dynamic_friction = 0.2;
    b.dem_stiffness                        = 4.e3;
    scene.materials.push_back(b);

    // A 4 x 4 x 4 lattice of spheres of random radii that overlap their
    // neighbours and the walls by up to 2 % of the radius, with random
    // velocities and spins; one sphere of the bottom layer is fixed.
    // Spheres get the ids before the walls: contacts with both id orders.
    const double                           r = 0.005, spacing = 1.99 * r;
    std::mt19937                           rng(5);
    std::uniform_real_distribution<double> u(-1., 1.);
    for (int i = 0; i < 64; ++i)
      {
        BodyDescription sphere;
        sphere.shape.kind   = particulate::geometry::ShapeKind::sphere;
        sphere.shape.radius = r * (1. + 0.01 * u(rng));
        sphere.material     = i % 2;
        sphere.position     = Eigen::Vector3d(r + (i % 4) * spacing,
                                          r + (i / 4 % 4) * spacing,
                                          r + (i / 16) * spacing)
                          + 0.002 * r * Eigen::Vector3d(u(rng), u(rng), u(rng));
        sphere.velocity = 0.05 * Eigen::Vector3d(u(rng), u(rng), u(rng));
        sphere.angular_velocity = 20. * Eigen::Vector3d(u(rng), u(rng), u(rng));
        sphere.fixed            = i == 5;
        scene.bodies.push_back(sphere);
      }
    PouringDescription walls;
    walls.radius_min = walls.radius_max = r;
    walls.box_max
      = Eigen::Vector3d(2. * r + 3. * spacing, 2. * r + 3. * spacing, 1.);
    for (const BodyDescription &wall : walls.generate())
      scene.bodies.push_back(wall);
    return scene.build_world();
  }

  void
  step(World &w, const unsigned int n)
  {
    for (unsigned int s = 0; s < n; ++s)
      {
        w.set_external_force_and_torque(9,
                                        Eigen::Vector3d(0.01, 0., 0.005),
                                        Eigen::Vector3d(0., 1.e-5, 0.));
        w.step(dt);
      }
  }

  /** Largest differences of @p a and @p b, each relative to its scale. */
  struct Difference
  {
    /** Positions (per smallest radius), velocities (per largest speed),
     * spins (per largest spin), orientations (unit quaternions). */
    double state = 0.;
    /** Total contact force and its moment per body (per largest contact
     * force and, for the moment, times the largest distance from the
     * origin). */
    double forces = 0.;
  };

  Difference
  difference(const World &a, const World &b)
  {
    double r_min = 1., v_max = 0., w_max = 0., f_max = 0., x_max = 0.;
    for (BodyId id = 0; id < a.n_bodies(); ++id)
      {
        const RigidBody &x = a.body(id);
        if (x.shape().kind() == particulate::geometry::ShapeKind::sphere)
          r_min = std::min(r_min, x.bounding_radius());
        v_max = std::max(v_max, x.linear_velocity.norm());
        w_max = std::max(w_max, x.angular_velocity.norm());
        x_max = std::max(x_max, x.position.norm());
        for (const auto &f : a.contact_forces(id))
          f_max = std::max(f_max, f.force.norm());
      }
    Difference d;
    for (BodyId id = 0; id < a.n_bodies(); ++id)
      {
        const RigidBody &x = a.body(id), &y = b.body(id);
        d.state = std::max(
          {d.state,
           (x.position - y.position).norm() / r_min,
           (x.linear_velocity - y.linear_velocity).norm() / v_max,
           (x.angular_velocity - y.angular_velocity).norm() / w_max,
           (x.orientation.coeffs() - y.orientation.coeffs()).norm()});
        Eigen::Vector3d fx = Eigen::Vector3d::Zero(), fy = fx, mx = fx, my = fx;
        for (const auto &f : a.contact_forces(id))
          {
            fx += f.force;
            mx += f.point.cross(f.force);
          }
        for (const auto &f : b.contact_forces(id))
          {
            fy += f.force;
            my += f.point.cross(f.force);
          }
        d.forces = std::max({d.forces,
                             (fx - fy).norm() / f_max,
                             (mx - my).norm() / (f_max * x_max)});
      }
    return d;
  }
} // namespace

int
main()
{
  World fast = make_world(true), general = make_world(false);
  for (int round = 1; round <= 5; ++round)
    {
      step(fast, 10);
      step(general, 10);
      CHECK(fast.uses_sphere_fast_path() && !general.uses_sphere_fast_path(),
            "the worlds took the wrong paths");
      const Difference d = difference(fast, general);
      std::cout << "after " << 10 * round << " steps ("
                << fast.statistics().substeps << " substeps each, "
                << fast.statistics().contacts
                << " contacts): relative difference of the states " << d.state
                << ", of the contact forces " << d.forces << "\n";
      // Measured: below 6e-13 (rounding, amplified); a missed contact or a
      // wrong coefficient shows at 1e-6 or more within a few substeps.
      CHECK(d.state < 1.e-11 && d.forces < 1.e-11,
            "the sphere path departs from the general path");
      CHECK(fast.statistics().contacts == general.statistics().contacts,
            "contact counts differ");
      CHECK(std::abs(fast.max_penetration() - general.max_penetration())
              <= 1.e-11 * general.max_penetration(),
            "penetrations differ");
    }
  CHECK(fast.statistics().contacts > 150, "the packing has too few contacts");

  // Checkpoint of the fast path: continued on the fast path bit for bit,
  // on the general path to rounding.
  std::stringstream saved;
  fast.save_state(saved);
  World             again = make_world(true), other = make_world(false);
  std::stringstream copy(saved.str());
  again.load_state(saved);
  other.load_state(copy);
  for (World *w : {&fast, &general, &again, &other})
    step(*w, 10);
  CHECK(again.state_hash() == fast.state_hash(),
        "a restarted fast path does not continue bit for bit");
  const Difference restart = difference(fast, other);
  std::cout << "checkpoint of the fast path continued on the general path: "
            << restart.state << ", " << restart.forces << "\n";
  CHECK(restart.state < 1.e-11 && restart.forces < 1.e-11,
        "the general path does not continue the fast path's checkpoint");

  // A box is no sphere: the World hands the state back to the general path.
  for (World *w : {&fast, &general})
    w->add_body(std::make_shared<Box>(Eigen::Vector3d(0.005, 0.005, 0.005)),
                0,
                Eigen::Vector3d(0.02, 0.02, 0.5));
  step(fast, 10);
  step(general, 10);
  CHECK(!fast.uses_sphere_fast_path(), "a box must take the general path");
  const Difference back = difference(fast, general);
  std::cout << "after handing back to the general path: " << back.state << ", "
            << back.forces << "\n";
  CHECK(back.state < 1.e-11 && back.forces < 1.e-11,
        "the state handed back departs from the general path");
  std::cout << "OK\n";
  return 0;
}
