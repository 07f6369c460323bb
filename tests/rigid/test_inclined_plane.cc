// Block on an inclined plane (the plane is horizontal and gravity tilted by
// theta, which is the same problem). mu_s = 0.5, mu_d = 0.3.
// - tan(theta) = 0.4 < mu_s: the block sticks (moves < 1e-6 m in 2 s; for
//   the DEM plus twice the elastic deflection of its tangential springs);
// - tan(theta) = 0.7 > mu_s: it slides with a = g (sin(theta) - mu_d
//   cos(theta)) within 1 %, measured between t = 0.5 s and 1.5 s.
#include <particulate/geometry/box.h>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

int
main()
{
  const double g = 9.81, mu_s = 0.5, mu_d = 0.3;
  for (const auto type : all_solvers())
    for (const double slope : {0.4, 0.7})
      {
        const double    theta = std::atan(slope);
        WorldParameters prm;
        prm.contact_solver = type;
        prm.gravity
          = g * Eigen::Vector3d(std::sin(theta), 0., -std::cos(theta));
        World    w(prm);
        Material m;
        m.static_friction          = mu_s;
        m.dynamic_friction         = mu_d;
        m.dem_stiffness            = 1.e6;
        m.dem_tangential_stiffness = 5.e5;
        w.add_material(m);
        add_floor(w);
        const Eigen::Vector3d
          e(0.1, 0.1, 0.02); // flat: little load imbalance between the corners
        const BodyId b = w.add_body(std::make_shared<Box>(e),
                                    0,
                                    Eigen::Vector3d(0., 0., e[2]));
        if (type == ContactSolverType::dem)
          w.body(b).position[2]
            -= w.body(b).mass() * g * std::cos(theta) / 4. / 5.e5;
        const double dt = 1.e-3;
        double       x0 = w.body(b).position[0], v05 = 0., v15 = 0.;
        for (int step = 1; step <= 2000; ++step)
          {
            w.step(dt);
            if (step == 500)
              v05 = w.body(b).linear_velocity[0];
            if (step == 1500)
              v15 = w.body(b).linear_velocity[0];
          }
        const double moved = w.body(b).position[0] - x0;
        if (slope < mu_s)
          {
            // The DEM's tangential springs deflect elastically by
            // F_t / (4 k_t); the rigid solvers must not move at all.
            const double elastic
              = type == ContactSolverType::dem ?
                  2. * w.body(b).mass() * g * std::sin(theta) / (4. * 2.5e5) :
                  0.;
            std::cout << to_string(type) << ", tan = " << slope << ": moved "
                      << moved << " m, speed "
                      << w.body(b).linear_velocity.norm() << " m/s\n";
            CHECK(std::abs(moved) < 1.e-6 + elastic,
                  "the block must stick, moved " << moved);
            CHECK(w.body(b).linear_velocity.norm() < 1.e-6,
                  "the block must be at rest");
          }
        else
          {
            const double a     = (v15 - v05) / 1.;
            const double exact = g * (std::sin(theta) - mu_d * std::cos(theta));
            std::cout << to_string(type) << ", tan = " << slope << ": a = " << a
                      << " (exact " << exact << "), rel. error "
                      << rel_diff(a, exact) << "\n";
            CHECK(rel_diff(a, exact) < 0.01, "sliding acceleration");
          }
        CHECK(std::abs(w.body(b).orientation.angularDistance(
                Eigen::Quaterniond::Identity()))
                < 1.e-3,
              "the block must not tip");
      }
  std::cout << "OK\n";
  return 0;
}
