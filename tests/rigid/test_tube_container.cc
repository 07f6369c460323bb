// A cylindrical container: geometry::Tube, a thick-walled pipe around the
// body z axis, as a fixed body whose bore holds the other bodies (the
// mantle of a fluidized-bed column).
// - Its signed distance is the closed form in the bore (r_i - rho), inside
//   the wall and beyond its ends (distance to the rim), and its normal is
//   the gradient (central differences, 1e-6).
// - Its volume and inertia equal those of the outer solid cylinder less
//   the bore's.
// - 40 spheres thrown about in the bore above a floor, with every contact
//   solver: no sphere ever reaches farther into the wall than 10 % of its
//   radius, and all come to rest on the floor inside the bore.
// - Without gravity, a sphere thrown at the wall at 1 m/s with restitution
//   0.5 comes back at 0.5 m/s (within 5 %), and a cube thrown at it keeps
//   its corners in the bore (to 10 % of its half edge) and is turned back.
#include <particulate/geometry/box.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/sphere.h>
#include <particulate/geometry/tube.h>

#include <cmath>
#include <random>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

namespace {
  const double ri = 0.05, wall = 0.01, half_length = 0.2;

  void
  check_distance()
  {
    const Tube tube(ri, wall, half_length);
    const auto sd = [&](double x, double y, double z) {
      return tube.signed_distance(Eigen::Vector3d(x, y, z));
    };
    CHECK(std::abs(sd(0.01, 0.02, 0.03) - (ri - std::hypot(0.01, 0.02)))
            < 1e-15,
          "distance in the bore");
    CHECK(std::abs(sd(0., 0.052, 0.) + 0.002) < 1e-15,
          "distance inside the wall, near the bore");
    CHECK(std::abs(sd(0.058, 0., 0.19) + 0.002) < 1e-15,
          "distance inside the wall, near the outer mantle");
    CHECK(std::abs(sd(0.07, 0., 0.22) - std::hypot(0.01, 0.02)) < 1e-15,
          "distance beyond the outer rim");
    CHECK(std::abs(sd(0.03, 0., -0.23) - std::hypot(0.02, 0.03)) < 1e-15,
          "distance beyond the inner rim");

    std::mt19937                           random(7);
    std::uniform_real_distribution<double> coordinate(-0.08, 0.08);
    double                                 worst = 0.;
    for (int i = 0; i < 2000; ++i)
      {
        const Eigen::Vector3d p(coordinate(random),
                                coordinate(random),
                                3. * coordinate(random));
        Eigen::Vector3d       n;
        tube.signed_distance(p, &n);
        Eigen::Vector3d gradient;
        for (int d = 0; d < 3; ++d)
          {
            Eigen::Vector3d e = Eigen::Vector3d::Zero();
            e[d]              = 1e-6;
            gradient[d]
              = (tube.signed_distance(p + e) - tube.signed_distance(p - e))
                / 2e-6;
          }
        worst = std::max(worst, (gradient - n).norm());
      }
    std::cout << "largest |normal - gradient|: " << worst << "\n";
    // a point within 1e-6 of a ridge of the distance has a one-sided
    // difference; 2000 random points avoid them
    CHECK(worst < 1e-6, "the normal is the gradient");

    const Cylinder outer(ri + wall, half_length), bore(ri, half_length);
    CHECK(std::abs(tube.volume() - (outer.volume() - bore.volume()))
            < 1e-12 * tube.volume(),
          "volume");
    CHECK((tube.unit_inertia() - (outer.unit_inertia() - bore.unit_inertia()))
              .norm()
            < 1e-12 * tube.unit_inertia().norm(),
          "inertia");
  }

  /** A world with a floor at z = 0 and the tube standing on it. */
  World
  container(const ContactSolverType type,
            const Eigen::Vector3d  &gravity,
            const double            restitution)
  {
    WorldParameters prm;
    prm.contact_solver = type;
    prm.gravity        = gravity;
    World    w(prm);
    Material m;
    m.restitution     = restitution;
    m.static_friction = m.dynamic_friction = 0.2;
    w.add_material(m);
    add_floor(w);
    w.add_body(std::make_shared<Tube>(ri, wall, half_length),
               0,
               Eigen::Vector3d(0., 0., half_length),
               Eigen::Quaterniond::Identity(),
               true);
    return w;
  }

