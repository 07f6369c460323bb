// Inner spheres (thesis §3.4.2): both constructions cover at least 90 % of
// the body's volume, never reach outside it by more than one map cell, the
// greedy packing needs fewer spheres, and the bucketed containment query
// equals a brute-force loop over the spheres.
#include <particulate/geometry/box.h>
#include <particulate/geometry/inner_spheres.h>
#include <particulate/geometry/mesh_io.h>
#include <particulate/geometry/sphere.h>
#include <particulate/geometry/torus.h>
#include <particulate/geometry/triangulated_surface.h>

#include <cmath>
#include <random>
#include <sstream>

#include "check.h"

using namespace particulate::geometry;
using Eigen::Vector3d;

namespace {
  void
  check_body(const Shape &shape, const double h, const std::string &name)
  {
    const DistanceMap  map   = DistanceMap::build(shape, {h, 2 * h, 2});
    const InnerSpheres cells = InnerSpheres::from_cells(map);
    const InnerSpheres pack  = InnerSpheres::greedy(map);

    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> u(0., 1.);
    const BoundingBox                      box = shape.bounding_box();
    const int                              n   = 100000;
    std::vector<Vector3d>                  pts;
    std::vector<char>                      inside;
    long                                   n_inside = 0;
    for (int s = 0; s < n; ++s)
      {
        pts.push_back(
          box.lower
          + box.extent().cwiseProduct(Vector3d(u(rng), u(rng), u(rng))));
        inside.push_back(shape.contains(pts.back()));
        n_inside += inside.back();
      }

    for (const auto *rep : {&cells, &pack})
      {
        const std::string kind
          = rep == &cells ? "cell spheres" : "greedy packing";
        long covered = 0, brute_mismatch = 0;
        for (int s = 0; s < n; ++s)
          {
            const bool in    = rep->contains(pts[s]);
            bool       brute = false;
            if (s % 10 == 0)
              {
                for (const auto &b : rep->balls())
                  brute = brute
                          || (pts[s] - b.centre).squaredNorm()
                               <= b.radius * b.radius;
                brute_mismatch += (brute != in);
              }
            covered += (in && inside[s]);
          }
        // Largest overshoot: how far a sphere reaches out of the body.
        double overshoot = -1e300;
        for (const auto &b : rep->balls())
          overshoot
            = std::max(overshoot, b.radius + shape.signed_distance(b.centre));
        const double coverage = double(covered) / n_inside;
        std::cout << name << ", " << kind << ": " << rep->size()
                  << " spheres, coverage " << 100. * coverage
                  << " %, overshoot " << overshoot / h << " h" << std::endl;
        CHECK_MSG(coverage >= 0.90, name + " " + kind + " covers >= 90 %");
        CHECK_MSG(overshoot <= h, name + " " + kind + " stays within one cell");
        CHECK_MSG(brute_mismatch == 0,
                  name + " " + kind + " query = brute force");
      }
    CHECK_MSG(pack.size() < cells.size() / 2,
              name + ": greedy packing needs fewer than half the cell spheres");

    const InnerSphereData d = pack.export_data();
    CHECK(d.cx.size() == pack.size() && d.r.size() == pack.size());
    CHECK(std::abs(d.cx[0] - pack.balls()[0].centre[0]) < 1e-6
          && std::abs(d.r[0] - pack.balls()[0].radius) < 1e-6);
  }
} // namespace

int
main()
{
  check_body(Sphere(1.), 0.05, "sphere");
  check_body(Torus(1., 0.35), 0.04, "torus");
  check_body(Box(Vector3d(1., 0.5, 0.25)), 0.04, "box");
  const std::string         dir = test::cgal_meshes_or_skip();
  const TriangulatedSurface elephant(read_surface_mesh(dir + "/elephant.off"));
  check_body(elephant,
             elephant.bounding_box().extent().maxCoeff() / 64.,
             "elephant");
  return test::finish("geometry_inner_spheres");
}
