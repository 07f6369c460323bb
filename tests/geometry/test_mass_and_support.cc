// The mass properties, support functions, normals and closest points that the
// rigid engine reads from geometry::Shape (thesis §3.4.2, §4.2.2):
// - volume and principal moments of every analytic solid against Monte Carlo
//   integration of its indicator {signed_distance < 0}: 1 % and 1.5 % (the
//   Monte Carlo error with 4e5 samples is about 0.3 %);
// - the exact polyhedron of a surface mesh of the same ellipsoid: its
//   centroid, inertia and volume from the divergence theorem agree with the
//   analytic ellipsoid to the mesh's resolution (2 %);
// - support points lie on the surface and beat every surface sample;
// - the normal is a unit vector along which the distance grows at rate 1;
// - closest points lie on the surface at the distance's length from p;
// - the elliptic cylinder: volume and inertia against the exact polyhedral
//   mass properties of the inscribed prism over an 8192-gon (relative error
//   of the polygon at most (2 pi / n)^2 / 3 = 2e-7; tolerance 1e-6), its
//   support against the maximum over 2 x 20000 rim points (never beaten,
//   above it by at most the sampling error max(a, b) dphi^2 / 8) and along
//   the axis.
#include <particulate/geometry/box.h>
#include <particulate/geometry/capsule.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/elliptic_cylinder.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/mass_properties.h>
#include <particulate/geometry/mesh_generators.h>
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

namespace {
  double
  rel_diff(const double a, const double b)
  {
    const double s = std::max(std::abs(a), std::abs(b));
    return s > 0. ? std::abs(a - b) / s : 0.;
  }

  /** Volume and principal moments by Monte Carlo over the bounding cube. */
  void
  check_mass_properties(const Shape &s, std::mt19937 &rng)
  {
    const double                           R = s.bounding_radius();
    std::uniform_real_distribution<double> u(-R, R);
    const int                              n      = 400000;
    double                                 inside = 0.;
    Vector3d                               second = Vector3d::Zero();
    for (int i = 0; i < n; ++i)
      {
        const Vector3d p(u(rng), u(rng), u(rng));
        if (s.signed_distance(p) < 0.)
          {
            inside += 1.;
            second += p.cwiseAbs2();
          }
      }
    const double cube = 8. * R * R * R;
    const double V_mc = inside / n * cube;
    second *= cube / n;
    const Vector3d        I_mc(second[1] + second[2],
                        second[0] + second[2],
                        second[0] + second[1]);
    const Eigen::Matrix3d I = s.unit_inertia();
    std::cout << s.name() << ": V = " << s.volume() << " (MC " << V_mc
              << "), I = " << I.diagonal().transpose() << " (MC "
              << I_mc.transpose() << ")\n";
    CHECK_MSG(rel_diff(V_mc, s.volume()) < 0.01, s.name() + " volume");
    for (int k = 0; k < 3; ++k)
      CHECK_MSG(rel_diff(I_mc[k], I(k, k)) < 0.015,
                s.name() + " inertia " + std::to_string(k));
    CHECK_MSG((I - Eigen::Matrix3d(I.diagonal().asDiagonal())).norm() == 0.,
              s.name() + " inertia not diagonal in the body frame");
    CHECK_MSG(s.centroid().norm() == 0., s.name() + " centroid");
  }

  void
  check_support(const Shape &s, std::mt19937 &rng)
  {
    std::normal_distribution<double> g;
    const auto                       samples = s.surface_points();
    CHECK_MSG(!samples.empty(), s.name() + " has no surface points");
    for (int i = 0; i < 200; ++i)
      {
        const Vector3d d(g(rng), g(rng), g(rng));
        const Vector3d sp = s.support(d);
        CHECK_MSG(std::abs(s.signed_distance(sp)) < 1e-9,
                  s.name() + " support point off the surface");
        for (const auto &q : samples)
          CHECK_MSG(d.dot(q) <= d.dot(sp) + 1e-12,
                    s.name() + " support beaten by a surface point");
        for (const auto &q : samples)
          CHECK_MSG(std::abs(s.signed_distance(q)) < 1e-12,
                    s.name() + " surface point off the surface");
      }
  }

  void
  check_normal_and_closest_point(const Shape &s, std::mt19937 &rng)
  {
    const double                           R = s.bounding_radius();
    std::uniform_real_distribution<double> u(-R, R);
    for (int i = 0; i < 200; ++i)
      {
        const Vector3d p(u(rng), u(rng), u(rng));
        Vector3d       n;
        const double   d = s.signed_distance(p, &n);
        CHECK_MSG(std::abs(n.norm() - 1.) < 1e-9, s.name() + " |normal|");
        const double h = 1e-7;
        const double fd
          = (s.signed_distance(p + h * n) - s.signed_distance(p - h * n))
            / (2. * h);
        CHECK_MSG(fd > 0.99, s.name() + " normal direction");
        const Vector3d c = s.closest_point(p);
        CHECK_MSG(std::abs(s.signed_distance(c)) < 1e-9 * R,
                  s.name() + " closest point off the surface");
        CHECK_MSG(std::abs((p - c).norm() - std::abs(d)) < 1e-9 * R,
                  s.name() + " closest point not at the distance");
      }
  }
} // namespace

