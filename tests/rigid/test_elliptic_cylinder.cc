// The elliptic cylinder (a 2D run's ellipse; semi-axes a = 0.06 m along x,
// b = 0.03 m along y, half height h = 0.02 m), a convex `general` shape that
// the narrow phase meets through its support function (thesis §3.4.2):
// 1. Narrow phase, aligned pairs at gaps 1e-2, 1e-3 and -2e-3 m: side to
//    side along x and along y and cap on cap (GJK/EPA), upright and lying
//    on the floor (convex-plane fan): every contact normal along the axis of
//    approach to 1e-6, the smallest gap the exact one to 1e-9 m (overlaps,
//    through EPA: 1e-7 m, normal 2e-3: EPA stops within 1e-7 of the curved
//    surface, where the depth varies as the square of the normal's angle),
//    and a face on a face gives at least 3 points; a
//    sphere against it (exact signed-distance path): gap to 1e-15 m.
// 2. Dynamics with both velocity solvers, 2 s at dt = 1e-3 s: two upright
//    elliptic cylinders dropped 1 mm onto the floor and onto each other
//    settle at heights h and 3h to 0.1 % of h, tilt less than 0.1 degree,
//    land within 1 % of b of the axis and, settled, move less than 1e-9 m
//    during the second second (no drift);
//    one lying on its flattest side, rolled by 0.05 rad, never gains energy,
//    never sinks more than 1 % of b into the floor and ends at height b to
//    1 % of b.
#include <particulate/geometry/elliptic_cylinder.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/sphere.h>
#include <particulate/rigid/narrow_phase.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <memory>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

namespace {
  const double a = 0.06, b = 0.03, h = 0.02;

  RigidBody
  body(std::shared_ptr<const Shape> shape,
       const Eigen::Vector3d       &x,
       const Eigen::Quaterniond    &q     = Eigen::Quaterniond::Identity(),
       const bool                   fixed = false)
  {
    RigidBody B(std::move(shape), 0, 1000., fixed);
    B.position    = x;
    B.orientation = q;
    return B;
  }

  /** Contacts of A and B: normals along @p n and the smallest gap @p gap.
   * Returns the number of points. */
  unsigned int
  check_pair(const RigidBody       &A,
             const RigidBody       &B,
             const Eigen::Vector3d &n,
             const double           gap,
             const char            *what)
  {
    ContactEdge        edge;
    const unsigned int count   = NarrowPhase::collide(A, B, 0.02, edge);
    double             min_gap = 1., normal_err = 0.;
    for (const auto &c : edge.manifold.points)
      {
        min_gap    = std::min(min_gap, c.distance);
        normal_err = std::max(normal_err, (c.normal - n).norm());
      }
    std::cout << what << " at gap " << gap << ": " << count
              << " points, gap error " << min_gap - gap << ", normal error "
              << normal_err << "\n";
    CHECK(count > 0, what << ": no contact");
    CHECK(normal_err < (gap > 0. ? 1.e-6 : 2.e-3), what << ": normal");
    CHECK(std::abs(min_gap - gap) < (gap > 0. ? 1.e-9 : 1.e-7),
          what << ": gap " << min_gap << " instead of " << gap);
    return count;
  }
} // namespace

