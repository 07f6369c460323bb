// A stack of 10 cubes (edge 0.1 m) on the floor stays standing for 10 s with
// the LCP (projected Gauss-Seidel) and the sequential-impulse solvers: no
// tipping (every box axis within 1 degree of vertical and every centre within
// 1 % of the edge from the stack axis) and penetration below 1 % of the edge.
#include <particulate/geometry/box.h>

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
      const double a = 0.1;
      auto box       = std::make_shared<Box>(Eigen::Vector3d::Constant(a / 2.));
      for (int i = 0; i < 10; ++i)
        w.add_body(box, 0, Eigen::Vector3d(0., 0., a / 2. + i * a));
      double max_pen = 0., max_off = 0., max_tilt = 0.;
      for (int step = 0; step < 10000; ++step)
        {
          w.step(1.e-3);
          max_pen = std::max(max_pen, w.max_penetration());
          for (unsigned int i = 1; i < w.n_bodies(); ++i)
            {
              const auto &b = w.body(i);
              max_off       = std::max(max_off, b.position.head<2>().norm());
              const Eigen::Vector3d z
                = b.orientation * Eigen::Vector3d::UnitZ();
              max_tilt = std::max(max_tilt, std::acos(std::min(1., z[2])));
            }
        }
      std::cout << to_string(type) << ": max penetration " << max_pen / a * 100.
                << " % of the edge, max lateral offset " << max_off
                << " m, max tilt " << max_tilt * 180. / M_PI
                << " deg, top box z " << w.body(10).position[2] << " (initial "
                << a / 2. + 9 * a << "), iterations "
                << w.statistics().solver_iterations << "\n";
      CHECK(max_pen < 0.01 * a, "penetration");
      CHECK(max_off < 0.01 * a, "lateral offset");
      CHECK(max_tilt < M_PI / 180., "tilt");
    }
  std::cout << "OK\n";
  return 0;
}
