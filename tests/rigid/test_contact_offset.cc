// The contact offset keeps surfaces apart by a given film thickness: two
// spheres stacked on a floor come to rest with gaps equal to the offset
// (sphere-plane through the general narrow phase, sphere-sphere through the
// fast path), with each contact solver, and no gap closes below the offset
// by more than the solver's slop during the fall. For the DEM the rest gap
// is the offset minus the spring compression m g / k of each contact, and
// the impact may compress the spring by at most the undamped bound
// v sqrt(m / k).
#include <particulate/geometry/sphere.h>

#include <cmath>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

int
main()
{
  const double r = 0.05, offset = 0.01, g = 9.81;
  for (const auto type : all_solvers())
    {
      WorldParameters prm;
      prm.contact_solver = type;
      prm.contact_offset = offset;
      World    w(prm);
      Material m;
      m.restitution   = 0.;
      m.dem_stiffness = 2.e5;
      w.add_material(m);
      add_floor(w);
      const BodyId lower = w.add_body(std::make_shared<Sphere>(r),
                                      0,
                                      Eigen::Vector3d(0., 0., 0.2));
      const BodyId upper = w.add_body(std::make_shared<Sphere>(r),
                                      0,
                                      Eigen::Vector3d(0., 0., 0.4));
      const auto   gaps  = [&]() {
        const Eigen::Vector3d a = w.body(lower).position,
                              b = w.body(upper).position;
        return std::make_pair(a[2] - r, (b - a).norm() - 2. * r);
      };
      double min_floor = 1., min_pair = 1.;
      for (int step = 0; step < 3000; ++step)
        {
          w.step(1.e-3);
          min_floor = std::min(min_floor, gaps().first);
          min_pair  = std::min(min_pair, gaps().second);
        }
      const auto [floor_gap, pair_gap] = gaps();
      const double mass                = w.body(lower).mass();
      // series springs of two bodies: k_eff = k / 2
      const double squeeze        = type == ContactSolverType::dem ?
                                      mass * g / (0.5 * m.dem_stiffness) :
                                      0.;
      const double expected_floor = offset - 2. * squeeze,
                   expected_pair  = offset - squeeze;
      std::cout << to_string(type) << ": rest gaps floor " << floor_gap
                << " m (expected " << expected_floor << "), pair " << pair_gap
                << " m (expected " << expected_pair
                << "); smallest during the fall " << min_floor << ", "
                << min_pair << " m; speeds "
                << w.body(lower).linear_velocity.norm() << ", "
                << w.body(upper).linear_velocity.norm() << " m/s\n";
      const double tol = 0.05 * offset;
      CHECK(std::abs(floor_gap - expected_floor) < tol,
            "floor gap " << floor_gap << " instead of " << expected_floor);
      CHECK(std::abs(pair_gap - expected_pair) < tol,
            "pair gap " << pair_gap << " instead of " << expected_pair);
      const double v_impact = std::sqrt(2. * g * (0.2 - r - offset));
      const double overshoot
        = type == ContactSolverType::dem ?
            v_impact * std::sqrt(mass / (0.5 * m.dem_stiffness)) :
            2. * tol;
      CHECK(min_floor > offset - overshoot && min_pair > offset - overshoot,
            "a gap closed below the offset during the fall");
      CHECK(w.body(upper).linear_velocity.norm() < 1.e-3,
            "the stack must come to rest");
    }
  std::cout << "OK\n";
  return 0;
}
