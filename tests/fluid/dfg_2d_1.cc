// DFG benchmark 2D-1 (Schaefer & Turek 1996, steady, Re = 20) from the case
// library's own .prm, on a mesh CI can afford. Gates: c_D within 0.5 %, c_L
// within 3 %, delta_p within 0.5 % of the reference values, for the surface
// integral and for the volume integral of thesis eq. 5.12.
// Usage: fluid_dfg_2d_1 [refinements]

#include <particulate/core/input_file.h>
#include <particulate/fluid/flow_simulation.h>

#include "test_utilities.h"

using namespace particulate;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;

  dealii::ParameterHandler prm;
  fluid::FlowCaseParameters::declare(prm);
  core::parse_input_file(prm,
                         testing::source_path("prm/dfg-2d-1/dfg-2d-1.prm"));
  fluid::FlowCaseParameters parameters;
  parameters.parse(prm);
  parameters.mesh.refinements = argc > 1 ? std::atoi(argv[1]) : 3;
  parameters.output.directory = "dfg_2d_1_output";
  parameters.output.write_vtu = false;
  std::filesystem::create_directories(parameters.output.directory);

  fluid::FlowSimulation<2> simulation(parameters,
                                      "dfg-2d-1.prm",
                                      MPI_COMM_WORLD);
  const auto               result = simulation.run();

  const double c_d = 5.57953523384, c_l = 0.010618948146, dp = 0.11752016697;
  checker.check_relative(result.drag_coefficient, c_d, 5e-3, "c_D (surface)");
  checker.check_relative(result.lift_coefficient, c_l, 3e-2, "c_L (surface)");
  checker.check_relative(result.drag_coefficient_volume,
                         c_d,
                         5e-3,
                         "c_D (volume)");
  checker.check_relative(result.lift_coefficient_volume,
                         c_l,
                         3e-2,
                         "c_L (volume)");
  checker.check_relative(result.pressure_difference, dp, 5e-3, "delta_p");
  return checker.exit_code();
}
