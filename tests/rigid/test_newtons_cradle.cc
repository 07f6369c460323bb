// Newton's cradle: five equal spheres with restitution 1, four touching in a
// row and the first arriving with speed v. The shock
// must propagate through the contact graph so that the last sphere leaves
// with at least 95 % of v and the others nearly stop (velocity solvers:
// exact pairwise exchange in propagation order). The DEM's linear springs
// disperse the pulse, which is reported, not asserted.
#include <particulate/geometry/sphere.h>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

int
main()
{
  for (const auto type : all_solvers())
    {
      WorldParameters prm;
      prm.contact_solver = type;
      prm.gravity.setZero();
      World    w(prm);
      Material m;
      m.restitution   = 1.;
      m.dem_stiffness = 1.e6;
      w.add_material(m);
      const double r = 0.05, v = 1.;
      auto         ball = std::make_shared<Sphere>(r);
      w.add_body(ball,
                 0,
                 Eigen::Vector3d(-0.05, 0., 0.)); // incoming, 0.05 m gap
      for (int i = 1; i < 5; ++i)
        w.add_body(ball, 0, Eigen::Vector3d(0.05 + 2. * r * (i - 1), 0., 0.));
      w.body(0).linear_velocity = Eigen::Vector3d(v, 0., 0.);
      for (int step = 0; step < 200; ++step)
        w.step(1.e-3);
      std::cout << to_string(type) << ": velocities";
      for (unsigned int i = 0; i < 5; ++i)
        std::cout << " " << w.body(i).linear_velocity[0];
      const double last = w.body(4).linear_velocity[0];
      std::cout << " -> last sphere leaves with " << 100. * last / v << " %\n";
      if (type != ContactSolverType::dem)
        {
          CHECK(last >= 0.95 * v, "last sphere speed " << last);
          for (unsigned int i = 0; i < 4; ++i)
            CHECK(std::abs(w.body(i).linear_velocity[0]) < 0.05 * v,
                  "sphere " << i << " should stop");
        }
    }
  std::cout << "OK\n";
  return 0;
}
