// Spheres (radii uniform in [4, 6] mm) poured into an open box of
// 0.1 m x 0.1 m come to rest: translational kinetic energy below 1e-6 of
// the potential energy, the deepest overlap below 1 % of the smallest radius,
// and no sphere outside the box. Usage: rigid_pouring [N] [solver]
// (default 400 spheres, sequential impulses; the validation run uses 10^4).
#include <particulate/rigid/scene.h>

#include <cstdlib>
#include <string>

#include "test_tools.h"

using namespace particulate::rigid;

namespace {
  double
  translational_energy(const World &w)
  {
    double e = 0.;
    for (const auto &b : w.bodies())
      if (!b.is_fixed())
        e += 0.5 * b.mass() * b.linear_velocity.squaredNorm();
    return e;
  }
} // namespace

int
main(int argc, char **argv)
{
  SceneDescription scene;
  scene.world.contact_solver         = argc > 2 ?
                                         contact_solver_type_from_string(argv[2]) :
                                         ContactSolverType::sequential_impulses;
  scene.world.solver.iterations      = 50;
  scene.materials[0].static_friction = scene.materials[0].dynamic_friction
    = 0.3;
  scene.materials[0].restitution   = 0.2;
  scene.materials[0].dem_stiffness = 2.e4;
  auto &p                          = scene.pouring;
  p.n_spheres                      = argc > 1 ? std::atoi(argv[1]) : 400;
  p.radius_min                     = 0.004;
  p.radius_max                     = 0.006;
  p.box_min                        = Eigen::Vector3d(0., 0., 0.);
  p.box_max                        = Eigen::Vector3d(0.1, 0.1, 0.1);
  p.seed                           = 7;
  World        w                   = scene.build_world();
  const double dt                  = 1.e-3;

  double pe0 = 0.;
  for (const auto &b : w.bodies())
    if (!b.is_fixed())
      pe0 += b.mass() * 9.81 * b.position[2];
  double       t_rest = -1., pen_max_rest = 0.;
  const double r_min = p.radius_min;
  for (int step = 1; step <= 20000; ++step)
    {
      w.step(dt);
      // Translational energy: a sphere may keep spinning about the vertical
      // (point contacts have no torsional or rolling resistance).
      if (step % 100 == 0 && step * dt > 0.3
          && translational_energy(w) < 1.e-6 * pe0)
        {
          t_rest = step * dt;
          break;
        }
    }
  pen_max_rest         = w.max_penetration();
  unsigned int outside = 0;
  double       zmax    = 0.;
  for (const auto &b : w.bodies())
    {
      if (b.is_fixed())
        continue;
      const double r = b.bounding_radius(), tol = 0.01 * r;
      const auto  &x = b.position;
      zmax           = std::max(zmax, x[2] + r);
      if (x[0] < r - tol || x[0] > 0.1 - r + tol || x[1] < r - tol
          || x[1] > 0.1 - r + tol || x[2] < r - tol)
        ++outside;
    }
  std::cout << p.n_spheres << " spheres, "
            << to_string(scene.world.contact_solver) << ": at rest after "
            << t_rest << " s, max penetration " << pen_max_rest / r_min * 100.
            << " % of the smallest radius, bed height " << zmax
            << " m, outside: " << outside << ", contacts "
            << w.statistics().contacts << "\n";
  CHECK(t_rest > 0., "the spheres did not come to rest within 20 s");
  CHECK(pen_max_rest < 0.01 * r_min, "penetration " << pen_max_rest);
  CHECK(outside == 0, outside << " spheres left the box");
  std::cout << "OK\n";
  return 0;
}