int
main()
{
  const auto ec    = std::make_shared<EllipticCylinder>(a, b, h);
  const auto floor = std::make_shared<HalfSpace>(Eigen::Vector3d::UnitZ(), 0.);
  // Axis along world y, semi-axis b vertical: body y -> world z.
  const Eigen::Quaterniond lying(
    Eigen::AngleAxisd(M_PI / 2., Eigen::Vector3d::UnitX()));
  for (const double gap : {1.e-2, 1.e-3, -2.e-3})
    {
      const RigidBody A = body(ec, Eigen::Vector3d(0.1, -0.2, 0.3));
      check_pair(A,
                 body(ec, A.position + Eigen::Vector3d(2. * a + gap, 0., 0.01)),
                 Eigen::Vector3d::UnitX(),
                 gap,
                 "side by side along x");
      check_pair(A,
                 body(ec, A.position + Eigen::Vector3d(0., 2. * b + gap, 0.)),
                 Eigen::Vector3d::UnitY(),
                 gap,
                 "side by side along y");
      const unsigned int stacked = check_pair(
        A,
        body(ec, A.position + Eigen::Vector3d(0.01, 0.005, 2. * h + gap)),
        Eigen::Vector3d::UnitZ(),
        gap,
        "cap on cap");
      CHECK(stacked >= 3, "a face on a face needs at least 3 points");
      const RigidBody    F = body(floor,
                               Eigen::Vector3d::Zero(),
                               Eigen::Quaterniond::Identity(),
                               true);
      const unsigned int upright
        = check_pair(body(ec, Eigen::Vector3d(0.2, 0.1, h + gap)),
                     F,
                     -Eigen::Vector3d::UnitZ(),
                     gap,
                     "upright on the floor");
      CHECK(upright >= 3, "a cap on the floor needs at least 3 points");
      const unsigned int side
        = check_pair(body(ec, Eigen::Vector3d(0.2, 0.1, b + gap), lying),
                     F,
                     -Eigen::Vector3d::UnitZ(),
                     gap,
                     "lying on the floor");
      CHECK(side >= 2, "a generator line on the floor needs 2 points");
      // Sphere: its centre against the exact signed distance.
      ContactEdge     edge;
      const RigidBody S
        = body(std::make_shared<Sphere>(0.01),
               A.position + Eigen::Vector3d(a + 0.01 + gap, 0., 0.005));
      NarrowPhase::collide(S, A, 0.02, edge);
      CHECK(
        edge.manifold.points.size() == 1
          && std::abs(edge.manifold.points[0].distance - gap) < 1.e-15
          && (edge.manifold.points[0].normal + Eigen::Vector3d::UnitX()).norm()
               < 1.e-15,
        "sphere against the elliptic cylinder");
    }

  for (const auto type : {ContactSolverType::projected_gauss_seidel,
                          ContactSolverType::sequential_impulses})
    {
      WorldParameters prm;
      prm.contact_solver = type;
      World    w(prm);
      Material m;
      m.static_friction = m.dynamic_friction = 0.5;
      w.add_material(m);
      add_floor(w);
      const BodyId low = w.add_body(ec, 0, Eigen::Vector3d(0., 0., h + 1.e-3));
      const BodyId top
        = w.add_body(ec, 0, Eigen::Vector3d(0., 0., 3. * h + 3.e-3));
      // Rolled by theta about its axis: on the floor the centre is at
      // sqrt(a^2 sin^2 theta + b^2 cos^2 theta); start 1 mm above that.
      const double theta = 0.05;
      const double z0    = std::sqrt(a * a * std::sin(theta) * std::sin(theta)
                                  + b * b * std::cos(theta) * std::cos(theta));
      const BodyId roll
        = w.add_body(ec,
                     0,
                     Eigen::Vector3d(0.5, 0., z0 + 1.e-3),
                     Eigen::Quaterniond(
                       Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()))
                       * lying);
      auto energy = [&w](BodyId i) {
        const auto &B = w.body(i);
        return B.kinetic_energy() + B.mass() * 9.81 * B.position[2];
      };
      const double E0    = energy(roll);
      double       E_max = 0., z_min = 1., tilt = 0., offset = 0., drift = 0.;
      Eigen::Vector3d settled[2];
      for (int step = 0; step < 2000; ++step)
        {
          w.step(1.e-3);
          for (const BodyId i : {low, top})
            {
              const Eigen::Vector3d z
                = w.body(i).orientation * Eigen::Vector3d::UnitZ();
              tilt   = std::max(tilt, std::acos(std::min(1., z[2])));
              offset = std::max(offset, w.body(i).position.head<2>().norm());
              if (step == 999)
                settled[i - low] = w.body(i).position;
              if (step >= 999)
                drift
                  = std::max(drift,
                             (w.body(i).position - settled[i - low]).norm());
            }
          E_max = std::max(E_max, energy(roll));
          z_min = std::min(z_min, w.body(roll).position[2]);
        }
      std::cout << to_string(type) << ": stack z " << w.body(low).position[2]
                << ", " << w.body(top).position[2] << " (exact " << h << ", "
                << 3. * h << "), max tilt " << tilt * 180. / M_PI
                << " deg, max offset " << offset << " m, drift in the 2nd s "
                << drift << " m; rolled one: z " << w.body(roll).position[2]
                << " (exact " << b << "), lowest " << z_min
                << ", energy max/initial " << E_max / E0 << "\n";
      CHECK(std::abs(w.body(low).position[2] - h) < 1.e-3 * h, "lower height");
      CHECK(std::abs(w.body(top).position[2] - 3. * h) < 1.e-3 * h,
            "upper height");
      CHECK(tilt < 0.1 * M_PI / 180., "the stack tilts");
      CHECK(offset < 0.01 * b, "the landing shifts the stack sideways");
      CHECK(drift < 1.e-9, "the settled stack drifts");
      CHECK(E_max <= E0 * (1. + 1.e-6), "the rolled one gained energy");
      CHECK(z_min > 0.99 * b, "the rolled one sank into the floor");
      CHECK(std::abs(w.body(roll).position[2] - b) < 0.01 * b,
            "the rolled one rests on its flattest side");
    }
  std::cout << "OK\n";
  return 0;
}
