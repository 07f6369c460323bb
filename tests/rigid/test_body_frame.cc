// A rigid body takes its mass properties from its geometry::Shape:
// - a surface mesh of a ball centred at the origin becomes a dynamic body
//   whose mass and principal moments are the exact polyhedron's times the
//   density (1e-12);
// - the same mesh moved off the origin is refused with a message naming the
//   principal frame, since the body frame must be centred at the centroid;
// - a torus, whose mass properties are known in closed form, is accepted;
// - a half-space is accepted only as a fixed body.
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/torus.h>
#include <particulate/geometry/triangulated_surface.h>
#include <particulate/rigid/world.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "test_tools.h"

using namespace particulate;

namespace {
  /** Whether adding @p shape as a body throws a message containing
   *  @p needle. */
  bool
  refused(std::shared_ptr<const geometry::Shape> shape,
          const bool                             fixed,
          const std::string                     &needle)
  {
    rigid::World world;
    world.add_material(rigid::Material{});
    try
      {
        world.add_body(shape,
                       0,
                       Eigen::Vector3d::Zero(),
                       Eigen::Quaterniond::Identity(),
                       fixed);
      }
    catch (const std::invalid_argument &e)
      {
        std::cout << "expected error: " << e.what() << "\n";
        return std::string(e.what()).find(needle) != std::string::npos;
      }
    return false;
  }
} // namespace

int
main()
{
  const geometry::TriangleMesh ball
    = geometry::mesh_generators::icosphere(0.01, 3);
  const auto centred = std::make_shared<geometry::TriangulatedSurface>(ball);

  rigid::World    world;
  rigid::Material glass;
  glass.density = 2500.;
  world.add_material(glass);
  const rigid::BodyId id = world.add_body(centred, 0, Eigen::Vector3d(0, 0, 1));
  const rigid::RigidBody &b = world.body(id);
  std::cout << "mesh ball: mass " << b.mass() << " kg (exact polyhedron "
            << 2500. * centred->volume() << "), moments "
            << b.principal_inertia().transpose() << "\n";
  CHECK(rel_diff(b.mass(), 2500. * centred->volume()) < 1e-12, "mass");
  for (int k = 0; k < 3; ++k)
    CHECK(rel_diff(b.principal_inertia()[k],
                   2500. * centred->unit_inertia()(k, k))
            < 1e-12,
          "principal moment " << k);

  geometry::TriangleMesh moved = ball;
  for (auto &v : moved.vertices)
    v += Eigen::Vector3d(0.003, 0., 0.);
  CHECK(refused(std::make_shared<geometry::TriangulatedSurface>(moved),
                false,
                "principal frame"),
        "a mesh off its centroid must be refused as a dynamic body");
  CHECK(!refused(std::make_shared<geometry::TriangulatedSurface>(moved),
                 true,
                 ""),
        "a fixed body needs no mass properties");

  CHECK(!refused(std::make_shared<geometry::Torus>(0.1, 0.03), false, ""),
        "a torus is a dynamic body");
  const auto floor
    = std::make_shared<geometry::HalfSpace>(Eigen::Vector3d::UnitZ(), 0.);
  CHECK(refused(floor, false, "fixed body"), "a free half-space");
  CHECK(!refused(floor, true, ""), "a fixed half-space");
  std::cout << "OK\n";
  return 0;
}
