// Validation (label validation): DFG 2D-1 with the cylinder as a fixed
// fictitious-boundary body, on refinement levels 3..L of the plain channel
// mesh of prm/dfg-2d-1-fbm (4, 8, 16, ... cells per diameter). Prints c_D and
// c_L beside the body-fitted reference values with their errors and the
// observed order between levels, and writes the table to
// fbm_dfg_2d_1_levels.dat (plotted into doc/validation by
// scripts/validation/plot_fbm_dfg_2d_1.py). Gate: the drag error on the
// finest level is below 1.5 % and smaller than on the coarsest.
// Usage: fbm_dfg_2d_1_levels [finest level, default 5]

#include <particulate/fbm/particulate_flow_simulation.h>

#include <cstdio>

#include "../fluid/test_utilities.h"

using namespace particulate;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const unsigned int finest = argc > 1 ? std::atoi(argv[1]) : 5;
  const bool         root
    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const double c_d_reference = 5.57953523384, c_l_reference = 0.010618948146;

  std::FILE *table
    = root ? std::fopen("fbm_dfg_2d_1_levels.dat", "w") : nullptr;
  if (table)
    std::fprintf(table,
                 "# level cells_per_diameter dofs c_D c_L c_D_reference "
                 "c_L_reference c_D_error c_L_error wall_seconds\n");
  std::vector<double> errors;
  for (unsigned int level = 3; level <= finest; ++level)
    {
      auto parameters = fbm::read_particulate_flow_case(
        testing::source_path("prm/dfg-2d-1-fbm/dfg-2d-1-fbm.prm"),
        "subsection Mesh\n set Refinements = " + std::to_string(level)
          + "\nend\n");
      parameters.flow.output.directory
        = "fbm_dfg_2d_1_level_" + std::to_string(level);
      parameters.flow.output.write_vtu = false;
      if (root)
        std::filesystem::create_directories(parameters.flow.output.directory);
      MPI_Barrier(MPI_COMM_WORLD);
      fbm::ParticulateFlowSimulation<2> simulation(parameters,
                                                   "dfg-2d-1-fbm.prm",
                                                   MPI_COMM_WORLD);
      const auto                        summary = simulation.run();
      // c = 2 F / (rho U_mean^2 D), U_mean = 0.2 m/s, D = 0.1 m, rho = 1
      const double c_d = 2. * summary.force[0][0] / (0.2 * 0.2 * 0.1);
      const double c_l = 2. * summary.force[0][1] / (0.2 * 0.2 * 0.1);
      const double e_d = (c_d - c_d_reference) / c_d_reference;
      const double e_l = (c_l - c_l_reference) / c_l_reference;
      const double cells_per_diameter = 0.1 / (0.2 / (1 << level));
      errors.push_back(std::abs(e_d));
      if (root)
        {
          std::printf("level %u (%4.0f cells/D, %7lu DoFs): c_D = %.5f "
                      "(error %+6.2f %%), c_L = %+.5f (reference %.5f)%s\n",
                      level,
                      cells_per_diameter,
                      summary.n_dofs,
                      c_d,
                      100. * e_d,
                      c_l,
                      c_l_reference,
                      errors.size() > 1 ?
                        (", drag order "
                         + std::to_string(std::log2(errors[errors.size() - 2]
                                                    / errors.back())))
                          .c_str() :
                        "");
          std::fprintf(table,
                       "%u %g %lu %.10g %.10g %.10g %.10g %.6g %.6g %.3f\n",
                       level,
                       cells_per_diameter,
                       summary.n_dofs,
                       c_d,
                       c_l,
                       c_d_reference,
                       c_l_reference,
                       e_d,
                       e_l,
                       summary.wall_seconds);
        }
    }
  if (table)
    std::fclose(table);
  checker.check(errors.back() < 1.5e-2,
                "drag error on the finest level < 1.5 %");
  checker.check(errors.back() < errors.front(),
                "drag error decreases from the coarsest to the finest level");
  return checker.exit_code();
}
