// The display triangulations of the shapes (Shape::surface_mesh(), what the
// bodies' ParaView output draws):
// - every vertex lies on the surface: |signed distance| <= 1e-12 of the
//   shape's size for the analytic shapes, within the map's trilinear error
//   (h^2 / R for a sphere, bound 0.05 h here) for a distance map through the
//   default projection;
// - the triangulation is closed and outward: every edge is shared by exactly
//   two triangles in opposite directions, and the volume it encloses
//   (divergence theorem) is positive and below the convex solid's volume,
//   which it approaches to the inscribed polyhedron's deficit: exact for the
//   box; (2 pi / n)^2 / 6 for an n-gon section, 0.29 % for the 48-sided
//   prisms, 1 % for the capsule (32 segments around, 16 rings over each
//   hemisphere), 1.4 % for the torus (a 24-gon tube on a 48-gon path); the
//   icospheres lose 3.4 % at 320 triangles (sphere) and 0.9 % at 1280
//   (ellipsoid); bounds 4 % and 1 %.
#include <particulate/geometry/box.h>
#include <particulate/geometry/capsule.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/distance_map_shape.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/elliptic_cylinder.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/mass_properties.h>
#include <particulate/geometry/sphere.h>
#include <particulate/geometry/torus.h>

#include <cmath>
#include <map>
#include <memory>
#include <utility>

#include "check.h"

using namespace particulate::geometry;
using Eigen::Vector3d;

namespace {
  /** Each directed edge once, and its reverse present: closed and
   *  consistently oriented. */
  bool
  is_closed_and_oriented(const TriangleMesh &mesh)
  {
    std::map<std::pair<int, int>, int> edges;
    for (const auto &t : mesh.triangles)
      for (int k = 0; k < 3; ++k)
        ++edges[{t[k], t[(k + 1) % 3]}];
    for (const auto &[edge, count] : edges)
      {
        const auto reverse = edges.find({edge.second, edge.first});
        if (count != 1 || reverse == edges.end() || reverse->second != 1)
          return false;
      }
    return true;
  }

  void
  check_display_mesh(const Shape &shape,
                     const double distance_tolerance,
                     const double volume_tolerance)
  {
    const TriangleMesh mesh = shape.surface_mesh();
    CHECK_MSG(mesh.n_triangles() > 0, shape.name() + ": has triangles");
    double worst = 0.;
    for (const Vector3d &v : mesh.vertices)
      worst = std::max(worst, std::abs(shape.signed_distance(v)));
    CHECK_MSG(worst <= distance_tolerance * shape.bounding_radius(),
              shape.name() + ": vertices on the surface (worst "
                + std::to_string(worst) + ")");
    CHECK_MSG(is_closed_and_oriented(mesh),
              shape.name() + ": closed and consistently oriented");
    const double enclosed = compute_mass_properties(mesh).volume;
    const double exact    = shape.volume();
    CHECK_MSG(enclosed > 0. && enclosed <= exact * (1. + 1e-12)
                && enclosed >= exact * (1. - volume_tolerance),
              shape.name() + ": enclosed volume " + std::to_string(enclosed)
                + " against " + std::to_string(exact));
  }
} // namespace

int
main()
{
  check_display_mesh(Sphere(0.7), 1e-12, 0.04);
  check_display_mesh(Ellipsoid(Vector3d(1., 0.5, 0.3)), 1e-12, 0.01);
  check_display_mesh(Box(Vector3d(1., 0.4, 0.2)), 1e-12, 1e-12);
  check_display_mesh(Cylinder(0.5, 1.5), 1e-12, 0.003);
  check_display_mesh(EllipticCylinder(1., 0.5, 0.5), 1e-12, 0.003);
  check_display_mesh(Capsule(0.3, 0.8), 1e-12, 0.01);
  // not convex, but inscribed too: a polygonal tube on a polygonal path
  check_display_mesh(Torus(1., 0.3), 1e-12, 0.02);

  // The default: a sphere's distance map, the display mesh projected onto
  // its zero level (vertices within the trilinear error).
  {
    const Sphere           sphere(1.);
    const double           h   = 0.05;
    const DistanceMap      map = DistanceMap::build(sphere, {h, 0.2, 2});
    const DistanceMapShape shape(std::make_shared<const DistanceMap>(map));
    const TriangleMesh     mesh  = shape.surface_mesh();
    double                 worst = 0.;
    for (const Vector3d &v : mesh.vertices)
      worst = std::max(worst, std::abs(sphere.signed_distance(v)));
    CHECK_MSG(worst <= 0.05 * h,
              "distance map: vertices on the sphere (worst "
                + std::to_string(worst) + ")");
    CHECK(is_closed_and_oriented(mesh));
  }

  CHECK(HalfSpace(Vector3d(0., 0., 1.), 0.).surface_mesh().n_triangles() == 0);
  return test::finish("geometry_surface_mesh");
}
