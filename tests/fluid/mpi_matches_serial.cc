// The distributed solver reproduces the serial one: run the same cases on
// all ranks of MPI_COMM_WORLD and on rank 0 alone, and require drag, lift and
// pressure difference to agree to a relative 1e-8. Steady DFG 2D-1 and three
// fractional-step-theta steps of DFG 2D-2, both on a coarse mesh and with
// tight solver tolerances (the partitioning changes the AMG, so agreement is
// to the nonlinear and linear tolerances, not to round-off).

#include <particulate/core/input_file.h>
#include <particulate/fluid/flow_simulation.h>

#include "test_utilities.h"

using namespace particulate;


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const unsigned int                       rank
    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const unsigned int n_ranks
    = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  checker.check(n_ranks > 1, "runs on more than one rank");

  const std::string tight = "subsection Mesh\n set Refinements = 1\nend\n"
                            + testing::tight_solver_tolerances();
  const std::string unsteady
    = tight + "subsection Time\n set End time = 0.03\nend\n";

  for (const auto &[case_name, extra] :
       {std::pair<std::string, std::string>{"dfg-2d-1", tight},
        std::pair<std::string, std::string>{"dfg-2d-2", unsteady}})
    {
      const auto            parallel = testing::run_library_case(case_name,
                                                      extra,
                                                      MPI_COMM_WORLD,
                                                      case_name + "_parallel");
      fluid::FlowRunSummary serial;
      if (rank == 0)
        serial = testing::run_library_case(case_name,
                                           extra,
                                           MPI_COMM_SELF,
                                           case_name + "_serial");
      if (rank == 0)
        {
          testing::check_coefficients(checker,
                                      parallel,
                                      serial,
                                      {1e-8, 1e-8, 1e-8},
                                      case_name + " on "
                                        + std::to_string(n_ranks) + " ranks");
        }
      MPI_Barrier(MPI_COMM_WORLD);
    }
  int code = checker.exit_code();
  MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return code;
}
