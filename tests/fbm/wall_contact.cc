// A disk settling onto the floor of a closed box comes to rest one contact
// distance (one cell, 'Contact distance = auto') above it, held by the rigid
// engine's contact: prm/settling-disk on a 4-cells-per-diameter mesh,
// released two cells above the floor and thrown down at 2 cm/s. Without the
// contact distance the film under the disk drops below a cell, the squeeze
// pressure spikes and the linear solver breaks down (doc/developer/fbm.md,
// "Near contact"); with it the run finishes, and at rest the contact force and
// the fluid force together carry the buoyancy-corrected weight.

#include <particulate/fbm/particulate_flow_simulation.h>

#include "../fluid/test_utilities.h"

using namespace particulate;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  auto parameters = fbm::read_particulate_flow_case(
    testing::source_path("prm/settling-disk/settling-disk.prm"),
    "subsection Mesh\n set Refinements = 5\nend\n"
    "subsection Time\n set End time = 0.08\nend\n"
    "subsection Particles\n subsection Particle 0\n"
    "  set Position = 0.01, 0.0025\n  set Velocity = 0, -0.02\n end\n"
    " set Contact distance = auto\nend\n");
  const std::string output         = "wall_contact";
  parameters.flow.output.directory = output;
  parameters.flow.output.write_vtu = false;
  std::filesystem::create_directories(output);
  fbm::ParticulateFlowSimulation<2> simulation(parameters,
                                               "settling-disk.prm",
                                               MPI_COMM_SELF);
  const auto                        summary = simulation.run();

  const auto  &p      = parameters.particles.bodies.at(0);
  const double radius = p.shape->bounding_box().upper[0];
  const double h      = 0.02 / 32.; // 20 mm box width, 2^5 cells
  const double weight = (p.density - parameters.flow.fluid.properties.density)
                        * M_PI * radius * radius * 9.81;
  // the time series: force (columns 11, 12) and contact force (17, 18)
  const auto series    = testing::read_time_series(output + "/particle_0.dat");
  double     max_force = 0., fluid_y = 0., contact_y = 0., gap = 0.;
  for (const std::vector<double> &c : series)
    {
      max_force = std::max(max_force, std::hypot(c[10], c[11]));
      fluid_y   = c[11];
      contact_y = c[17];
      gap       = c[2] - radius;
    }
  const std::size_t rows = series.size();
  std::cout << "rows " << rows << ", final gap " << gap << " m (h = " << h
            << " m), velocity " << summary.velocity[0].transpose()
            << " m/s; at rest: fluid " << fluid_y << " N + contact "
            << contact_y << " N vs buoyant weight " << weight
            << " N; largest fluid force " << max_force << " N\n";
  checker.check(rows == 81, "all 80 steps written");
  checker.check(gap > 0.9 * h && gap <= h * (1. + 1e-9),
                "rests one contact distance above the floor");
  // frictionless contact: the round-off asymmetry of the flow may let the
  // disk creep sideways, 4 orders of magnitude slower than it arrived
  checker.check(std::abs(summary.velocity[0][1]) < 1e-9
                  && std::abs(summary.velocity[0][0]) < 1e-4,
                "comes to rest on the floor");
  checker.check_relative(fluid_y + contact_y,
                         weight,
                         0.02,
                         "the contact force reported per step closes the force "
                         "balance of the resting disk");
  checker.check(contact_y > 0.5 * weight,
                "the floor, not the fluid, carries the disk at rest");
  checker.check(max_force < 10. * weight,
                "no squeeze-film force spike (|F| < 10 x weight)");
  return checker.exit_code();
}
