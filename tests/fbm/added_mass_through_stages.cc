// A disk (R = 0.1) accelerated uniformly from rest (x = a t^2 / 2, a = 1
// m/s^2) through water at rest in the middle of a closed unit box meets the
// fluid's added mass: F = -m_a a, with m_a = rho pi R^2 (R_o^2 + R^2) /
// (R_o^2 - R^2) for a concentric container of radius R_o, 1.083 rho pi R^2 for
// the circle inscribed in the box (the box, less confining, gives a little
// less). The viscous part is below 0.5 % at t = 0.05 s (boundary layer
// sqrt(nu t) = 2e-4 m against R).
//
// The prescribed motion through the mesh, plain FBM at 12.8 cells per
// diameter, dt = 0.01 s:
// - fractional-step theta gives the force of backward Euler within 1 %: its
//   three stages accelerate the covered nodes with the body, so the
//   pressure at the end of the step holds the added mass (imposing the
//   end-of-step velocity from the first stage on, as a constant, leaves it
//   out: the force falls to the viscous part);
// - the force is the added mass of the inscribed circle within 10 %.
#include <particulate/fbm/particulate_flow_simulation.h>

#include <cmath>

#include "../fluid/test_utilities.h"
#include "run_case.h"

using namespace particulate;

namespace {
  const double radius = 0.1, acceleration = 1.;

  /** The force on the disk at t = 0.05 s with the time scheme @p scheme. */
  double
  force_at_end(const std::string &scheme, const std::string &output)
  {
    const std::string overrides
      = "subsection Time\n set Scheme = " + scheme
        + "\n set Time step = 0.01\n set End time = 0.05\nend\n"
          "subsection Mesh\n set Upper corner = 1, 1\n"
          " set Subdivisions = 1, 1\n set Refinements = 6\nend\n"
          "subsection Fluid\n set Density = 1000\n"
          " set Dynamic viscosity = 1e-3\nend\n"
          "subsection Particles\n subsection Shape disk\n  set Radius = "
        + std::to_string(radius)
        + "\n end\n subsection Particle 0\n  set Position = 0.5, 0.5\n"
          "  set Prescribed displacement = 0.5 * a * t^2; 0\n"
          "  set Prescribed displacement constants = a = "
        + std::to_string(acceleration)
        + "\n end\nend\n"
          "subsection Checkpoint\n set Wall-time interval = 0\nend\n";
    const auto parameters = fbm::read_particulate_flow_case(
      testing::source_path("prm/oscillating-cylinder/oscillating-cylinder.prm"),
      overrides);
    const auto summary
      = testing::run_without_fields<2>(parameters,
                                       "accelerated disk, " + scheme,
                                       output,
                                       MPI_COMM_WORLD);
    return summary.force[0][0];
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const double                             rho = 1000., R_o = 0.5, R = radius;
  const double                             inscribed
    = rho * M_PI * R * R * (R_o * R_o + R * R) / (R_o * R_o - R * R);

  const double staged
    = force_at_end("fractional-step theta", "added_mass_through_stages_fs");
  const double single
    = force_at_end("backward Euler", "added_mass_through_stages_be");
  checker.check_relative(staged,
                         single,
                         0.01,
                         "fractional-step theta's stages keep the added mass");
  checker.check_relative(-single / acceleration,
                         inscribed,
                         0.1,
                         "the force is the fluid's added mass");
  return checker.exit_code();
}
