// The particle set of a case file: shape templates, numbered particles with
// orientations and prescribed motions, a particle file, a lattice and a
// random fill, each particle checked against what the case writes, the
// mass properties against closed forms, and the random fill against its
// definition (count, region, no overlap, same seed same particles).

#include <particulate/fbm/particle_generators.h>
#include <particulate/fbm/particle_set_checks.h>
#include <particulate/fbm/particulate_flow_simulation.h>
#include <particulate/fbm/prescribed_motion.h>
#include <particulate/geometry/box.h>
#include <particulate/geometry/sphere.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  bool
  near(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const double tol)
  {
    return (a - b).norm() <= tol;
  }

  /** The same rotation (q and -q are one rotation). */
  bool
  same_rotation(const Eigen::Quaterniond &a, const Eigen::Quaterniond &b)
  {
    return std::abs(std::abs(a.dot(b)) - 1.) < 1e-14;
  }

  void
  check_described_particles(const std::vector<fbm::ParticleDescription> &set,
                            testing::Checker &checker)
  {
    const double pi = M_PI;
    // Particle 0: the grain, turned 90 degrees about y
    const auto &grain = set.at(0);
    checker.check(grain.shape_name == "grain" && grain.density == 1500.,
                  "particle 0: template 'grain' and its density");
    checker.check(std::abs(grain.shape->volume()
                           - 4. / 3. * pi * 0.06 * 0.03 * 0.03)
                    < 1e-15,
                  "particle 0: the ellipsoid's volume 4/3 pi a b c");
    checker.check(near(grain.orientation * Eigen::Vector3d::UnitX(),
                       -Eigen::Vector3d::UnitZ(),
                       1e-15),
                  "particle 0: its long axis turned from x onto -z");
    checker.check(near(grain.velocity, Eigen::Vector3d(0.01, 0., 0.), 0.)
                    && near(grain.angular_velocity,
                            Eigen::Vector3d(0., 0., 2.),
                            0.),
                  "particle 0: velocity and angular velocity");

    // Particle 1: the prescribed spinning rod
    const auto &rod = set.at(1);
    checker.check(rod.motion == fbm::ParticleMotion::prescribed
                    && same_rotation(rod.orientation,
                                     Eigen::Quaterniond(0., 1., 0., 0.)),
                  "particle 1: prescribed, turned by the quaternion");
    const double                   t = 0.3;
    const fbm::PrescribedMotion<3> motion(rod, 1.);
    const fbm::PrescribedState     s = motion.state(t);
    const Eigen::Quaterniond       expected
      = Eigen::Quaterniond(Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ()))
        * rod.orientation;
    checker.check(same_rotation(s.orientation, expected),
                  "particle 1: orientation R(phi(t)) q_0 at t = 0.3 s");
    checker.check(near(s.angular_velocity, Eigen::Vector3d(0., 0., 1.), 1e-8)
                    && near(s.position, rod.position, 0.)
                    && s.velocity.norm() == 0.,
                  "particle 1: spins at 1 rad/s about z, in place");

    // the particle file: two pills (one fixed, turned 90 degrees about x)
    // and a grain, after the numbered particles
    checker.check(set.at(2).shape_name == "pill"
                    && set.at(2).motion == fbm::ParticleMotion::free
                    && near(set.at(2).velocity,
                            Eigen::Vector3d(0., 0., -0.1),
                            0.),
                  "file line 2: a free pill falling at 0.1 m/s");
    checker.check(set.at(3).motion == fbm::ParticleMotion::fixed
                    && near(set.at(3).orientation * Eigen::Vector3d::UnitZ(),
                            -Eigen::Vector3d::UnitY(),
                            1e-15),
                  "file line 3: a fixed pill, its axis turned from z onto "
                  "-y");
    checker.check(set.at(4).shape_name == "grain"
                    && near(set.at(4).position,
                            Eigen::Vector3d(0.7, 0.2, 0.9),
                            0.),
                  "file line 6 (after a comment): the grain");
    checker.check(set.at(2).origin.find("mixed_set_particles.csv:2")
                    != std::string::npos,
                  "a file particle says which line describes it");
    checker.check(set.at(2).shape == set.at(3).shape,
                  "particles of one template share one solid");
    const double capsule = pi * 0.02 * 0.02 * 0.06 + 4. / 3. * pi * 8e-6;
    checker.check_relative(set.at(2).shape->volume(),
                           capsule,
                           1e-14,
                           "capsule volume pi r^2 L + 4/3 pi r^3");

    // the lattice: 3 x 2 balls on the floor, x fastest
    for (unsigned int j = 0; j < 2; ++j)
      for (unsigned int i = 0; i < 3; ++i)
        checker.check(near(set.at(5 + i + 3 * j).position,
                           Eigen::Vector3d(0.1 + 0.2 * i, 0.1 + 0.2 * j, 0.06),
                           1e-15),
                      "lattice ball (" + std::to_string(i) + ", "
                        + std::to_string(j) + ") at first + (i, j) spacing");
    checker.check(set.at(5).density == 2500.
                    && set.at(11).shape_name == "brick",
                  "the lattice's balls, then the random fill's bricks");
  }

  void
  check_random_fill(const std::vector<fbm::ParticleDescription> &set,
                    testing::Checker                            &checker)
  {
    // 0.02 of the box [0, 1]^2 x [0.3, 0.6] in bricks of 8 * 0.04 * 0.03 *
    // 0.02 m^3: round(31.25) = 31
    const unsigned int first = 11, n = set.size() - first;
    checker.check(n == 31, "random fill: 31 bricks for a solid fraction 0.02");
    bool inside = true, turned = false;
    for (unsigned int i = first; i < set.size(); ++i)
      {
        const geometry::BoundingBox box
          = geometry::Pose(set[i].orientation, set[i].position)
              .to_world(set[i].shape->bounding_box());
        inside &= box.lower.minCoeff() >= 0. && box.upper.maxCoeff() <= 1.
                  && box.lower[2] >= 0.3 && box.upper[2] <= 0.6;
        turned |= !same_rotation(set[i].orientation, set[first].orientation);
      }
    checker.check(inside, "random fill: every brick inside its region");
    checker.check(turned, "random fill: the bricks turned at random");

    // the fill alone: the same seed gives the same particles; a solid
    // fraction above what random sequential addition reaches is refused
    fbm::RandomFill fill;
    fill.lower          = Eigen::Vector3d(0., 0., 0.);
    fill.upper          = Eigen::Vector3d(1., 1., 1.);
    fill.solid_fraction = 0.1;
    fill.seed           = 3;
    const geometry::Sphere ball(0.05);
    const auto a = fill.place(ball, 3, Eigen::Quaterniond::Identity(), {});
    const auto b = fill.place(ball, 3, Eigen::Quaterniond::Identity(), {});
    fill.seed    = 4;
    const auto c = fill.place(ball, 3, Eigen::Quaterniond::Identity(), {});
    checker.check(a.size() == 191 && a.size() == b.size(),
                  "random fill: round(0.1 / (4/3 pi 0.05^3)) = 191 balls");
    bool same = true, different = false;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        same &= a[i].translation() == b[i].translation();
        different |= a[i].translation() != c[i].translation();
      }
    checker.check(same && different,
                  "random fill: the same seed, the same balls; another "
                  "seed, others");
    // a clearance: every pair of balls and every ball and face of the box
    // keep it (all pairs, independent of the fill's grid)
    fill.clearance    = 0.02;
    const auto spaced = fill.place(ball, 3, Eigen::Quaterniond::Identity(), {});
    double     closest = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < spaced.size(); ++i)
      {
        const Eigen::Vector3d x = spaced[i].translation();
        closest
          = std::min({closest, x.minCoeff() - 0.05, 1. - 0.05 - x.maxCoeff()});
        for (unsigned int j = 0; j < i; ++j)
          closest
            = std::min(closest, (x - spaced[j].translation()).norm() - 0.1);
      }
    std::cout << "random fill with clearance 0.02: closest gap " << closest
              << std::endl;
    checker.check(spaced.size() == 191 && closest >= 0.02 * (1. - 1e-12),
                  "random fill: 191 balls, none closer than the clearance "
                  "0.02 to another or to the box");
    // the cylinder inscribed in the box: pi 0.5^2 of its volume, every
    // ball the clearance inside the mantle
    fill.region       = fbm::RandomFill::Region::cylinder;
    const auto column = fill.place(ball, 3, Eigen::Quaterniond::Identity(), {});
    double     mantle_gap = std::numeric_limits<double>::max();
    for (const auto &pose : column)
      mantle_gap = std::min(mantle_gap,
                            0.5 - 0.05
                              - std::hypot(pose.translation()[0] - 0.5,
                                           pose.translation()[1] - 0.5));
    std::cout << "random fill of the cylinder: " << column.size()
              << " balls, closest gap to the mantle " << mantle_gap
              << std::endl;
    checker.check(column.size() == 150 && mantle_gap >= 0.02 * (1. - 1e-12),
                  "random fill of the cylinder: round(0.1 pi 0.25 / (4/3 pi "
                  "0.05^3)) = 150 balls, none closer than the clearance to "
                  "the mantle");
    fill.region         = fbm::RandomFill::Region::box;
    fill.clearance      = 0.;
    fill.solid_fraction = 0.45;
    bool refused        = false;
    try
      {
        fill.place(ball, 3, Eigen::Quaterniond::Identity(), {});
      }
    catch (const std::runtime_error &e)
      {
        std::cout << "expected: " << e.what() << std::endl;
        refused = std::string(e.what()).find("placed") != std::string::npos;
      }
    checker.check(refused,
                  "random fill: a solid fraction of 0.45 (above the 0.38 "
                  "of random sequential addition) is refused");
  }

  void
  check_overlap_and_domain(std::vector<fbm::ParticleDescription> set,
                           testing::Checker                     &checker)
  {
    const auto refused = [&](const auto &call) {
      try
        {
          call();
        }
      catch (const std::runtime_error &e)
        {
          std::cout << "expected: " << e.what() << std::endl;
          return true;
        }
      return false;
    };
    // two bricks: touching is allowed, 1 micrometre deeper is not
    fbm::ParticleDescription brick;
    brick.shape
      = std::make_shared<geometry::Box>(Eigen::Vector3d(0.1, 0.1, 0.1));
    brick.position = Eigen::Vector3d(0.5, 0.5, 0.5);
    auto other     = brick;
    other.position[0] += 0.2;
    checker.check(!refused([&]() {
      fbm::check_no_overlap({brick, other}, 3);
    }),
                  "two boxes face to face are accepted");
    other.position[0] -= 1e-6;
    checker.check(refused([&]() {
                    fbm::check_no_overlap({brick, other}, 3);
                  }),
                  "two boxes overlapping by 1 um are refused");
    // the box turned by 45 degrees reaches 0.1 sqrt(2) from its centre
    brick.orientation = Eigen::AngleAxisd(M_PI / 4., Eigen::Vector3d::UnitZ());
    brick.position[0] = 0.1 * std::sqrt(2.) + 1e-6;
    fbm::DomainBox unit_box;
    unit_box.upper = Eigen::Vector3d::Ones();
    checker.check(!refused(
                    [&]() { fbm::check_inside_domain({brick}, unit_box); }),
                  "a turned box just inside the domain is accepted");
    brick.position[0] -= 2e-6;
    checker.check(refused(
                    [&]() { fbm::check_inside_domain({brick}, unit_box); }),
                  "a turned box whose corner leaves the domain is refused");
    // the column of radius 0.5 about the vertical axis through (0.5, 0.5)
    fbm::DomainBox column         = unit_box;
    column.column_radius          = 0.5;
    fbm::ParticleDescription ball = brick;
    ball.shape                    = std::make_shared<geometry::Sphere>(0.1);
    ball.orientation              = Eigen::Quaterniond::Identity();
    ball.position = Eigen::Vector3d(0.5 + 0.4 / std::sqrt(2.) - 1e-6,
                                    0.5 + 0.4 / std::sqrt(2.),
                                    0.5);
    checker.check(!refused([&]() { fbm::check_inside_domain({ball}, column); }),
                  "a sphere just inside a column's mantle is accepted");
    ball.position[0] += 2e-6;
    checker.check(refused([&]() { fbm::check_inside_domain({ball}, column); }),
                  "a sphere reaching 1 um beyond the mantle is refused");
    checker.check(!refused([&]() { fbm::check_no_overlap(set, 3); }),
                  "the case's particles do not overlap");
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const auto parameters = fbm::read_particulate_flow_case(
    testing::source_path("tests/fbm/particle_set/mixed_set.prm"));
  const auto &set = parameters.particles.bodies;
  std::cout << set.size() << " particles" << std::endl;
  checker.check(set.size() == 11 + 31,
                "2 numbered + 3 from the file + 6 on the lattice + 31 random");
  check_described_particles(set, checker);
  check_random_fill(set, checker);
  check_overlap_and_domain(set, checker);
  return checker.exit_code();
}
