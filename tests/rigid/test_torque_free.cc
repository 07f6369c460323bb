// Torque-free asymmetric rigid body (thesis eq. 4.31 with tau = 0):
// kinetic energy and world angular momentum conserved to 1e-6 (relative)
// over 1e4 steps, and the intermediate-axis (Dzhanibekov) flip: spinning
// about the middle principal axis with a tiny perturbation, the body-frame
// angular velocity about that axis reverses sign periodically.
#include <particulate/geometry/box.h>
#include <particulate/rigid/newton_euler_integrator.h>

#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

int
main()
{
  // Box with three distinct moments: I1 < I2 < I3 (x is the long axis).
  auto      shape = std::make_shared<Box>(Eigen::Vector3d(0.5, 0.25, 0.1));
  RigidBody body(shape, 0, 1000., false);
  const Eigen::Vector3d I = body.principal_inertia();
  CHECK(I[0] < I[1] && I[1] < I[2], "moments ordered " << I.transpose());

  // Spin mostly about the intermediate axis (body y), perturbed.
  body.orientation = Eigen::Quaterniond(
    Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  body.angular_velocity = body.orientation * Eigen::Vector3d(1.e-3, 10., 1.e-3);
  body.linear_velocity  = Eigen::Vector3d(0.1, -0.2, 0.3);

  const double          E0        = body.kinetic_energy();
  const Eigen::Vector3d L0        = body.angular_momentum();
  const double          dt        = 1.e-3;
  int                   flips     = 0;
  double                last_sign = 1.;
  double                max_dE = 0., max_dL = 0.;
  for (int step = 0; step < 10000; ++step)
    {
      NewtonEulerIntegrator::integrate_velocity(body,
                                                Eigen::Vector3d::Zero(),
                                                Eigen::Vector3d::Zero(),
                                                Eigen::Vector3d::Zero(),
                                                dt);
      NewtonEulerIntegrator::integrate_position(body, dt);
      max_dE = std::max(max_dE, std::abs(body.kinetic_energy() - E0) / E0);
      max_dL
        = std::max(max_dL, (body.angular_momentum() - L0).norm() / L0.norm());
      const double wy
        = (body.orientation.conjugate() * body.angular_velocity)[1];
      if (wy * last_sign < 0.)
        {
          ++flips;
          last_sign = -last_sign;
        }
      CHECK(std::abs(body.orientation.norm() - 1.) < 1.e-14, "unit quaternion");
    }
  std::cout << "max relative energy error " << max_dE
            << ", max relative angular momentum error " << max_dL
            << ", intermediate-axis flips " << flips << "\n";
  CHECK(max_dE < 1.e-6, "energy drift " << max_dE);
  CHECK(max_dL < 1.e-6, "angular momentum drift " << max_dL);
  CHECK(flips >= 2, "the intermediate-axis flip did not happen");

  // Control: spin about the largest axis is stable, no flip.
  body.orientation      = Eigen::Quaterniond::Identity();
  body.angular_velocity = Eigen::Vector3d(1.e-3, 1.e-3, 10.);
  for (int step = 0; step < 10000; ++step)
    {
      NewtonEulerIntegrator::integrate_position(body, dt);
      const double wz
        = (body.orientation.conjugate() * body.angular_velocity)[2];
      CHECK(wz > 9.9, "major-axis spin must stay stable, w_z = " << wz);
    }
  std::cout << "OK\n";
  return 0;
}
