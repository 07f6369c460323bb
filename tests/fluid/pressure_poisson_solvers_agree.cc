// How tightly the Schur complement approximation solves with L_p ('Pressure
// Poisson tolerance' in subsection 'Linear solver') changes how fast FGMRES
// converges, not what it converges to: three fractional-step-theta steps of
// DFG 2D-2 with tight outer tolerances give the same drag, lift and pressure
// difference with CG to 1e-2 and CG to 0.3 (the default with
// Cahouet-Chabard), to a relative 1e-8.

#include <particulate/fluid/flow_simulation.h>

#include "test_utilities.h"

using namespace particulate;


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;

  const std::string tight = "subsection Mesh\n set Refinements = 2\nend\n"
                            "subsection Time\n set End time = 0.03\nend\n"
                            + testing::tight_solver_tolerances();
  const auto run = [&](const std::string &tolerance, const std::string &name) {
    return testing::run_library_case(
      "dfg-2d-2",
      tight + "subsection Linear solver\n set Pressure Poisson tolerance = "
        + tolerance + "\nend\n",
      MPI_COMM_SELF,
      "pressure_poisson_solvers_agree_" + name);
  };
  const auto cg_tight = run("1e-2", "cg_1e-2");
  const auto cg_loose = run("0.3", "cg_0.3");
  testing::check_coefficients(checker,
                              cg_loose,
                              cg_tight,
                              {1e-8, 1e-8, 1e-8},
                              "CG to 0.3 against 1e-2");
  return checker.exit_code();
}
