// The sanity checks of the bodies after a coupled step (BodyStateGuard), in
// the unit box with a contact distance of 0.01 m:
// - a position or velocity that is not finite stops the run;
// - a sphere of radius 0.1 m that moved 0.3 m in a step (more than its
//   diameter) stops it, with the time step that its speed allows; 0.15 m
//   does not;
// - a sphere 0.05 m past the floor (a wall) stops it; 0.005 m does not
//   (within the contact distance);
// - a spheroid (semi-axes 0.3, 0.05, 0.05 m) tilted by 45 degrees whose
//   lowest point is 0.005 m above the floor passes: its reach is its
//   support point, where its tilted bounding box would reach 0.027 m past
//   the floor;
// - a sphere given as a surface mesh (an icosphere of radius 0.1 m, 1 280
//   triangles), turned by 45 degrees, whose lowest vertex is 0.005 m above
//   the floor passes: its reach is that vertex, where its turned bounding
//   box would reach 0.066 m past the floor (a mesh body falling into a
//   basket was stopped so);
// - a centre beyond a face that is not a wall stops the run ("left the
//   domain"); on a mirror plane it does not;
// - a fixed body is not checked;
// - a body whose motion the case gives (immovable in the engine) is checked
//   by check_given_motions(): a hinged sphere 0.05 m past the floor stops
//   the run naming its motion, 0.005 m does not; a prescribed one whose
//   centre is beyond an open face has left the domain; a fixed particle is
//   not checked there either;
// - two spheres of radius 0.1 m in the engine's contact graph that overlap
//   by 0.005 m (2.5 % of the size 0.2 m) pass; by 0.02 m (10 %, beyond the
//   5 % limit) they stop the run, naming both particles.

#include <particulate/fbm/body_state_guard.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/mapped_surface.h>
#include <particulate/geometry/mesh_body.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/sphere.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

using namespace particulate;

namespace {
  int failures = 0;

  void
  check(const bool ok, const std::string &what)
  {
    if (!ok)
      {
        std::cerr << "FAILED: " << what << std::endl;
        ++failures;
      }
  }

  /** The message check_step() throws, or "" if the state passes. */
  std::string
  verdict(const fbm::BodyStateGuard &guard, const rigid::World &world)
  {
    try
      {
        guard.check_step(world, 1., 0.01);
      }
    catch (const std::runtime_error &e)
      {
        return e.what();
      }
    return "";
  }

  void
  expect(const fbm::BodyStateGuard &guard,
         const rigid::World        &world,
         const std::string         &what,
         const std::string         &expected)
  {
    const std::string message = verdict(guard, world);
    std::cout << what << ": " << (message.empty() ? "passes" : message)
              << std::endl;
    if (expected.empty())
      check(message.empty(), what + ": stopped: " + message);
    else
      check(message.find(expected) != std::string::npos,
            what + ": expected '" + expected + "', got '" + message + "'");
  }

  struct Scene
  {
    rigid::World   world;
    rigid::BodyId  id;
    fbm::DomainBox domain;

    explicit Scene(std::shared_ptr<const geometry::Shape> shape,
                   const bool                             fixed = false)
    {
      const unsigned int material = world.add_material(rigid::Material());
      id                          = world.add_body(shape,
                          material,
                          Eigen::Vector3d(0.5, 0.5, 0.5),
                          Eigen::Quaterniond::Identity(),
                          fixed);
      domain.lower                = Eigen::Vector3d::Zero();
      domain.upper                = Eigen::Vector3d::Ones();
      domain.walls = {{false, false, false, false, true, false}}; // z- only
    }

    fbm::BodyStateGuard
    guard() const
    {
      return fbm::BodyStateGuard(domain, {id}, 0.01);
    }

    rigid::RigidBody &
    body()
    {
      return world.body(id);
    }
  };
} // namespace



