// DFG benchmark 2D-1 with the cylinder as a fixed fictitious-boundary body on
// the plain channel mesh of the case library (prm/dfg-2d-1-fbm). The drag
// comes from the volume integral -int sigma . grad(alpha) of thesis eq. 5.13
// over the cells the cylinder cuts. The FBM describes the cylinder only to
// within a cell, so its drag error is first order in h/D; with 8 cells per
// diameter (refinement 4) we require 2.5 % (the measured error is 1.2 %,
// doc/validation/dfg-2d-1-fbm.md), and the force must not depend on where the
// solver stops. Lift is a difference of large pressure integrals on either side
// of the cylinder and is not resolved by the FBM at this level
// (doc/validation/dfg-2d-1-fbm.md).
// Usage: fbm_dfg_2d_1 [refinements]

#include <particulate/fbm/particulate_flow_simulation.h>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  double
  drag_coefficient(const unsigned int refinements, const std::string &solver)
  {
    auto parameters = fbm::read_particulate_flow_case(
      testing::source_path("prm/dfg-2d-1-fbm/dfg-2d-1-fbm.prm"),
      "subsection Mesh\n set Refinements = " + std::to_string(refinements)
        + "\nend\n" + solver);
    parameters.flow.output.directory = "dfg_2d_1_fbm_output";
    parameters.flow.output.write_vtu = false;
    std::filesystem::create_directories(parameters.flow.output.directory);
    fbm::ParticulateFlowSimulation<2> simulation(parameters,
                                                 "dfg-2d-1-fbm.prm",
                                                 MPI_COMM_WORLD);
    const auto                        summary = simulation.run();
    // c_D = 2 F_x / (rho U_mean^2 D), U_mean = 0.2 m/s, D = 0.1 m, rho = 1
    return 2. * summary.force[0][0] / (1. * 0.2 * 0.2 * 0.1);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const unsigned int refinements = argc > 1 ? std::atoi(argv[1]) : 4;

  const double c_d_reference = 5.57953523384;
  const double c_d           = drag_coefficient(refinements, "");
  checker.check_relative(c_d, c_d_reference, 2.5e-2, "c_D (FBM, volume)");

  const double c_d_tight = drag_coefficient(
    refinements,
    "subsection Nonlinear solver\n set Relative tolerance = 1e-10\nend\n"
    "subsection Linear solver\n set Relative tolerance = 1e-8\nend\n");
  checker.check_relative(c_d,
                         c_d_tight,
                         1e-5,
                         "c_D independent of the solver tolerances");
  return checker.exit_code();
}
