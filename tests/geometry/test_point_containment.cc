// Hash-grid point classification (thesis §5.4.2) gives exactly the
// brute-force answer for many bodies of every kind, on a lattice and on
// scattered points, and touches only the points in the bodies' boxes.
#include <particulate/geometry/box.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/distance_map_shape.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/inner_spheres.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/point_containment.h>
#include <particulate/geometry/sphere.h>
#include <particulate/geometry/torus.h>
#include <particulate/geometry/triangulated_surface.h>

#include <cmath>
#include <memory>
#include <random>
#include <sstream>

#include "check.h"

using namespace particulate::geometry;
using Eigen::Vector3d;

int
main()
{
  std::mt19937                           rng(11);
  std::uniform_real_distribution<double> u(0., 1.);

  // Shapes of every kind, small against the unit cube.
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(std::make_unique<Sphere>(0.06));
  shapes.push_back(std::make_unique<Box>(Vector3d(0.05, 0.03, 0.08)));
  shapes.push_back(std::make_unique<Cylinder>(0.04, 0.07));
  shapes.push_back(std::make_unique<Ellipsoid>(Vector3d(0.08, 0.05, 0.03)));
  shapes.push_back(std::make_unique<Torus>(0.06, 0.02));
  shapes.push_back(std::make_unique<TriangulatedSurface>(
    mesh_generators::torus(0.06, 0.025, 24, 12)));
  auto map = std::make_shared<const DistanceMap>(
    DistanceMap::build(Ellipsoid(Vector3d(0.07, 0.04, 0.05)),
                       {0.005, 0.01, 1}));
  shapes.push_back(std::make_unique<DistanceMapShape>(map));

  // 100 bodies at random poses; the first also a half-space (floor).
  HalfSpace                floor(Vector3d(0, 0, 1), 0.05);
  std::vector<PlacedShape> bodies;
  bodies.push_back({&floor, Pose()});
  for (int b = 0; b < 99; ++b)
    {
      const Eigen::Quaterniond q(u(rng) - 0.5,
                                 u(rng) - 0.5,
                                 u(rng) - 0.5,
                                 u(rng) - 0.5);
      bodies.push_back({shapes[b % shapes.size()].get(),
                        Pose(q, Vector3d(u(rng), u(rng), 0.1 + 0.9 * u(rng)))});
    }

  // Point sets: a 33^3 lattice (mesh vertices), scattered points.
  std::vector<std::vector<Vector3d>> sets(2);
  for (int k = 0; k < 33; ++k)
    for (int j = 0; j < 33; ++j)
      for (int i = 0; i < 33; ++i)
        sets[0].emplace_back(i / 32., j / 32., k / 32.);
  for (int s = 0; s < 50000; ++s)
    sets[1].emplace_back(u(rng), u(rng), u(rng));

  for (std::size_t s = 0; s < sets.size(); ++s)
    for (const double cell : {0., 0.01, 0.2})
      {
        const PointHashGrid   grid(sets[s], cell);
        ContainmentStatistics stats;
        std::vector<double>   dist;
        const auto  fast = classify_points(grid, bodies, &dist, &stats);
        const auto  slow = classify_points_brute_force(sets[s], bodies);
        std::size_t diff = 0, n_in = 0;
        for (std::size_t i = 0; i < fast.size(); ++i)
          {
            diff += fast[i] != slow[i];
            n_in += fast[i] >= 0;
          }
        std::cout << "set " << s << ", cell " << grid.cell_size() << ": "
                  << grid.size() << " points, " << grid.n_cells() << " cells, "
                  << n_in << " inside, " << stats.n_tests << " tests for "
                  << bodies.size() << " bodies (brute force "
                  << grid.size() * bodies.size() << "), differences " << diff
                  << std::endl;
        CHECK_MSG(diff == 0, "hash grid = brute force");
        CHECK(n_in > 0);
        // Distances: inside points have d <= 0 for their body, exactly the
        // body's own value where only one box holds the point.
        long bad = 0;
        for (std::size_t i = 0; i < fast.size(); ++i)
          if (fast[i] >= 0)
            bad += !(dist[i] <= 1e-12);
        CHECK(bad == 0);
      }

  // Without the half-space (whose box is everything), the hash grid touches
  // only a small fraction of the points.
  {
    std::vector<PlacedShape> finite(bodies.begin() + 1, bodies.end());
    const PointHashGrid      grid(sets[0]);
    ContainmentStatistics    stats;
    const auto fast = classify_points(grid, finite, nullptr, &stats);
    CHECK(fast == classify_points_brute_force(sets[0], finite));
    const double fraction
      = double(stats.n_tests) / (grid.size() * finite.size());
    std::cout << "99 finite bodies: " << stats.n_points_touched
              << " points touched, tests / brute-force tests = " << fraction
              << std::endl;
    CHECK(fraction < 0.01);
  }

  // Edge cases: no points, no bodies, a point exactly on a sphere's box.
  {
    const PointHashGrid empty(std::vector<Vector3d>{});
    CHECK(classify_points(empty, bodies).empty());
    Sphere              s(0.25);
    const PointHashGrid one({Vector3d(0.5, 0.25, 0.25)});
    const auto          r = classify_points(
      one,
      {{&s, Pose(Eigen::Matrix3d::Identity(), Vector3d(0.25, 0.25, 0.25))}});
    CHECK(r.size() == 1 && r[0] == 0);
    CHECK(classify_points(one, {})[0] == -1);
  }
  return test::finish("geometry_point_containment");
}