int
main()
{
  const auto sphere = std::make_shared<geometry::Sphere>(0.1);
  {
    Scene               s(sphere);
    fbm::BodyStateGuard guard = s.guard();
    guard.start_step(s.world);
    expect(guard, s.world, "at rest", "");
    s.body().linear_velocity[0] = std::numeric_limits<double>::quiet_NaN();
    expect(guard, s.world, "NaN velocity", "no longer finite");
    s.body().linear_velocity[0] = 0.;
    s.body().position[1]        = std::numeric_limits<double>::infinity();
    expect(guard, s.world, "infinite position", "no longer finite");
  }
  {
    Scene               s(sphere);
    fbm::BodyStateGuard guard = s.guard();
    guard.start_step(s.world);
    s.body().position[0] += 0.15;
    expect(guard, s.world, "moved 0.15 m", "");
    s.body().position[0] += 0.15;
    // 0.3 m in dt = 0.01 s: 30 m/s, size 0.2 m: below 0.2/30 s
    expect(guard,
           s.world,
           "moved 0.3 m",
           "a time step below size / speed = 0.00666667 s");
  }
  {
    Scene               s(sphere);
    fbm::BodyStateGuard guard = s.guard();
    s.body().position[2]      = 0.095;
    guard.start_step(s.world);
    expect(guard, s.world, "0.005 m past the floor", "");
    s.body().position[2] = 0.05;
    expect(guard, s.world, "0.05 m past the floor", "crossed the wall z-");
    // the same past the ceiling, which is not a wall: only its centre counts
    s.body().position[2] = 0.95;
    guard.start_step(s.world);
    expect(guard, s.world, "0.05 m past the open ceiling", "");
    s.body().position[2] = 1.02;
    expect(guard, s.world, "centre past the open ceiling", "left the domain");
    s.domain.mirror_planes[5]    = true;
    fbm::BodyStateGuard mirrored = s.guard();
    mirrored.start_step(s.world);
    expect(mirrored, s.world, "centre on a mirror plane", "");
  }
  {
    const Eigen::Vector3d semi_axes(0.3, 0.05, 0.05);
    Scene                 s(std::make_shared<geometry::Ellipsoid>(semi_axes));
    const double          angle = M_PI / 4.;
    s.body().orientation
      = Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()));
    // the lowest point of the tilted spheroid, 0.005 m above the floor
    const double reach
      = std::sqrt(std::pow(semi_axes[0] * std::sin(angle), 2)
                  + std::pow(semi_axes[2] * std::cos(angle), 2));
    s.body().position[2]      = reach + 0.005;
    fbm::BodyStateGuard guard = s.guard();
    guard.start_step(s.world);
    check(std::abs(fbm::body_reach(s.body(), 2, false) - 0.005) < 1e-12,
          "the spheroid's lowest point");
    expect(guard, s.world, "tilted spheroid above the floor", "");
  }
  {
    const geometry::MeshBody mesh_sphere
      = geometry::make_mesh_body(geometry::mesh_generators::icosphere(0.1, 3),
                                 geometry::MeshBodyOptions(),
                                 "icosphere");
    Scene s(mesh_sphere.shape);
    s.body().orientation = Eigen::Quaterniond(
      Eigen::AngleAxisd(M_PI / 4., Eigen::Vector3d(1., 1., 0.).normalized()));
    double lowest = 0.;
    for (const Eigen::Vector3d &v : mesh_sphere.shape->surface_points())
      lowest = std::min(lowest, (s.body().orientation * v)[2]);
    s.body().position[2]      = 0.005 - lowest;
    fbm::BodyStateGuard guard = s.guard();
    guard.start_step(s.world);
    check(std::abs(fbm::body_reach(s.body(), 2, false) - 0.005) < 1e-12,
          "the mesh sphere's lowest vertex");
    expect(guard, s.world, "turned mesh sphere above the floor", "");
  }
  {
    Scene               s(sphere, true);
    fbm::BodyStateGuard guard = s.guard();
    guard.start_step(s.world);
    s.body().position[2] = -1.;
    expect(guard, s.world, "fixed body below the floor", "");
  }
  {
    const auto given = [&](const fbm::ParticleMotion motion,
                           const Eigen::Vector3d    &position,
                           const std::string        &what,
                           const std::string        &expected) {
      Scene                     s(sphere, true);
      const fbm::BodyStateGuard guard(s.domain, {s.id}, 0.01, {motion});
      s.body().position = position;
      std::string message;
      try
        {
          guard.check_given_motions(s.world, 0.5);
        }
      catch (const std::runtime_error &e)
        {
          message = e.what();
        }
      std::cout << what << ": " << (message.empty() ? "passes" : message)
                << std::endl;
      check(expected.empty() ? message.empty() :
                               message.find(expected) != std::string::npos,
            what + ": expected '" + expected + "', got '" + message + "'");
    };
    given(fbm::ParticleMotion::hinged,
          Eigen::Vector3d(0.5, 0.5, 0.05),
          "hinged sphere 0.05 m past the floor",
          "Particle 0 (Motion = hinged) reaches 0.05 m beyond the wall z- "
          "at t = 0.5 s");
    given(fbm::ParticleMotion::hinged,
          Eigen::Vector3d(0.5, 0.5, 0.095),
          "hinged sphere 0.005 m past the floor",
          "");
    given(fbm::ParticleMotion::prescribed,
          Eigen::Vector3d(1.05, 0.5, 0.5),
          "prescribed sphere beyond the open face x+",
          "Particle 0 left the domain at t = 0.5 s: its centre is at x = "
          "1.05 m, beyond the face x+ at 1 m, which is not a wall. Nothing "
          "stops a body whose motion the case gives");
    given(fbm::ParticleMotion::fixed,
          Eigen::Vector3d(0.5, 0.5, -1.),
          "fixed particle below the floor",
          "");
  }
  {
    rigid::WorldParameters parameters;
    parameters.gravity = Eigen::Vector3d::Zero();
    rigid::World       world(parameters);
    const unsigned int material = world.add_material(rigid::Material());
    const auto         add      = [&](const double x) {
      return world.add_body(sphere,
                            material,
                            Eigen::Vector3d(x, 0.5, 0.5),
                            Eigen::Quaterniond::Identity(),
                            false);
    };
    const rigid::BodyId a = add(0.3), b = add(0.5);
    world.step(1e-6); // the touching pair enters the contact graph
    fbm::BodyStateGuard guard(fbm::DomainBox{Eigen::Vector3d::Zero(),
                                             Eigen::Vector3d::Ones(),
                                             {},
                                             {},
                                             3},
                              {a, b},
                              0.01);
    world.body(b).position[0] = 0.495;
    guard.start_step(world);
    expect(guard, world, "spheres overlapping by 0.005 m", "");
    world.body(b).position[0] = 0.48;
    expect(guard,
           world,
           "spheres overlapping by 0.02 m",
           "Particles 0 and 1 overlap by 0.02 m");
  }
  std::cout << (failures == 0 ? "OK" : "FAILED") << std::endl;
  return failures == 0 ? 0 : 1;
}
