// Signed distances of the analytic shapes against closed forms and against
// each other (thesis §3.4: sphere, box, cylinder, half-space, ellipsoid,
// torus, elliptic cylinder), and of a triangulated surface against its exact
// polyhedron. The elliptic cylinder (a 2D run's ellipse) also against an
// independent 2D ellipse distance (dense sampling of the ellipse refined by
// ternary search): equal to 1e-12 in the plane z = 0 and, combined with the
// cap distance, everywhere; with equal semi-axes it is the cylinder to
// 1e-12; its normal is the finite-difference gradient to 1e-6.
#include <particulate/geometry/box.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/elliptic_cylinder.h>
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

  // Signed distance of (x, y) to the ellipse (x/a)^2 + (y/b)^2 = 1, computed
  // independently of Eberly's method: the best of 4096 points (a cos t,
  // b sin t) by angle, then the squared distance minimised over t by ternary
  // search within one sample spacing either side.
  double
  brute_ellipse_distance(const double a,
                         const double b,
                         const double x,
                         const double y)
  {
    auto dist2 = [&](const double t) {
      const double dx = x - a * std::cos(t), dy = y - b * std::sin(t);
      return dx * dx + dy * dy;
    };
    const int    n  = 4096;
    const double dt = 2. * M_PI / n;
    double       t0 = 0., best = dist2(0.);
    for (int k = 1; k < n; ++k)
      if (dist2(k * dt) < best)
        {
          best = dist2(k * dt);
          t0   = k * dt;
        }
    double lo = t0 - dt, hi = t0 + dt;
    for (int i = 0; i < 200; ++i)
      {
        const double m1 = lo + (hi - lo) / 3., m2 = hi - (hi - lo) / 3.;
        if (dist2(m1) < dist2(m2))
          hi = m2;
        else
          lo = m1;
      }
    const double d     = std::sqrt(std::min(best, dist2(0.5 * (lo + hi))));
    const double level = (x / a) * (x / a) + (y / b) * (y / b) - 1.;
    return level > 0. ? d : -d;
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
  // Elliptic cylinder, a = 3 along x, b = 2 along y, half height 1.5.
  {
    const double           a = 3., b = 2., h = 1.5;
    const EllipticCylinder ec(a, b, h);
    // Outside the side on the axes, above the caps, beyond the rim over the
    // vertex (a, 0, h) by (0.3, 0, 0.4).
    CHECK(std::abs(ec.signed_distance(Vector3d(5, 0, 0)) - 2.) < 1e-14);
    CHECK(std::abs(ec.signed_distance(Vector3d(0, -2.7, 0.3)) - 0.7) < 1e-14);
    CHECK(std::abs(ec.signed_distance(Vector3d(0, 0, -2)) - 0.5) < 1e-15);
    CHECK(std::abs(ec.signed_distance(Vector3d(1, 1, 2)) - 0.5) < 1e-15);
    CHECK(std::abs(ec.signed_distance(Vector3d(3.3, 0, 1.9)) - 0.5) < 1e-14);
    CHECK(std::abs(ec.signed_distance(Vector3d(0, -2.3, -1.9)) - 0.5) < 1e-14);
    // Inside: the centre is nearest to the caps; on the axes near the side.
    CHECK(std::abs(ec.signed_distance(Vector3d(0, 0, 0)) + 1.5) < 1e-15);
    CHECK(std::abs(ec.signed_distance(Vector3d(0, 0, 1.2)) + 0.3) < 1e-15);
    CHECK(std::abs(ec.signed_distance(Vector3d(-2.5, 0, 0.2)) + 0.5) < 1e-14);
    CHECK(std::abs(ec.signed_distance(Vector3d(0, 1.6, 0)) + 0.4) < 1e-14);
    // Inside on the major axis within the centre of curvature of the vertex,
    // |x| < (a^2 - b^2) / a, the closest points leave the axis: distance
    // b sqrt(1 - x^2 / (a^2 - b^2)).
    {
      const EllipticCylinder tall(a, b, 10.);
      const double           x = 1.;
      CHECK(std::abs(tall.signed_distance(Vector3d(x, 0, 0))
                     + b * std::sqrt(1. - x * x / (a * a - b * b)))
            < 1e-14);
    }
    CHECK(ec.contains(Vector3d(2.9, 0, 1.4))
          && !ec.contains(Vector3d(0, 0, 1.6))
          && !ec.contains(Vector3d(2.2, 1.5, 0)));

    // Against the independent 2D distance: in the plane z = 0 of a 2D run's
    // ellipse (unit depth, h = 0.5: inside, the caps bound the depth), of a
    // tall one (the 2D distance itself), and everywhere in 3D.
    std::mt19937                           rng(11);
    std::uniform_real_distribution<double> u(-1., 1.);
    double                                 err_2d = 0., err_3d = 0.;
    int                                    disagree = 0;
    for (const double hz : {0.5, 100.})
      {
        const EllipticCylinder slab(a, b, hz);
        for (int i = 0; i < 1000; ++i)
          {
            const double x = 2. * a * u(rng), y = 2. * b * u(rng);
            const double d2 = brute_ellipse_distance(a, b, x, y);
            err_2d          = std::max(err_2d,
                              std::abs(slab.signed_distance(Vector3d(x, y, 0))
                                       - std::max(d2, -hz)));
          }
      }
    for (int i = 0; i < 1000; ++i)
      {
        const Vector3d p(2. * a * u(rng), 2. * b * u(rng), 2. * h * u(rng));
        const double   dr = brute_ellipse_distance(a, b, p[0], p[1]);
        const double   dz = std::abs(p[2]) - h;
        const double   exact
          = dr > 0. && dz > 0. ? std::hypot(dr, dz) : std::max(dr, dz);
        err_3d = std::max(err_3d, std::abs(ec.signed_distance(p) - exact));
        disagree += ec.contains(p) != (exact <= 0.);
      }
    std::cout << "elliptic cylinder vs sampled ellipse distance: max error "
              << err_2d << " (z = 0), " << err_3d << " (3D)\n";
    CHECK_MSG(err_2d < 1e-12,
              "elliptic cylinder: 2D ellipse distance at z = 0");
    CHECK_MSG(err_3d < 1e-12, "elliptic cylinder: 3D distance");
    CHECK(disagree == 0);

    // The semi-axes may come in either order: (b, a) is (a, b) turned by 90
    // degrees about z.
    const EllipticCylinder turned(b, a, h);
    double                 turn_diff = 0.;
    for (int i = 0; i < 1000; ++i)
      {
        const Vector3d p(3. * u(rng), 3. * u(rng), 2. * u(rng));
        Vector3d       n, m;
        const double   d = ec.signed_distance(p, &n);
        const double e = turned.signed_distance(Vector3d(p[1], p[0], p[2]), &m);
        turn_diff      = std::max({turn_diff,
                                   std::abs(d - e),
                                   (Vector3d(m[1], m[0], m[2]) - n).norm()});
      }
    CHECK_MSG(turn_diff < 1e-15, "elliptic cylinder with swapped semi-axes");

    // Equal semi-axes: the circular cylinder.
    const EllipticCylinder round(1.2, 1.2, 0.7);
    const Cylinder         cyl(1.2, 0.7);
    double                 cyl_diff = 0.;
    for (int i = 0; i < 5000; ++i)
      {
        Vector3d p(2. * u(rng), 2. * u(rng), 1.5 * u(rng));
        if (i % 10 == 0)
          p[0] = p[1] = 0.; // on the axis
        Vector3d     n, m;
        const double d = round.signed_distance(p, &n),
                     e = cyl.signed_distance(p, &m);
        cyl_diff       = std::max({cyl_diff, std::abs(d - e), (n - m).norm()});
      }
    std::cout << "elliptic cylinder with a = b vs cylinder: max difference "
              << cyl_diff << "\n";
    CHECK_MSG(cyl_diff < 1e-12, "elliptic cylinder with a = b = cylinder");

    // Normal = gradient: at chosen points of each region and at random
    // points away from the kinks of the distance (inside: where side and
    // cap are equally near, the medial plane z = 0 near the centre and the
    // medial segment of the ellipse on the major axis).
    check_gradient(ec, Vector3d(2.8, 1.1, 1.9), "elliptic cylinder rim");
    check_gradient(ec, Vector3d(2.1, -1.9, 0.4), "elliptic cylinder side");
    check_gradient(ec, Vector3d(0.3, 0.2, -1.7), "elliptic cylinder cap");
    check_gradient(ec, Vector3d(2.2, 0.9, 0.1), "elliptic cylinder inside");
    double grad_err = 0.;
    int    checked  = 0;
    for (int i = 0; i < 4000; ++i)
      {
        const Vector3d p(4. * u(rng), 3. * u(rng), 2.5 * u(rng));
        const double   side = brute_ellipse_distance(a, b, p[0], p[1]);
        const double   cap  = std::abs(p[2]) - h;
        if (side < 0. && cap < 0.
            && (std::abs(side - cap) < 1e-4 || std::abs(p[1]) < 1e-4
                || std::abs(p[2]) < 1e-4))
          continue;
        Vector3d     n, g;
        const double fd = 1e-6;
        ec.signed_distance(p, &n);
        for (int k = 0; k < 3; ++k)
          {
            Vector3d e = Vector3d::Zero();
            e[k]       = fd;
            g[k]       = (ec.signed_distance(p + e) - ec.signed_distance(p - e))
                   / (2. * fd);
          }
        grad_err
          = std::max({grad_err, (n - g).norm(), std::abs(n.norm() - 1.)});
        ++checked;
      }
    std::cout << "elliptic cylinder: |normal - FD gradient| <= " << grad_err
              << " at " << checked << " points\n";
    CHECK_MSG(grad_err < 1e-6, "elliptic cylinder normal = gradient");

    bool threw = false;
    try
      {
        EllipticCylinder(1., 0., 1.);
      }
    catch (const GeometryError &)
      {
        threw = true;
      }
    CHECK_MSG(threw, "a zero semi-axis must throw");
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
