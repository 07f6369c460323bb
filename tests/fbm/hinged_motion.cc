// The parts of an articulated body (Motion = hinged), without a fluid:
// 1. kinematics (2D and 3D): a part on a parent that translates and turns
//    (a prescribed motion) while its hinge turns by beta(t). The part keeps
//    its distance to the hinge's axis, beta(0) = 0 leaves it where the case
//    puts it, and the velocity it is given at two of its material points,
//    and its angular velocity, equal the time derivatives of where those
//    points are and how the part is turned (central differences, 1e-6
//    relative): the composite rigid velocity is the one the motion has;
// 2. assembly inertia: a sphere with a second one hinged at distance d
//    carries m_1 + m_2, and 2/5 m_1 a^2 + 2/5 m_2 b^2 (+ m_2 d^2 about the
//    axes across the line of centres) (closed form, 1e-12 relative);
// 3. the engine: the head of an articulated body moves with its parts'
//    mass plus the added mass, and a part that overlaps its head at the
//    hinge does not push it (no contact), while an overlapping body of
//    another particle would.
#include <particulate/fbm/articulated_assembly.h>
#include <particulate/fbm/hinged_motion.h>
#include <particulate/fbm/particle_world.h>
#include <particulate/geometry/box.h>
#include <particulate/geometry/sphere.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <string>

#include "../fluid/test_utilities.h"

namespace {
  using namespace particulate;

  testing::Checker checker;

  void
  check(const bool ok, const std::string &what)
  {
    checker.check(ok, what);
  }

  core::FunctionExpression
  expression(const std::string &text)
  {
    core::FunctionExpression f;
    f.expression = text;
    return f;
  }

