// A sphere resting on a plane (with gravity and friction) must not drift:
// its centre moves less than 1e-6 m during 10 s of simulated time with each
// contact solver. The DEM sphere starts at its equilibrium overlap m g / k.
// Also checks that the contact force reported to the coupling (averaged
// over the step) equals the weight to 1e-6, with 1 and 4 substeps per step.
#include <particulate/geometry/sphere.h>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

int
main()
{
  for (const auto type : all_solvers())
    for (const unsigned int substeps : {1u, 4u})
      {
        WorldParameters prm;
        prm.contact_solver = type;
        prm.substeps       = substeps;
        World    w(prm);
        Material m;
        m.static_friction = m.dynamic_friction = 0.5;
        m.restitution                          = 0.3;
        m.dem_stiffness                        = 2.e5;
        w.add_material(m);
        add_floor(w);
        const double r    = 0.05;
        const BodyId s    = w.add_body(std::make_shared<Sphere>(r),
                                    0,
                                    Eigen::Vector3d(0.3, -0.2, r));
        const double mass = w.body(s).mass();
        if (type == ContactSolverType::dem)
          {
            const double k
              = 1. / (2. / m.dem_stiffness); // series of floor and sphere
            w.body(s).position[2] -= mass * 9.81 / k;
          }
        const Eigen::Vector3d x0    = w.body(s).position;
        double                drift = 0.;
        const double          dt    = 1.e-3;
        for (int step = 0; step < 10000; ++step)
          {
            w.step(dt);
            drift = std::max(drift, (w.body(s).position - x0).norm());
          }
        Eigen::Vector3d F = Eigen::Vector3d::Zero();
        for (const auto &f : w.contact_forces(s))
          F += f.force;
        std::cout << to_string(type) << ", " << substeps
                  << " substep(s): drift over 10 s = " << drift
                  << " m, contact force " << F.transpose() << " N (weight "
                  << mass * 9.81 << " N), substeps " << w.statistics().substeps
                  << "\n";
        CHECK(drift < 1.e-6, "resting sphere drifted by " << drift << " m");
        CHECK(std::abs(F[2] - mass * 9.81) < 1.e-6 * mass * 9.81
                && F.head<2>().norm() < 1.e-9,
              "contact force must balance the weight");
      }
  std::cout << "OK\n";
  return 0;
}
