// Signed distances of the analytic shapes against closed forms and against
// each other (thesis §3.4: sphere, box, cylinder, half-space, ellipsoid,
// torus), and of a triangulated surface against its exact polyhedron.
#include <particulate/geometry/box.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/mesh_generators.h>
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
  // The signed-distance gradient must be the returned normal: check by
  // central differences at points away from the medial axis.
  void
  check_gradient(const Shape &s, const Vector3d &p, const char *name)
  {
    Vector3d     n;
    const double d = s.signed_distance(p, &n);
    (void)d;
    const double h = 1e-6;
    Vector3d     g;
    for (int k = 0; k < 3; ++k)
      {
        Vector3d e = Vector3d::Zero();
        e[k]       = h;
        g[k] = (s.signed_distance(p + e) - s.signed_distance(p - e)) / (2 * h);
      }
    std::ostringstream msg;
    msg << name << ": normal " << n.transpose() << " vs gradient "
        << g.transpose() << " at " << p.transpose();
    CHECK_MSG((n - g).norm() < 1e-5 && std::abs(n.norm() - 1.) < 1e-12,
              msg.str());
  }
} // namespace

int
main()
{
  // Sphere: |p| - r.
  {
    Sphere s(2.);
    CHECK(std::abs(s.signed_distance(Vector3d(3, 0, 0)) - 1.) < 1e-15);
    CHECK(std::abs(s.signed_distance(Vector3d(0, 0, 0)) + 2.) < 1e-15);
    check_gradient(s, Vector3d(0.3, -1.2, 0.7), "sphere");
  }
  // Box: faces, edge and corner regions, inside.
  {
    Box b(Vector3d(1, 2, 3));
    CHECK(std::abs(b.signed_distance(Vector3d(2, 0, 0)) - 1.) < 1e-15);
    CHECK(std::abs(b.signed_distance(Vector3d(2, 3, 0)) - std::sqrt(2.))
          < 1e-15);
    CHECK(std::abs(b.signed_distance(Vector3d(2, 3, 4)) - std::sqrt(3.))
          < 1e-15);
    CHECK(std::abs(b.signed_distance(Vector3d(0.5, 0, 0)) + 0.5) < 1e-15);
    CHECK(std::abs(b.signed_distance(Vector3d(0, 0, 0)) + 1.) < 1e-15);
    check_gradient(b, Vector3d(1.5, 2.5, 0.3), "box edge region");
    check_gradient(b, Vector3d(0.2, 1.5, -0.4), "box inside");
  }
  // Cylinder: side, cap, rim, inside.
  {
    Cylinder c(1., 2.);
    CHECK(std::abs(c.signed_distance(Vector3d(0, 3, 0)) - 2.) < 1e-15);
    CHECK(std::abs(c.signed_distance(Vector3d(0.5, 0, -3)) - 1.) < 1e-15);
    CHECK(std::abs(c.signed_distance(Vector3d(4, 0, 6)) - 5.) < 1e-14);
    CHECK(std::abs(c.signed_distance(Vector3d(0, 0.5, 0)) + 0.5) < 1e-15);
    CHECK(std::abs(c.signed_distance(Vector3d(0, 0, 1.8)) + 0.2) < 1e-15);
    check_gradient(c, Vector3d(1.2, 0.9, 2.4), "cylinder rim");
  }
  // Half-space {n.x <= c}.
  {
    HalfSpace h(Vector3d(0, 0, 2), 1.);
    CHECK(std::abs(h.signed_distance(Vector3d(5, 5, 3)) - 2.) < 1e-15);
    CHECK(h.contains(Vector3d(0, 0, -10)) && !h.contains(Vector3d(0, 0, 1.1)));
    CHECK(h.bounding_box().upper[2] == 1.);
  }
  // Torus: on the centre circle the distance is -r.
  {
    Torus t(2., 0.5);
    CHECK(std::abs(t.signed_distance(Vector3d(0, 2, 0)) + 0.5) < 1e-15);
    CHECK(std::abs(t.signed_distance(Vector3d(0, 0, 0)) - 1.5) < 1e-15);
    CHECK(std::abs(t.signed_distance(Vector3d(3, 0, 1)) - (std::sqrt(2.) - 0.5))
          < 1e-15);
    check_gradient(t, Vector3d(1.1, 1.9, 0.4), "torus");
  }
  // Ellipsoid: with equal axes it is a sphere; on the axes the distance is
  // exact; elsewhere the closest point satisfies the ellipsoid equation and
  // p - x is parallel to the normal, and brute-force sampling of the
  // surface never finds a closer point.
  {
    Ellipsoid                              round(Vector3d(1.5, 1.5, 1.5));
    Sphere                                 s(1.5);
    std::mt19937                           rng(3);
    std::uniform_real_distribution<double> u(-3., 3.);
    double                                 max_diff = 0.;
    for (int i = 0; i < 2000; ++i)
      {
        const Vector3d p(u(rng), u(rng), u(rng));
        max_diff
          = std::max(max_diff,
                     std::abs(round.signed_distance(p) - s.signed_distance(p)));
      }
    CHECK_MSG(max_diff < 1e-12, "ellipsoid with equal axes = sphere");

    const Vector3d e(3., 2., 1.);
    Ellipsoid      el(e);
    CHECK(std::abs(el.signed_distance(Vector3d(5, 0, 0)) - 2.) < 1e-14);
    CHECK(std::abs(el.signed_distance(Vector3d(0, 0, 0)) + 1.) < 1e-14);
    CHECK(std::abs(el.signed_distance(Vector3d(0, -2.5, 0)) - 0.5) < 1e-14);
    // Dense sampling of the surface by angles.
    std::vector<Vector3d> surface;
    const int             n = 400;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j < 2 * n; ++j)
        {
          const double th = M_PI * i / n, ph = M_PI * j / n;
          surface.emplace_back(e[0] * std::sin(th) * std::cos(ph),
                               e[1] * std::sin(th) * std::sin(ph),
                               e[2] * std::cos(th));
        }
    double worst = 0.;
    for (int i = 0; i < 40; ++i)
      {
        const Vector3d p(u(rng), u(rng) * 0.7, u(rng) * 0.4);
        Vector3d       nrm;
        const double   sd = el.signed_distance(p, &nrm);
        const double   d  = std::abs(sd);
        // The closest point p - sd n lies on the ellipsoid.
        const Vector3d x = p - sd * nrm;
        CHECK_MSG(std::abs(x.cwiseQuotient(e).squaredNorm() - 1.) < 1e-10,
                  "ellipsoid: p - d n lies on the surface");
        double best = 1e300;
        for (const auto &q : surface)
          best = std::min(best, (p - q).norm());
        // The sampled minimum is an upper bound of the exact distance, and
        // close to it (sample spacing <= 0.024, so within half of that).
        worst = std::max(worst, best - d);
        CHECK_MSG(d <= best + 1e-12,
                  "ellipsoid distance not larger than a sampled distance");
      }
    CHECK_MSG(worst < 0.012, "ellipsoid distance close to the sampled minimum");
    check_gradient(el, Vector3d(2.5, 1.5, 0.8), "ellipsoid outside");
    check_gradient(el, Vector3d(0.5, 0.3, 0.2), "ellipsoid inside");
    CHECK(el.contains(Vector3d(2.9, 0, 0))
          && !el.contains(Vector3d(0, 0, 1.01)));
  }
  // Triangulated box: the polyhedron is exactly the box, so the signed
  // distance must equal Box's to rounding, inside and outside, and the
  // exact side test must agree with the pseudo-normal sign.
  {
    const Vector3d                         h(0.5, 1., 1.5);
    TriangulatedSurface                    tb(mesh_generators::box(h, 3));
    Box                                    b(h);
    std::mt19937                           rng(5);
    std::uniform_real_distribution<double> u(-2.5, 2.5);
    double                                 max_diff = 0.;
    int                                    disagree = 0;
    for (int i = 0; i < 20000; ++i)
      {
        const Vector3d p(u(rng), u(rng), u(rng));
        max_diff
          = std::max(max_diff,
                     std::abs(tb.signed_distance(p) - b.signed_distance(p)));
        disagree += (tb.contains(p) != b.contains(p));
      }
    std::ostringstream msg;
    msg << "triangulated box vs box: max |diff| = " << max_diff;
    CHECK_MSG(max_diff < 1e-12, msg.str());
    CHECK(disagree == 0);
    CHECK(std::abs(tb.volume() - b.volume()) < 1e-12);
    check_gradient(tb, Vector3d(0.1, 0.2, 0.3), "triangulated box inside");
    check_gradient(tb, Vector3d(0.9, 1.6, 0.3), "triangulated box edge");
  }
  // A surface that does not bound a solid is refused.
  {
    TriangleMesh open = mesh_generators::icosphere(1., 1);
    open.triangles.pop_back();
    bool threw = false;
    try
      {
        TriangulatedSurface s(open);
      }
    catch (const GeometryError &e)
      {
        threw = std::string(e.what()).find("open: 3 border edges")
                != std::string::npos;
      }
    CHECK_MSG(threw, "open mesh refused with 'open: 3 border edges'");
  }
  return test::finish("geometry_shapes");
}
