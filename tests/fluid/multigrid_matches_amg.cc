// The geometric multigrid velocity preconditioner ('Velocity preconditioner
// = geometric multigrid') changes how FGMRES converges, not what it
// converges to, and it keeps the iteration count nearly independent of the
// mesh:
//  - three fractional-step-theta steps of DFG 2D-2 on all ranks with the
//    multigrid give the drag, lift and pressure difference of the serial
//    AMG run to a relative 1e-8 (tight tolerances: agreement is to them);
//  - FGMRES iterations per Newton step over two steps of DFG 2D-2 on levels
//    1, 2 and 3 grow by at most 30 % per level (the bound of issue 2).

#include <particulate/core/input_file.h>
#include <particulate/fluid/flow_simulation.h>

#include <deal.II/base/mpi.h>

#include <iostream>
#include <string>

#include "test_utilities.h"

using namespace particulate;


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const unsigned int                       rank
    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const std::string multigrid
    = "subsection Linear solver\n"
      " set Velocity preconditioner = geometric multigrid\nend\n";

  {
    const std::string tight
      = "subsection Mesh\n set Refinements = 1\nend\n"
        "subsection Time\n set End time = 0.03\nend\n"
        "subsection Nonlinear solver\n set Absolute tolerance = 1e-12\n"
        " set Relative tolerance = 1e-12\nend\n"
        "subsection Linear solver\n set Relative tolerance = 1e-8\n"
        " set Pressure Poisson tolerance = 1e-8\nend\n";
    const auto            with_multigrid = testing::run_library_case("dfg-2d-2",
                                                          tight + multigrid,
                                                          MPI_COMM_WORLD,
                                                          "multigrid_run");
    fluid::FlowRunSummary with_amg;
    if (rank == 0)
      with_amg = testing::run_library_case("dfg-2d-2",
                                           tight,
                                           MPI_COMM_SELF,
                                           "multigrid_amg_run");
    if (rank == 0)
      {
        checker.check_relative(with_multigrid.drag_coefficient,
                               with_amg.drag_coefficient,
                               1e-8,
                               "c_D with multigrid (all ranks) against AMG "
                               "(serial)");
        checker.check_relative(with_multigrid.lift_coefficient,
                               with_amg.lift_coefficient,
                               1e-8,
                               "c_L");
        checker.check_relative(with_multigrid.pressure_difference,
                               with_amg.pressure_difference,
                               1e-8,
                               "delta_p");
      }
  }

  double previous = 0.;
  for (const unsigned int level : {1u, 2u, 3u})
    {
      const auto run = testing::run_library_case(
        "dfg-2d-2",
        "subsection Mesh\n set Refinements = " + std::to_string(level)
          + "\nend\nsubsection Time\n set End time = 0.02\nend\n" + multigrid,
        MPI_COMM_WORLD,
        "multigrid_level_" + std::to_string(level));
      const double per_newton_step
        = static_cast<double>(run.linear_iterations)
          / static_cast<double>(run.nonlinear_iterations);
      if (rank == 0)
        std::cout << "level " << level << ": " << run.linear_iterations
                  << " FGMRES iterations in " << run.nonlinear_iterations
                  << " Newton steps, " << per_newton_step << " per step"
                  << std::endl;
      if (previous > 0.)
        checker.check(per_newton_step <= 1.3 * previous,
                      "level " + std::to_string(level)
                        + ": iterations per Newton step grow by at most "
                          "30 %");
      previous = per_newton_step;
    }

  return checker.exit_code();
}
