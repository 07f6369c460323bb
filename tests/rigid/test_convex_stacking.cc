// Reduced contact sets for curved convex shapes (thesis §3.4.1, Fig. 3.20):
// - five upright cylinders stacked on the floor (cylinder-plane fan and
//   perturbed GJK/EPA between cylinders) stand for 3 s: axes within 1 degree
//   of vertical, centres within 1 % of the diameter of the stack axis;
// - a capsule dropped on the floor lies on its side at height r (it may keep
//   rolling: no rolling resistance) and stops bouncing;
// - a slightly tilted ellipsoid dropped flat rocks on its flattest side: its
//   energy never exceeds the initial one, it never sinks more than 1 % into
//   the floor and ends within 1 % of its size of the resting height.
#include <particulate/geometry/capsule.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/ellipsoid.h>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

int
main()
{
  for (const auto type : {ContactSolverType::projected_gauss_seidel,
                          ContactSolverType::sequential_impulses})
    {
      WorldParameters prm;
      prm.contact_solver = type;
      World    w(prm);
      Material m;
      m.static_friction = m.dynamic_friction = 0.5;
      w.add_material(m);
      add_floor(w);
      const double r = 0.05, hh = 0.04;
      auto         cyl = std::make_shared<Cylinder>(r, hh);
      for (int i = 0; i < 5; ++i)
        w.add_body(cyl, 0, Eigen::Vector3d(0., 0., hh + 2. * hh * i));
      const BodyId cap
        = w.add_body(std::make_shared<Capsule>(0.02, 0.05),
                     0,
                     Eigen::Vector3d(0.5, 0., 0.1),
                     Eigen::Quaterniond(
                       Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitX())));
      const BodyId ell = w.add_body(
        std::make_shared<Ellipsoid>(Eigen::Vector3d(0.06, 0.04, 0.025)),
        0,
        Eigen::Vector3d(-0.5, 0., 0.1),
        Eigen::Quaterniond(
          Eigen::AngleAxisd(0.05, Eigen::Vector3d(1, 1, 0).normalized())));
      auto energy = [&w](BodyId i) {
        const auto &b = w.body(i);
        return b.kinetic_energy() + b.mass() * 9.81 * b.position[2];
      };
      const double E0_ell = energy(ell);
      double       E_max = 0., z_min_ell = 1.;
      double       max_tilt = 0., max_off = 0.;
      for (int step = 0; step < 3000; ++step)
        {
          w.step(1.e-3);
          for (BodyId i = 1; i <= 5; ++i)
            {
              const Eigen::Vector3d z
                = w.body(i).orientation * Eigen::Vector3d::UnitZ();
              max_tilt = std::max(max_tilt, std::acos(std::min(1., z[2])));
              max_off  = std::max(max_off, w.body(i).position.head<2>().norm());
            }
          E_max     = std::max(E_max, energy(ell));
          z_min_ell = std::min(z_min_ell, w.body(ell).position[2]);
        }
      std::cout << to_string(type) << ": cylinder stack max tilt "
                << max_tilt * 180. / M_PI << " deg, max offset " << max_off
                << " m, top z " << w.body(5).position[2] << " (initial "
                << 9 * hh << "); capsule z " << w.body(cap).position[2]
                << ", ellipsoid z " << w.body(ell).position[2]
                << ", max penetration " << w.max_penetration() << "\n";
      CHECK(max_tilt < M_PI / 180., "cylinder tilt");
      CHECK(max_off < 0.01 * 2. * r, "cylinder offset");
      CHECK(std::abs(w.body(5).position[2] - 9. * hh) < 0.01 * hh,
            "stack height");
      CHECK(std::abs(w.body(cap).position[2] - 0.02) < 0.01 * 0.02 + 1.e-4,
            "capsule rests on its side");
      std::cout << "  ellipsoid: energy max/initial " << E_max / E0_ell
                << ", lowest z " << z_min_ell << "\n";
      CHECK(E_max <= E0_ell * (1. + 1.e-6), "the ellipsoid gained energy");
      CHECK(z_min_ell > 0.025 * 0.99, "the ellipsoid sank into the floor");
      CHECK(std::abs(w.body(ell).position[2] - 0.025) < 0.01 * 0.06,
            "ellipsoid stays on its flat side");
      // A capsule on its side may keep rolling (no rolling resistance);
      // it must not bounce.
      std::cout << "  capsule v = " << w.body(cap).linear_velocity.transpose()
                << ", ellipsoid v = " << w.body(ell).linear_velocity.transpose()
                << "\n";
      CHECK(std::abs(w.body(cap).linear_velocity[2]) < 1.e-3,
            "the capsule must not bounce");
    }
  std::cout << "OK\n";
  return 0;
}
