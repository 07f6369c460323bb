// DEM cost per particle-step (issue 3; LAMMPS reports 48.6 ns for its
// granular chute on one core). A dense bed of n spheres (default 1e5) on a
// simple cubic lattice with 0.5 % overlap (6 contacts per sphere, like a
// packed bed), radius 1 mm, in a box of five walls, under gravity, with
// small random velocities, stepped with the DEM solver for a fixed number
// of substeps. Prints ns of thread CPU time per particle-substep, split
// over the stages. By default the World takes its sphere-only DEM path
// (SphereDem); `general` forces the general path (contact graph, DemSolver)
// for comparison; `no-forces` turns off the recording of contact forces
// (WorldParameters::record_contact_forces); `read` reads every body after
// every step (as output or a coupling would), which makes the sphere path
// copy its state into the RigidBody objects each step.
// Usage: bench_rigid_dem [n] [steps] [general] [no-forces] [read]
#include <particulate/rigid/scene.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <string>

using namespace particulate::rigid;

int
main(int argc, char **argv)
{
  const unsigned int n       = argc > 1 ? std::atoi(argv[1]) : 100000;
  const unsigned int steps   = argc > 2 ? std::atoi(argv[2]) : 20;
  bool               general = false, record = true, read = false;
  for (int a = 3; a < argc; ++a)
    {
      const std::string flag = argv[a];
      general |= flag == "general";
      record &= flag != "no-forces";
      read |= flag == "read";
    }
  SceneDescription scene;
  scene.world.contact_solver        = ContactSolverType::dem;
  scene.world.substeps              = 1;
  scene.world.dem_steps_per_contact = 20.;
  scene.world.sphere_fast_path      = !general;
  scene.world.record_contact_forces = record;
  auto &m                           = scene.materials[0];
  m.density                         = 2500.;
  m.restitution                     = 0.5;
  m.static_friction = m.dynamic_friction = 0.5;
  m.dem_stiffness                        = 2.e3;
  m.dem_tangential_stiffness             = 1.e3;
  const double r                         = 1.e-3;
  const int    side                      = std::ceil(std::cbrt(double(n)));
  const double a                         = 2. * r * 0.995;
  World        w                         = [&] {
    World world(scene.world);
    world.add_material(m);
    auto sphere
      = ShapeDescription{particulate::geometry::ShapeKind::sphere, r}.create();
    const Eigen::Vector3d lo(0., 0., 0.),
      hi(side * a + 0.1 * r, side * a + 0.1 * r, 1.);
    PouringDescription walls;
    walls.n_spheres  = 0;
    walls.box_min    = lo;
    walls.box_max    = hi;
    walls.radius_min = walls.radius_max = r;
    for (const auto &b : walls.generate())
      world.add_body(b.shape.create(), 0, b.position, b.orientation, true);
    std::mt19937                           rng(3);
    std::uniform_real_distribution<double> u(-1., 1.);
    for (unsigned int i = 0; i < n; ++i)
      {
        const int ix = i % side, iy = (i / side) % side, iz = i / (side * side);
        const BodyId id
          = world.add_body(sphere,
                           0,
                           Eigen::Vector3d(r + ix * a, r + iy * a, r + iz * a));
        world.body(id).linear_velocity
          = 1.e-3 * Eigen::Vector3d(u(rng), u(rng), u(rng));
      }
    return world;
  }();
  // Time step: the DEM picks its substeps from the contact time; use one
  // step of exactly one substep to measure the per-substep cost.
  const double m_s = 2500. * 4. / 3. * M_PI * r * r * r;
  const double tc
    = M_PI * std::sqrt(0.4 * m_s / 2.e3 * 2.); // pair stiffness k/2 (series)
  const double dt = tc / 20.;
  w.step(dt); // warm-up: builds the grid and the contact graph
  double        tb = 0., tn = 0., ts = 0., ti = 0., sum = 0.;
  unsigned long substeps = 0;
  auto          cpu      = [] {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1.e-9 * t.tv_nsec;
  };
  const double t0 = cpu();
  for (unsigned int s = 0; s < steps; ++s)
    {
      w.step(dt);
      if (read)
        {
          const auto t_read = std::chrono::steady_clock::now();
          for (const RigidBody &b : w.bodies())
            sum += b.position[2];
          ti += std::chrono::duration<double>(std::chrono::steady_clock::now()
                                              - t_read)
                  .count();
        }
      const auto &st = w.statistics();
      tb += st.time_broad;
      tn += st.time_narrow;
      ts += st.time_solve;
      ti += st.time_integrate;
      substeps += st.substeps;
    }
  const double total = cpu() - t0;
  const double per   = 1.e9 / (double(n) * substeps);
  // The stage timers measure wall time; scale them to the CPU total so the
  // columns add up on a loaded machine.
  const double wall  = tb + tn + ts + ti;
  const double scale = wall > 0. ? total / wall : 1.;
  tb *= scale;
  tn *= scale;
  ts *= scale;
  ti *= scale;
  std::printf(
    "| path | spheres | substeps | contacts | total ns/particle-step | broad | narrow+graph | "
    "solve | integrate |\n|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| %s%s%s | %u | %lu | %u | %.0f | %.0f | %.0f | %.0f | %.0f |\n",
              w.uses_sphere_fast_path() ? "spheres only" : "general",
              record ? "" : ", no forces",
              read ? ", bodies read" : "",
              n,
              substeps,
              w.statistics().contacts,
              total * per,
              tb * per,
              tn * per,
              ts * per,
              ti * per);
  std::printf("max penetration %.3g r, kinetic energy %.3g J\n",
              w.max_penetration() / r,
              w.kinetic_energy());
  if (read)
    std::printf("(bodies read after every step, counted as integrate; "
                "checksum %.6g)\n",
                sum);
  return 0;
}
