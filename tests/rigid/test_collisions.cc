// Two-body collisions without gravity or friction.
// 1. Head-on sphere collisions (unequal masses): post-collision velocities
//    equal the closed form v1' = (m1 v1 + m2 v2 + m2 e (v2 - v1)) / (m1 + m2)
//    to 1e-12 for e = 0, 0.5, 1 with the two velocity-level solvers, and to
//    1 % with the DEM (its linear spring-dashpot restitution is exact in
//    continuous time; the explicit integration with 50 substeps per contact
//    time costs ~0.5 %).
// 2. Oblique sphere and rotating box collisions: linear and angular momentum
//    (about the origin) conserved to 1e-12 relative (DEM: 1e-11, round-off
//    of its ~10x more substeps);
//    kinetic energy conserved to 1e-9 for e = 1 head-on.
#include <particulate/geometry/box.h>
#include <particulate/geometry/sphere.h>
#include <particulate/rigid/world.h>

#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

namespace {
  World
  make_world(const ContactSolverType type, const double e)
  {
    WorldParameters prm;
    prm.gravity        = Eigen::Vector3d::Zero();
    prm.contact_solver = type;
    // Resolve the DEM contact time finely enough for a 1 % restitution.
    prm.dem_steps_per_contact = 50.;
    World    w(prm);
    Material m;
    m.restitution   = e;
    m.density       = 1000.;
    m.dem_stiffness = 2.e6;
    w.add_material(m);
    return w;
  }

  void
  momenta(const World &w, Eigen::Vector3d &P, Eigen::Vector3d &L)
  {
    P.setZero();
    L.setZero();
    for (const auto &b : w.bodies())
      {
        P += b.linear_momentum();
        L += b.angular_momentum();
      }
  }
} // namespace

int
main()
{
  for (const auto type : {ContactSolverType::projected_gauss_seidel,
                          ContactSolverType::sequential_impulses,
                          ContactSolverType::dem})
    for (const double e : {0., 0.5, 1.})
      {
        if (type == ContactSolverType::dem && e == 0.)
          continue; // a spring-dashpot cannot reach e = 0 exactly
        World        w  = make_world(type, e);
        const double r1 = 0.05, r2 = 0.08;
        w.add_body(std::make_shared<Sphere>(r1),
                   0,
                   Eigen::Vector3d(-0.2, 0.01, 0.02));
        w.add_body(std::make_shared<Sphere>(r2),
                   0,
                   Eigen::Vector3d(0.2, 0.01, 0.02));
        const double v1 = 1.5, v2 = -0.5;
        w.body(0).linear_velocity = Eigen::Vector3d(v1, 0, 0);
        w.body(1).linear_velocity = Eigen::Vector3d(v2, 0, 0);
        const double    m1 = w.body(0).mass(), m2 = w.body(1).mass();
        Eigen::Vector3d P0, L0, P, L;
        momenta(w, P0, L0);
        const double E0 = w.kinetic_energy();
        for (int s = 0; s < 300; ++s)
          w.step(1.e-3);
        momenta(w, P, L);
        const double v1x = w.body(0).linear_velocity[0],
                     v2x = w.body(1).linear_velocity[0];
        const double v1e = (m1 * v1 + m2 * v2 + m2 * e * (v2 - v1)) / (m1 + m2);
        const double v2e = (m1 * v1 + m2 * v2 + m1 * e * (v1 - v2)) / (m1 + m2);
        const double err = std::max(std::abs(v1x - v1e), std::abs(v2x - v2e))
                           / std::abs(v1 - v2);
        std::cout << to_string(type) << ", e = " << e << ": v1' = " << v1x
                  << " (exact " << v1e << "), v2' = " << v2x << " (exact "
                  << v2e << "), rel. error " << err
                  << ", |dP|/|P| = " << (P - P0).norm() / P0.norm() << "\n";
        const double tol = type == ContactSolverType::dem ? 1.e-2 : 1.e-12;
        CHECK(err < tol, "post-collision velocity error " << err);
        CHECK((P - P0).norm() <= 1.e-12 * P0.norm(), "linear momentum");
        CHECK((L - L0).norm() <= 1.e-12 * std::max(L0.norm(), P0.norm() * 0.2),
              "angular momentum");
        if (e == 1. && type != ContactSolverType::dem)
          CHECK(std::abs(w.kinetic_energy() - E0) <= 1.e-9 * E0,
                "energy for e = 1");
      }

  // Oblique sphere collision and a rotating box hitting another box.
  for (const auto type : {ContactSolverType::projected_gauss_seidel,
                          ContactSolverType::sequential_impulses,
                          ContactSolverType::dem})
    {
      World w = make_world(type, 0.7);
      w.add_body(std::make_shared<Sphere>(0.05),
                 0,
                 Eigen::Vector3d(-0.2, 0.03, 0.));
      w.add_body(std::make_shared<Sphere>(0.07),
                 0,
                 Eigen::Vector3d(0.2, -0.02, 0.01));
      w.body(0).linear_velocity = Eigen::Vector3d(2., 0., 0.);
      auto box = std::make_shared<Box>(Eigen::Vector3d(0.05, 0.03, 0.02));
      w.add_body(box,
                 0,
                 Eigen::Vector3d(0., 1., 0.),
                 Eigen::Quaterniond(
                   Eigen::AngleAxisd(0.3,
                                     Eigen::Vector3d(1, 1, 0).normalized())));
      w.add_body(box, 0, Eigen::Vector3d(0.03, 1.3, 0.01));
      w.body(2).linear_velocity  = Eigen::Vector3d(0., 1., 0.);
      w.body(2).angular_velocity = Eigen::Vector3d(0.5, -2., 3.);
      w.body(3).angular_velocity = Eigen::Vector3d(1., 0., 0.);
      Eigen::Vector3d P0, L0, P, L;
      momenta(w, P0, L0);
      unsigned int max_contacts = 0;
      for (int s = 0; s < 400; ++s)
        {
          w.step(1.e-3);
          max_contacts = std::max(max_contacts, w.statistics().contacts);
        }
      momenta(w, P, L);
      std::cout << to_string(type)
                << " oblique/box: |dP|/|P| = " << (P - P0).norm() / P0.norm()
                << ", |dL|/|L| = " << (L - L0).norm() / L0.norm()
                << ", contacts seen " << max_contacts << ", box speeds "
                << w.body(2).linear_velocity.norm() << " "
                << w.body(3).linear_velocity.norm() << "\n";
      CHECK(max_contacts > 0, "the bodies must have collided");
      CHECK(w.body(3).linear_velocity.norm() > 0.1,
            "the second box must have been hit");
      CHECK((P - P0).norm() <= 1.e-12 * P0.norm(), "linear momentum");
      // The DEM takes ~10 substeps per step, so its round-off accumulates
      // over ~4000 rotation updates: 1e-11 there.
      const double tol = type == ContactSolverType::dem ? 1.e-11 : 1.e-12;
      CHECK((L - L0).norm() <= tol * L0.norm(), "angular momentum");
    }
  std::cout << "OK\n";
  return 0;
}
