// A mirror plane reproduces the full domain: the disk of prm/settling-disk
// settles on the box's vertical mid-plane, once in the full box and once in
// its right half with the mid-plane as a free-slip symmetry plane
// ('Symmetry planes = x-'), on the same cells (1.25 mm). The half run sees
// half of the disk; its force completed by the mirror image, the disk's
// motion and the fluid's kinetic energy (doubled) must equal the full run's
// to the solver tolerances.

#include <particulate/fbm/particulate_flow_simulation.h>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  const std::string tight
    = "subsection Time\n set End time = 0.015\nend\n"
      "subsection Nonlinear solver\n set Absolute tolerance = 1e-14\n"
      " set Relative tolerance = 1e-10\nend\n"
      "subsection Linear solver\n set Relative tolerance = 1e-9\n"
      " set Pressure Poisson tolerance = 1e-8\nend\n";

  std::pair<fbm::ParticulateFlowSummary, double>
  run(const std::string &overrides, const std::string &output)
  {
    auto parameters = fbm::read_particulate_flow_case(
      testing::source_path("prm/settling-disk/settling-disk.prm"),
      tight + overrides);
    parameters.flow.output.directory = output;
    parameters.flow.output.write_vtu = false;
    std::filesystem::create_directories(output);
    fbm::ParticulateFlowSimulation<2> simulation(parameters,
                                                 "settling-disk.prm",
                                                 MPI_COMM_WORLD);
    const auto                        summary = simulation.run();
    // the fluid's kinetic energy at the end: column 2 of flow.dat
    std::ifstream series(output + "/flow.dat");
    std::string   line, last;
    while (std::getline(series, line))
      if (!line.empty() && line[0] != '#')
        last = line;
    std::istringstream row(last);
    double             t = 0., energy = 0.;
    row >> t >> energy;
    return {summary, energy};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;

  const auto [full, full_energy]
    = run("subsection Mesh\n set Refinements = 4\nend\n", "symmetry_full");
  const auto [half, half_energy]
    = run("subsection Mesh\n set Lower corner = 0.01, 0\n"
          " set Subdivisions = 1, 4\n set Refinements = 3\nend\n"
          "subsection Boundary conditions\n set Free-slip = 0\n"
          " set No-slip = 1, 2, 3\nend\n"
          "subsection Particles\n set Locked translations = x\n"
          " set Symmetry planes = x-\n set Domain walls = x+, y-, y+\nend\n",
          "symmetry_half");

  checker.check(full.n_dofs > 1.9 * half.n_dofs,
                "the half run has half the DoFs");
  checker.check_relative(half.velocity[0][1],
                         full.velocity[0][1],
                         1e-6,
                         "settling velocity, half vs full domain");
  checker.check_relative(half.force[0][1],
                         full.force[0][1],
                         1e-6,
                         "vertical fluid force, half (mirrored) vs full");
  // the mirrored half run has no horizontal force by construction; the
  // full run must find it from a symmetric flow
  checker.check(std::abs(full.force[0][0]) < 1e-6 * std::abs(full.force[0][1]),
                "full run: no horizontal force on the disk on the mid-plane");
  checker.check_relative(half_energy,
                         full_energy,
                         1e-6,
                         "fluid kinetic energy, half (doubled) vs full");
  return checker.exit_code();
}
