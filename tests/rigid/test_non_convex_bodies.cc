// Non-convex bodies, which the narrow phase meets through their signed
// distance and surface points (geometry::ShapeKind::general), with an
// analytic torus standing in for a distance map (major radius R = 0.1 m,
// minor radius r = 0.03 m, axis z).
// - The torus dropped flat comes to rest with its centre at height r.
// - A small sphere (radius 0.03 < R - r) dropped on the axis falls through
//   the hole onto the floor (centre at its radius).
// - A large sphere (radius 0.1) dropped on the axis rests on the ring at
//   the closed-form height z_torus + sqrt((r + r_s)^2 - R^2).
// Heights to 1 % of the minor radius, with both velocity solvers.
#include <particulate/geometry/sphere.h>
#include <particulate/geometry/torus.h>

#include <cmath>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

int
main()
{
  const double R = 0.1, r = 0.03;
  for (const auto type : {ContactSolverType::projected_gauss_seidel,
                          ContactSolverType::sequential_impulses})
    {
      WorldParameters prm;
      prm.contact_solver = type;
      World    w(prm);
      Material m;
      m.static_friction = m.dynamic_friction = 0.4;
      w.add_material(m);
      add_floor(w);
      auto         torus = std::make_shared<Torus>(R, r);
      const BodyId t1    = w.add_body(torus, 0, Eigen::Vector3d(0., 0., 0.06));
      const BodyId small = w.add_body(std::make_shared<Sphere>(0.03),
                                      0,
                                      Eigen::Vector3d(0., 0., 0.2));
      const BodyId t2    = w.add_body(torus, 0, Eigen::Vector3d(1., 0., 0.06));
      const BodyId big   = w.add_body(std::make_shared<Sphere>(0.1),
                                    0,
                                    Eigen::Vector3d(1., 0., 0.3));
      for (int step = 0; step < 2000; ++step)
        w.step(1.e-3);
      const double big_exact = r + std::sqrt((r + 0.1) * (r + 0.1) - R * R);
      std::cout << to_string(type) << ": torus z " << w.body(t1).position[2]
                << " (exact " << r << "), small sphere z "
                << w.body(small).position[2] << " (exact 0.03), big sphere z "
                << w.body(big).position[2] << " (exact " << big_exact
                << "), second torus z " << w.body(t2).position[2] << "\n";
      CHECK(std::abs(w.body(t1).position[2] - r) < 0.01 * r, "torus height");
      CHECK(std::abs(w.body(small).position[2] - 0.03) < 0.01 * r,
            "small sphere through the hole");
      CHECK(std::abs(w.body(big).position[2] - big_exact) < 0.01 * r,
            "big sphere on the ring");
      CHECK(std::abs(w.body(t2).position[2] - r) < 0.01 * r,
            "loaded torus height");
    }
  std::cout << "OK\n";
  return 0;
}
