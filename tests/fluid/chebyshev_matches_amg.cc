// The Chebyshev velocity preconditioner ('Velocity preconditioner =
// Chebyshev', for mass-dominated time steps) changes how fast FGMRES
// converges, not what it converges to: three fractional-step-theta steps of
// DFG 2D-2 with tight tolerances give the same drag, lift and pressure
// difference as with the AMG V-cycle, to a relative 1e-8. A steady case that
// asks for it is refused with a message naming the entry.

#include <particulate/core/input_file.h>
#include <particulate/fluid/flow_simulation.h>

#include <stdexcept>

#include "test_utilities.h"

using namespace particulate;


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;

  const std::string tight = "subsection Mesh\n set Refinements = 1\nend\n"
                            "subsection Time\n set End time = 0.03\nend\n"
                            + testing::tight_solver_tolerances();
  const auto amg = testing::run_library_case(
    "dfg-2d-2",
    tight
      + "subsection Linear solver\n set Velocity preconditioner = AMG\nend\n",
    MPI_COMM_SELF,
    "chebyshev_matches_amg_amg");
  const auto chebyshev = testing::run_library_case(
    "dfg-2d-2",
    tight
      + "subsection Linear solver\n set Velocity preconditioner = "
        "Chebyshev\nend\n",
    MPI_COMM_SELF,
    "chebyshev_matches_amg_chebyshev");
  testing::check_coefficients(checker,
                              chebyshev,
                              amg,
                              {1e-8, 1e-8, 1e-8},
                              "Chebyshev against AMG");

  bool refused = false;
  try
    {
      testing::library_case(
        "dfg-2d-1",
        "subsection Linear solver\n set Velocity preconditioner = "
        "Chebyshev\nend\n");
    }
  catch (const std::runtime_error &e)
    {
      refused = std::string(e.what()).find("Velocity preconditioner")
                != std::string::npos;
    }
  checker.check(refused, "a steady case with Chebyshev is refused");
  return checker.exit_code();
}
