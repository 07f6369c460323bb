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
// - closest points lie on the surface at the distance's length from p.
#include <particulate/geometry/box.h>
#include <particulate/geometry/capsule.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/half_space.h>
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
       std::make_shared<Capsule>(0.35, 0.6)};
  for (const auto &s : convex)
    {
      CHECK_MSG(s->is_convex() && s->is_bounded(), s->name() + " convex");
      check_mass_properties(*s, rng);
      check_support(*s, rng);
      check_normal_and_closest_point(*s, rng);
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