  void
  check_spheres_stay_in_the_bore(const ContactSolverType type)
  {
    World        w = container(type, Eigen::Vector3d(0., 0., -9.81), 0.);
    const double r = 0.008;
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(-1., 1.);
    std::vector<BodyId>                    spheres;
    for (int i = 0; i < 40; ++i)
      {
        // four to a layer, the layers 2.5 radii apart and turned
        const double a  = M_PI / 2. * (i % 4) + 0.4 * (i / 4);
        const BodyId id = w.add_body(std::make_shared<Sphere>(r),
                                     0,
                                     Eigen::Vector3d(0.03 * std::cos(a),
                                                     0.03 * std::sin(a),
                                                     0.02 + 2.5 * r * (i / 4)));
        w.body(id).linear_velocity
          = Eigen::Vector3d(unit(random), unit(random), 0.);
        spheres.push_back(id);
      }
    double deepest = 0.;
    for (int step = 0; step < 3000; ++step)
      {
        w.step(1e-3);
        for (const BodyId id : spheres)
          {
            const Eigen::Vector3d &x = w.body(id).position;
            deepest = std::max(deepest, std::hypot(x[0], x[1]) + r - ri);
          }
      }
    double fastest = 0., highest = 0.;
    for (const BodyId id : spheres)
      {
        fastest = std::max(fastest, w.body(id).linear_velocity.norm());
        highest = std::max(highest, w.body(id).position[2]);
      }
    std::cout << to_string(type) << ": deepest reach into the wall " << deepest
              << " m, fastest sphere at the end " << fastest
              << " m/s, highest centre " << highest << " m\n";
    CHECK(deepest < 0.1 * r, "the spheres stay in the bore");
    CHECK(fastest < 0.01, "the spheres come to rest");
    CHECK(highest < half_length, "the spheres rest in the tube");
  }

  void
  check_bounce(const ContactSolverType type)
  {
    World        w    = container(type, Eigen::Vector3d::Zero(), 0.5);
    const BodyId ball = w.add_body(std::make_shared<Sphere>(0.01),
                                   0,
                                   Eigen::Vector3d(0., 0., 0.1));
    w.body(ball).linear_velocity = Eigen::Vector3d(1., 0., 0.);
    const double half_edge       = 0.01;
    const BodyId cube
      = w.add_body(std::make_shared<Box>(Eigen::Vector3d::Constant(half_edge)),
                   0,
                   Eigen::Vector3d(0., 0., 0.3));
    w.body(cube).linear_velocity = Eigen::Vector3d(0., 1., 0.);
    // both meet the wall after 0.04 s and are halfway back across the
    // bore after 0.1 s
    double corner_reach = 0.;
    for (int step = 0; step < 100; ++step)
      {
        w.step(1e-3);
        const RigidBody &b = w.body(cube);
        for (int c = 0; c < 8; ++c)
          {
            const Eigen::Vector3d corner
              = b.position
                + b.orientation
                    * Eigen::Vector3d((c & 1 ? 1 : -1) * half_edge,
                                      (c & 2 ? 1 : -1) * half_edge,
                                      (c & 4 ? 1 : -1) * half_edge);
            corner_reach
              = std::max(corner_reach, std::hypot(corner[0], corner[1]) - ri);
          }
      }
    const double back = w.body(ball).linear_velocity[0];
    std::cout << to_string(type) << ": sphere back at " << back
              << " m/s, cube's corners at most " << corner_reach
              << " m into the wall, cube's velocity "
              << w.body(cube).linear_velocity.transpose() << "\n";
    CHECK(std::abs(back + 0.5) < 0.025, "the sphere bounces with e = 0.5");
    CHECK(corner_reach < 0.1 * half_edge, "the cube stays in the bore");
    CHECK(w.body(cube).linear_velocity[1] < 0.,
          "the cube was turned back by the wall");
  }
} // namespace

int
main()
{
  check_distance();
  for (const auto type : all_solvers())
    check_spheres_stay_in_the_bore(type);
  for (const auto type : {ContactSolverType::projected_gauss_seidel,
                          ContactSolverType::sequential_impulses})
    check_bounce(type);
  std::cout << "OK\n";
  return 0;
}