int
main()
{
  std::mt19937                              rng(42);
  const std::vector<std::shared_ptr<Shape>> convex
    = {std::make_shared<Sphere>(0.7),
       std::make_shared<Box>(Vector3d(0.3, 0.5, 0.9)),
       std::make_shared<Cylinder>(0.4, 0.8),
       std::make_shared<Ellipsoid>(Vector3d(0.9, 0.5, 0.3)),
       std::make_shared<Capsule>(0.35, 0.6),
       std::make_shared<EllipticCylinder>(0.6, 0.25, 0.4)};
  for (const auto &s : convex)
    {
      CHECK_MSG(s->is_convex() && s->is_bounded(), s->name() + " convex");
      check_mass_properties(*s, rng);
      check_support(*s, rng);
      check_normal_and_closest_point(*s, rng);
    }

  // Elliptic cylinder: exact polyhedral mass properties of the prism over
  // the 8192-gon inscribed in the ellipse, and the support function against
  // dense rim samples.
  {
    const double           a = 0.6, b = 0.25, h = 0.4;
    const EllipticCylinder ec(a, b, h);
    CHECK(ec.kind() == ShapeKind::general && ec.name() == "elliptic cylinder");
    CHECK(std::abs(ec.bounding_radius() - std::hypot(a, h)) < 1e-15);
    const int                       n = 8192;
    std::vector<Vector3d>           v;
    std::vector<std::array<int, 3>> t;
    for (int k = 0; k < n; ++k)
      {
        const double phi = 2. * M_PI * k / n;
        v.emplace_back(a * std::cos(phi), b * std::sin(phi), -h);
        v.emplace_back(a * std::cos(phi), b * std::sin(phi), h);
      }
    v.emplace_back(0., 0., -h);
    v.emplace_back(0., 0., h);
    for (int k = 0; k < n; ++k)
      {
        const int lo = 2 * k, up = 2 * k + 1, lo1 = 2 * ((k + 1) % n),
                  up1 = lo1 + 1;
        t.push_back({lo, lo1, up1});
        t.push_back({lo, up1, up});
        t.push_back({2 * n, lo1, lo});
        t.push_back({2 * n + 1, up, up1});
      }
    const MassProperties  prism = compute_mass_properties(TriangleMesh(v, t));
    const double          V     = ec.volume();
    const Eigen::Matrix3d I     = ec.unit_inertia();
    double                I_err = 0.;
    for (int k = 0; k < 3; ++k)
      I_err = std::max(I_err, rel_diff(prism.inertia(k, k), I(k, k)));
    std::cout << "elliptic cylinder: V = " << V << " (prism " << prism.volume
              << ", relative difference " << rel_diff(prism.volume, V)
              << "), I = " << I.diagonal().transpose() << " (prism "
              << prism.inertia.diagonal().transpose()
              << ", max relative difference " << I_err << ")\n";
    // The prism's volume is the polygon's area (n/2) a b sin(2 pi/n) times
    // 2h: checks the mesh.
    CHECK(
      rel_diff(prism.volume, 0.5 * n * a * b * std::sin(2. * M_PI / n) * 2. * h)
      < 1e-12);
    CHECK(rel_diff(prism.volume, V) < 1e-6);
    CHECK_MSG(I_err < 1e-6, "elliptic cylinder inertia vs the prism");
    CHECK(prism.centre.norm() < 1e-12);
    CHECK((I - Eigen::Matrix3d(I.diagonal().asDiagonal())).norm() == 0.);

    // Support: the rim points beat every sample, along the axis the cap
    // centre.
    std::vector<Vector3d> rim;
    for (int k = 0; k < 20000; ++k)
      {
        const double phi = 2. * M_PI * k / 20000.;
        for (const double z : {-h, h})
          rim.emplace_back(a * std::cos(phi), b * std::sin(phi), z);
      }
    std::normal_distribution<double> g;
    double                           support_err = 0.;
    for (int i = 0; i < 500; ++i)
      {
        Vector3d d(g(rng), g(rng), g(rng));
        if (i % 50 == 0)
          d[2] = 0.; // horizontal: a whole generator line is the support
        const Vector3d sp   = ec.support(d);
        double         best = -1e300;
        for (const auto &q : rim)
          best = std::max(best, d.normalized().dot(q));
        const double h_s = d.normalized().dot(sp);
        CHECK_MSG(h_s >= best - 1e-15, "elliptic cylinder support beaten");
        support_err = std::max(support_err, h_s - best);
        CHECK(std::abs(ec.signed_distance(sp)) < 1e-12);
      }
    std::cout << "elliptic cylinder: support exceeds the sampled maximum by "
              << "at most " << support_err << "\n";
    // Samples dphi apart miss the maximum by at most max(a, b) dphi^2 / 8.
    const double dphi = 2. * M_PI / 20000.;
    CHECK_MSG(support_err <= a * dphi * dphi / 8.,
              "elliptic cylinder support vs samples");
    CHECK((ec.support(Vector3d(0, 0, 2)) - Vector3d(0, 0, h)).norm() == 0.);
    CHECK((ec.support(Vector3d(0, 0, -1)) - Vector3d(0, 0, -h)).norm() == 0.);

    // Equal semi-axes: the cylinder's mass properties and support.
    const EllipticCylinder round(0.4, 0.4, 0.8);
    const Cylinder         cyl(0.4, 0.8);
    CHECK(rel_diff(round.volume(), cyl.volume()) < 1e-15);
    CHECK((round.unit_inertia() - cyl.unit_inertia()).norm()
          < 1e-12 * cyl.unit_inertia().norm());
    CHECK(std::abs(round.bounding_radius() - cyl.bounding_radius()) < 1e-15);
    for (int i = 0; i < 100; ++i)
      {
        const Vector3d d(g(rng), g(rng), g(rng));
        CHECK((round.support(d) - cyl.support(d)).norm() < 1e-12);
      }
  }

  // A non-convex solid: mass properties and normals, no support function.
  const Torus torus(0.1, 0.03);
  CHECK(!torus.is_convex() && torus.kind() == ShapeKind::general);
  check_mass_properties(torus, rng);
  check_normal_and_closest_point(torus, rng);
  bool threw = false;
  try
    {
      torus.support(Vector3d::UnitZ());
    }
  catch (const GeometryError &e)
    {
      threw = true;
      std::cout << "expected error: " << e.what() << "\n";
    }
  CHECK_MSG(threw, "a torus has no support function");

  // A surface mesh of an ellipsoid, moved off the origin: its exact
  // polyhedral mass properties match the analytic ellipsoid's.
  {
    const Vector3d  axes(0.9, 0.5, 0.3), shift(0.2, -0.1, 0.05);
    const Ellipsoid exact(axes);
    TriangleMesh    sphere = mesh_generators::icosphere(1., 4);
    for (auto &v : sphere.vertices)
      v = v.cwiseProduct(axes) + shift;
    const TriangulatedSurface mesh(sphere);
    std::cout << "surface mesh: V = " << mesh.volume() << " (ellipsoid "
              << exact.volume() << "), centroid " << mesh.centroid().transpose()
              << "\n";
    CHECK(rel_diff(mesh.volume(), exact.volume()) < 0.02);
    CHECK((mesh.centroid() - shift).norm() < 1e-9);
    for (int k = 0; k < 3; ++k)
      CHECK(rel_diff(mesh.unit_inertia()(k, k), exact.unit_inertia()(k, k))
            < 0.02);
    CHECK(mesh.surface_points().size() == mesh.mesh().n_vertices());
    CHECK(mesh.kind() == ShapeKind::general);
  }

  // Exact point distances.
  CHECK(
    std::abs(Ellipsoid(Vector3d(2, 1, 0.5)).signed_distance(Vector3d(3, 0, 0))
             - 1.)
    < 1e-10);
  CHECK(
    std::abs(Ellipsoid(Vector3d(2, 1, 0.5)).signed_distance(Vector3d(0, 0, 0.2))
             + 0.3)
    < 1e-10);
  CHECK(std::abs(Capsule(0.5, 1.).signed_distance(Vector3d(0, 0, 2.)) - 0.5)
        < 1e-15);
  CHECK(std::abs(Capsule(0.5, 1.).signed_distance(Vector3d(1, 0, 0.3)) - 0.5)
        < 1e-15);
  const HalfSpace floor(Vector3d(0, 0, 2), 1.);
  CHECK(std::abs(floor.signed_distance(Vector3d(5, 5, 3)) - 2.) < 1e-15);
  CHECK(!floor.is_bounded() && std::isinf(floor.bounding_radius()));

  threw = false;
  try
    {
      Box(Vector3d(1, -1, 1));
    }
  catch (const GeometryError &e)
    {
      threw = true;
      std::cout << "expected error: " << e.what() << "\n";
    }
  CHECK_MSG(threw, "a negative box extent must throw");
  return test::finish("geometry_mass_and_support");
}
