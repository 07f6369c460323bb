// Bodies made from surface meshes (geometry::make_mesh_body: exact mass
// properties from the polyhedron, contacts through its distance map, thesis
// §3.4.2) against the same solids given analytically. The mesh is an
// ellipsoid with semi-axes (a, b, c) = (0.02, 0.014, 0.01) m meshed as a
// scaled icosphere (5 120 triangles, vertices about 0.8 h apart), its map at
// the automatic spacing h = c / 8.
// 1. Narrow phase: a sphere of radius 2c above the mesh ellipsoid's top, its
//    centre beyond the map (where the exact surface answers), at gaps 1 mm,
//    0.1 mm and -0.1 mm: the gap to 0.1 h (the map's interpolation error
//    near the surface, geometry_mesh_body), the normal along z.
// 2. Dynamics with both velocity solvers, dt = 1 ms, 2 s:
//    - dropped lying flat 1 mm above the floor, it rests at height c (its
//      vertices against the plane: exact but for the polyhedron's sag);
//    - a mesh box (half extents 0.03, 0.03, 0.01 m, each face split into
//      8 x 8 squares) on the floor with a mesh ellipsoid dropped flat onto
//      it (the vertices of each against the other's map): the box rests at
//      0.01 m, the ellipsoid at 0.02 m + c;
//    each to 0.1 h, and nothing sinks into the floor by more than 0.1 h.
//    (Two ellipsoids stacked would not do: a convex body resting on top of
//    another, each curving away from the contact, is unstable once its
//    centre of mass is higher than the contact's reduced radius of
//    curvature.)
//    - dropped turned by 30 degrees about its long axis, it rocks without
//      slipping (rolling does no work, so it does not settle in 2 s): over
//      the first swing (0.1 s) its tilt follows the analytic ellipsoid's
//      within 2 degrees, and it never swings wider than it started (the
//      vertices' small impacts can only take energy out).
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/mesh_body.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/sphere.h>
#include <particulate/rigid/narrow_phase.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <memory>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

namespace {
  const Eigen::Vector3d semi_axes(0.02, 0.014, 0.01);
  const double          c = semi_axes[2];
  const Eigen::Vector3d box_half_extents(0.03, 0.03, 0.01);

  MeshBody
  box_mesh()
  {
    return make_mesh_body(mesh_generators::box(box_half_extents, 8),
                          MeshBodyOptions(),
                          "the box mesh");
  }

  MeshBody
  ellipsoid_mesh()
  {
    TriangleMesh mesh = mesh_generators::icosphere(1., 4);
    for (auto &v : mesh.vertices)
      v = semi_axes.cwiseProduct(v);
    return make_mesh_body(mesh, MeshBodyOptions(), "the ellipsoid mesh");
  }

  double
  tilt_of(const RigidBody &body)
  {
    const Eigen::Vector3d z = body.orientation * Eigen::Vector3d::UnitZ();
    return std::acos(std::min(1., std::abs(z[2])));
  }

  World
  make_world(const ContactSolverType type)
  {
    WorldParameters prm;
    prm.contact_solver = type;
    World    w(prm);
    Material m;
    m.static_friction = m.dynamic_friction = 0.3;
    w.add_material(m);
    add_floor(w);
    return w;
  }

  void
  check_sphere_above(const MeshBody &mesh)
  {
    const double h = mesh.shape->map().spacing(), r = 2. * c;
    for (const double gap : {1e-3, 1e-4, -1e-4})
      {
        RigidBody E(mesh.shape, 0, 1000., false);
        RigidBody S(std::make_shared<Sphere>(r), 0, 1000., false);
        S.position = Eigen::Vector3d(0., 0., c + r + gap);
        CHECK(!mesh.shape->map().covers(S.position),
              "the sphere's centre lies beyond the map");
        ContactEdge edge;
        NarrowPhase::collide(S, E, 0.002, edge);
        CHECK(edge.manifold.points.size() == 1,
              "one contact point for the sphere at gap " << gap);
        const auto &p = edge.manifold.points.front();
        std::cout << "sphere at gap " << gap << ": gap error "
                  << (p.distance - gap) / h << " h\n";
        CHECK(std::abs(p.distance - gap) < 0.1 * h,
              "sphere above the mesh ellipsoid at gap " << gap);
        CHECK((p.normal + Eigen::Vector3d::UnitZ()).norm() < 1e-3,
              "normal from the sphere to the mesh ellipsoid");
      }
  }
} // namespace

int
main()
{
  const MeshBody mesh = ellipsoid_mesh();
  const double   h    = mesh.shape->map().spacing();
  std::cout << "map spacing h = " << h << " m\n";
  check_sphere_above(mesh);

  const auto               analytic = std::make_shared<Ellipsoid>(semi_axes);
  const Eigen::Quaterniond turned(
    Eigen::AngleAxisd(M_PI / 6., Eigen::Vector3d::UnitX()));
  const MeshBody box  = box_mesh();
  const double   base = box_half_extents[2];
  for (const auto type : {ContactSolverType::projected_gauss_seidel,
                          ContactSolverType::sequential_impulses})
    {
      World        w         = make_world(type);
      World        reference = make_world(type);
      const BodyId flat
        = w.add_body(mesh.shape, 0, Eigen::Vector3d(0., 0., c + 1e-3));
      const BodyId plinth
        = w.add_body(box.shape, 0, Eigen::Vector3d(0.2, 0., base + 1e-3));
      const BodyId upper
        = w.add_body(mesh.shape,
                     0,
                     Eigen::Vector3d(0.2, 0., 2. * base + c + 3e-3));
      const BodyId rolled
        = w.add_body(mesh.shape, 0, Eigen::Vector3d(0.1, 0., 0.02), turned);
      const BodyId rolled_reference
        = reference.add_body(analytic,
                             0,
                             Eigen::Vector3d(0.1, 0., 0.02),
                             turned);
      double first_swing = 0., widest = 0., lowest = 1.;
      for (int step = 0; step < 2000; ++step)
        {
          w.step(1e-3);
          reference.step(1e-3);
          const double tilt = tilt_of(w.body(rolled));
          if (step < 100)
            first_swing
              = std::max(first_swing,
                         std::abs(tilt
                                  - tilt_of(reference.body(rolled_reference))));
          widest = std::max(widest, tilt);
          lowest = std::min(lowest, w.body(flat).position[2]);
          lowest = std::min(lowest, w.body(plinth).position[2] - base + c);
        }
      const auto z = [&](const BodyId i) { return w.body(i).position[2]; };
      std::cout << to_string(type) << ": flat at " << (z(flat) - c) / h
                << " h from c; box at " << (z(plinth) - base) / h
                << " h, the ellipsoid on it at "
                << (z(upper) - 2. * base - c) / h << " h; lowest "
                << (lowest - c) / h
                << " h; rocking: first swing apart by at most "
                << first_swing * 180. / M_PI << " deg, widest "
                << widest * 180. / M_PI << " deg\n";
      CHECK(std::abs(z(flat) - c) < 0.1 * h, "flat mesh ellipsoid height");
      CHECK(std::abs(z(plinth) - base) < 0.1 * h, "mesh box on the floor");
      CHECK(std::abs(z(upper) - 2. * base - c) < 0.1 * h,
            "mesh ellipsoid on a mesh box");
      CHECK(lowest > c - 0.1 * h, "the mesh body sank into the floor");
      CHECK(first_swing < 2. * M_PI / 180.,
            "the mesh ellipsoid rocks as the analytic one");
      CHECK(widest <= M_PI / 6. + 1e-9, "the rocking gained energy");
    }
  std::cout << "OK\n";
  return 0;
}
