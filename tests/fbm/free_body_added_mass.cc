// A free disk (R = 0.1 m, rho_p = 2 rho_f) released from rest in the middle
// of a closed unit box of water: in potential flow it starts to sink with
// a = (rho_p - rho_f) g / (rho_p + C_a rho_f), its added mass
// C_a rho_f pi R^2 that of the circle inscribed in the box, C_a =
// (R_o^2 + R^2) / (R_o^2 - R^2) = 1.083 (R_o = 0.5 m): 3.182 m/s^2, against
// 4.905 m/s^2 without added mass. The viscous part is below 1 % over the
// first 0.05 s (boundary layer sqrt(nu t) = 2e-4 m against R).
//
// With the default coupling ('Stage velocities = interpolated') the disk's
// covered nodes follow its velocity through the stages of each step, so
// the pressure at the end of the step holds the fluid's answer to the
// acceleration: the disk's acceleration over t = 0.02-0.05 s (after the
// first step, which the added-mass correction alone sets) is the closed
// form's within 5 % ('held' gives about the value without added mass).
#include <particulate/fbm/particulate_flow_simulation.h>

#include <cmath>
#include <stdexcept>

#include "../fluid/test_utilities.h"
#include "run_case.h"

using namespace particulate;

namespace {
  const double radius = 0.1, rho_f = 1000., rho_p = 2000., g = 9.81;

  /** The disk's vertical velocity at time @p t of the run in @p output
   *  (one of its output times). */
  double
  velocity_at(const std::string &output, const double t)
  {
    const std::string file = output + "/particle_0.dat";
    const auto        time = testing::read_column(file, "time");
    const auto        v    = testing::read_column(file, "v");
    for (unsigned int i = 0; i < time.size(); ++i)
      if (std::abs(time[i] - t) < 1e-9)
        return v[i];
    throw std::runtime_error(file + " has no row at t = " + std::to_string(t));
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const std::string                        output = "free_body_added_mass";
  const std::string                        overrides
    = "subsection Time\n set Time step = 0.01\n set End time = 0.05\nend\n"
      "subsection Mesh\n set Upper corner = 1, 1\n"
      " set Subdivisions = 1, 1\n set Refinements = 6\nend\n"
      "subsection Fluid\n set Dynamic viscosity = 1e-3\nend\n"
      "subsection Particles\n"
      " subsection Shape disk\n  set Radius = "
      + std::to_string(radius) + "\n  set Density = " + std::to_string(rho_p)
      + "\n end\n"
        " subsection Particle 0\n  set Position = 0.5, 0.5\n end\nend\n";
  const auto parameters
    = fbm::read_particulate_flow_case(testing::source_path(
                                        "prm/settling-disk/settling-disk.prm"),
                                      overrides);
  testing::run_without_fields<2>(parameters,
                                 "free disk from rest",
                                 output,
                                 MPI_COMM_WORLD);

  const double R_o = 0.5, R = radius;
  const double added    = (R_o * R_o + R * R) / (R_o * R_o - R * R);
  const double expected = (rho_p - rho_f) * g / (rho_p + added * rho_f);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      const double acceleration
        = -(velocity_at(output, 0.05) - velocity_at(output, 0.02)) / 0.03;
      checker.check_relative(acceleration,
                             expected,
                             0.05,
                             "the free disk accelerates with its added mass");
    }
  return checker.exit_code();
}