  /** A box-shaped part of a parent that moves by d(t), phi(t). */
  template <int dim>
  void
  check_kinematics()
  {
    const std::string        name = std::to_string(dim) + "D: ";
    fbm::ParticleDescription parent;
    parent.shape    = std::make_shared<geometry::Sphere>(0.05);
    parent.position = Eigen::Vector3d(0.3, 0.2, dim == 3 ? 0.1 : 0.);
    parent.motion   = fbm::ParticleMotion::prescribed;
    if (dim == 2)
      {
        parent.prescribed_displacement = expression("0.1*sin(t); 0.05*t^2");
        parent.prescribed_rotation     = expression("0.4*t + 0.2*sin(3*t)");
      }
    else
      {
        parent.prescribed_displacement
          = expression("0.1*sin(t); 0.05*t^2; -0.02*t");
        parent.prescribed_rotation = expression("0.3*t; 0.2*sin(t); 0.1*t^2");
      }
    const fbm::PrescribedMotion<dim> parent_motion(parent, 10.);

    fbm::ParticleDescription part;
    part.shape = std::make_shared<geometry::Box>(
      Eigen::Vector3d(0.005, 0.08, dim == 3 ? 0.02 : 0.5));
    part.position = Eigen::Vector3d(0.3, 0.08, parent.position[2]);
    part.orientation
      = Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()));
    part.motion      = fbm::ParticleMotion::hinged;
    part.hinge.point = Eigen::Vector3d(0.3, 0.16, parent.position[2]);
    part.hinge.axis  = dim == 3 ? Eigen::Vector3d(1., 0., 1.).normalized() :
                                  Eigen::Vector3d::UnitZ();
    part.hinge.angle = expression("0.7*sin(2*t)");
    const fbm::HingedMotion<dim> motion(part, parent_motion.state(0.), 10.);

    const fbm::PrescribedState start
      = motion.state(0., parent_motion.state(0.));
    check((start.position - part.position).norm() < 1e-14
            && start.orientation.angularDistance(part.orientation) < 1e-14,
          name + "beta(0) = 0 leaves the part where the case puts it");

    const auto at
      = [&](const double t) { return motion.state(t, parent_motion.state(t)); };
    // two material points of the part, in its body frame
    const Eigen::Vector3d a = Eigen::Vector3d::Zero(),
                          b(0.004, -0.07, dim == 3 ? 0.015 : 0.);
    const auto point
      = [](const fbm::PrescribedState &s, const Eigen::Vector3d &x) {
          return Eigen::Vector3d(s.position + s.orientation * x);
        };
    const double radius0 = [&] {
      const Eigen::Vector3d r = part.position - part.hinge.point;
      return (r - r.dot(part.hinge.axis) * part.hinge.axis).norm();
    }();
    double       worst_velocity = 0., worst_omega = 0., worst_radius = 0.;
    const double delta = 1e-5;
    for (const double t : {0.3, 1.1, 2.7})
      {
        const fbm::PrescribedState s = at(t), before = at(t - delta),
                                   after = at(t + delta);
        for (const Eigen::Vector3d &x : {a, b})
          {
            const Eigen::Vector3d x_now = point(s, x);
            const Eigen::Vector3d given
              = s.velocity + s.angular_velocity.cross(x_now - s.position);
            const Eigen::Vector3d measured
              = (point(after, x) - point(before, x)) / (2. * delta);
            worst_velocity
              = std::max(worst_velocity,
                         (given - measured).norm() / measured.norm());
          }
        const Eigen::AngleAxisd turn(after.orientation
                                     * before.orientation.conjugate());
        const Eigen::Vector3d omega = turn.angle() / (2. * delta) * turn.axis();
        worst_omega
          = std::max(worst_omega,
                     (omega - s.angular_velocity).norm() / omega.norm());
        // the hinge's axis where the parent has carried it
        const fbm::PrescribedState p  = parent_motion.state(t);
        const fbm::PrescribedState p0 = parent_motion.state(0.);
        const Eigen::Quaterniond   carry
          = p.orientation * p0.orientation.conjugate();
        const Eigen::Vector3d hinge
          = p.position + carry * (part.hinge.point - p0.position);
        const Eigen::Vector3d axis = carry * part.hinge.axis;
        const Eigen::Vector3d r    = s.position - hinge;
        worst_radius
          = std::max(worst_radius,
                     std::abs((r - r.dot(axis) * axis).norm() - radius0));
      }
    std::cout << name << "velocity vs d/dt of the points " << worst_velocity
              << ", angular velocity " << worst_omega
              << ", change of the distance to the hinge " << worst_radius
              << " m" << std::endl;
    check(worst_velocity < 1e-6,
          name + "the points move with the velocity the part is given");
    check(worst_omega < 1e-6,
          name + "the part turns with the angular velocity it is given");
    check(worst_radius < 1e-12,
          name + "the part keeps its distance to the hinge");
  }

  /** Head sphere (a) with a sphere (b) hinged at distance d along x. */
  std::vector<fbm::ParticleDescription>
  two_spheres(const double a, const double b, const double d)
  {
    fbm::ParticleDescription head, part;
    head.shape        = std::make_shared<geometry::Sphere>(a);
    head.density      = 1000.;
    part.shape        = std::make_shared<geometry::Sphere>(b);
    part.density      = 3000.;
    part.position     = Eigen::Vector3d(d, 0., 0.);
    part.motion       = fbm::ParticleMotion::hinged;
    part.hinge.parent = 0;
    part.hinge.point  = Eigen::Vector3d(a, 0., 0.);
    part.hinge.angle  = expression("0");
    return {head, part};
  }

  void
  check_assembly_inertia()
  {
    const double                a = 0.02, b = 0.01, d = 0.025;
    const auto                  particles = two_spheres(a, b, d);
    std::vector<fbm::BodyStart> starts(2);
    starts[1].position               = particles[1].position;
    const double               extra = 500.;
    const fbm::AssemblyInertia I
      = fbm::assembly_inertia(particles, starts, 0, {1}, extra);
    const double          m1  = (1000. + extra) * 4. / 3. * M_PI * a * a * a;
    const double          m2  = (3000. + extra) * 4. / 3. * M_PI * b * b * b;
    const double          own = 0.4 * (m1 * a * a + m2 * b * b);
    const Eigen::Vector3d expected(own, own + m2 * d * d, own + m2 * d * d);
    const double          error
      = std::max(std::abs(I.mass - (m1 + m2)) / (m1 + m2),
                 (I.inertia.diagonal() - expected).norm() / expected.norm());
    std::cout << "assembly mass and inertia vs closed form: " << error
              << std::endl;
    check(error < 1e-12, "the assembly's mass and inertia (parallel axes)");
    check(I.inertia.norm() - I.inertia.diagonal().norm()
            < 1e-12 * I.inertia.norm(),
          "no products of inertia along the line of centres");
  }

  void
  check_engine()
  {
    const double a = 0.02, b = 0.01, d = 0.025; // the part overlaps the head
    fbm::ParticleParameters p;
    p.bodies = two_spheres(a, b, d);
    fbm::ParticleWorldFrame frame;
    frame.domain.lower  = Eigen::Vector3d::Constant(-1.);
    frame.domain.upper  = Eigen::Vector3d::Constant(1.);
    frame.domain.dim    = 3;
    frame.added_density = 500.;
    std::vector<fbm::BodyStart> starts(2);
    starts[1].position       = p.bodies[1].position;
    fbm::ParticleWorld built = fbm::build_particle_world(p, starts, frame);
    rigid::World      &world = *built.world;
    const double       expected
      = fbm::assembly_inertia(p.bodies, starts, 0, {1}, 500.).mass;
    check(std::abs(world.body(built.ids[0]).mass() - expected)
            < 1e-12 * expected,
          "the head moves with its assembly's mass plus the added mass");
    world.step(1e-3);
    world.step(1e-3);
    check(world.body(built.ids[0]).linear_velocity.norm() == 0.,
          "a part overlapping its head at the hinge does not push it");

    // the same overlap with a free body of its own is a contact
    fbm::ParticleParameters q = p;
    q.bodies[1].motion        = fbm::ParticleMotion::fixed;
    fbm::ParticleWorld other  = fbm::build_particle_world(q, starts, frame);
    other.world->step(1e-3);
    check(other.world->body(other.ids[0]).linear_velocity.norm() > 0.,
          "an overlapping body that is not a part pushes (the check can fail)");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_kinematics<2>();
  check_kinematics<3>();
  check_assembly_inertia();
  check_engine();
  return checker.exit_code();
}
