// The coarse solve of the geometric multigrid V-cycle ('Multigrid coarse
// solver' in subsection 'Linear solver') changes what a V-cycle costs, not
// what FGMRES converges to, and 'automatic' picks the path that suits the
// flow:
//  - DFG 2D-2 (fractional-step theta, the mass term dominates the coarse
//    level): 'automatic' runs the Chebyshev polynomial and never the
//    CG + AMG solve; drag, lift and pressure difference agree with the
//    forced CG + AMG run to a relative 1e-8 (tight tolerances: agreement
//    is to them), with at most 10 % more FGMRES iterations per Newton step;
//  - a steady half channel on a coarse mesh of 16 x 32 cells (no mass
//    term: the coarse level carries the viscous operator's condition
//    number, which grows with the number of coarse cells): 'automatic' runs
//    CG + AMG, and a forced Chebyshev polynomial gives the same pressure
//    difference. (On DFG 2D-1's small coarse mesh 'automatic' takes the
//    polynomial even for steady flow, with the same FGMRES iterations as
//    CG + AMG: 728 against 726 at level 2.)

#include <particulate/core/input_file.h>
#include <particulate/fluid/flow_simulation.h>

#include <deal.II/base/mpi.h>

#include <iostream>
#include <string>

#include "test_utilities.h"

using namespace particulate;

namespace {
  const std::string chebyshev_section
    = "fluid: velocity coarse solve (Chebyshev)";
  const std::string cg_amg_section = "fluid: velocity coarse solve (CG + ML)";

  double
  calls(const fluid::FlowRunSummary &run, const std::string &section)
  {
    const auto it = run.phase_calls.find(section);
    return it == run.phase_calls.end() ? 0. : it->second;
  }

  double
  iterations_per_newton_step(const fluid::FlowRunSummary &run)
  {
    return static_cast<double>(run.linear_iterations)
           / static_cast<double>(run.nonlinear_iterations);
  }

  /** @p label: the coarse level of @p run was solved by the path of timer
   *  section @p used alone. */
  void
  check_coarse_path(testing::Checker            &checker,
                    const fluid::FlowRunSummary &run,
                    const std::string           &used,
                    const std::string           &unused,
                    const std::string           &label)
  {
    checker.check(calls(run, used) > 0. && calls(run, unused) == 0., label);
  }

  /** What 'automatic' chose, and the FGMRES iterations per Newton step
   *  against the run with the coarse solve forced to @p other_name. */
  void
  report(const std::string           &label,
         const fluid::FlowRunSummary &automatic,
         const fluid::FlowRunSummary &other,
         const std::string           &other_name)
  {
    std::cout << label << ": coarse solves Chebyshev "
              << calls(automatic, chebyshev_section) << ", CG + AMG "
              << calls(automatic, cg_amg_section)
              << " (automatic); FGMRES iterations per Newton step "
              << iterations_per_newton_step(automatic) << " (automatic), "
              << iterations_per_newton_step(other) << " (" << other_name << ")"
              << std::endl;
  }

  /** DFG 2D-2's case file with @p overrides, the geometric multigrid and
   *  'Multigrid coarse solver = @p choice', on all ranks. */
  fluid::FlowRunSummary
  run_with_coarse_solver(const std::string &overrides,
                         const std::string &choice,
                         const std::string &output)
  {
    return testing::run_library_case(
      "dfg-2d-2",
      overrides
        + "subsection Linear solver\n"
          " set Velocity preconditioner = geometric multigrid\n"
          " set Multigrid coarse solver = "
        + choice + "\nend\n",
      MPI_COMM_WORLD,
      output);
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const unsigned int                       rank
    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const std::string tight = testing::tight_solver_tolerances();

  {
    const std::string unsteady = "subsection Mesh\n set Refinements = 1\nend\n"
                                 "subsection Time\n set End time = 0.02\nend\n"
                                 + tight;
    const auto automatic
      = run_with_coarse_solver(unsteady,
                               "automatic",
                               "coarse_solve_unsteady_automatic");
    const auto cg_amg = run_with_coarse_solver(unsteady,
                                               "CG + AMG",
                                               "coarse_solve_unsteady_cg_amg");
    if (rank == 0)
      report("DFG 2D-2", automatic, cg_amg, "CG + AMG");
    check_coarse_path(checker,
                      automatic,
                      chebyshev_section,
                      cg_amg_section,
                      "DFG 2D-2: automatic solves the coarse level with the "
                      "Chebyshev polynomial only");
    check_coarse_path(checker,
                      cg_amg,
                      cg_amg_section,
                      chebyshev_section,
                      "DFG 2D-2: 'CG + AMG' solves the coarse level with CG "
                      "+ AMG only");
    testing::check_coefficients(checker,
                                automatic,
                                cg_amg,
                                {1e-8, 1e-8, 1e-8},
                                "DFG 2D-2: automatic against CG + AMG");
    checker.check(iterations_per_newton_step(automatic)
                    <= 1.1 * iterations_per_newton_step(cg_amg),
                  "DFG 2D-2: at most 10 % more FGMRES iterations per "
                  "Newton step than with CG + AMG");
  }

  {
    const std::string steady_half_channel
      = "subsection Time\n set Scheme = steady\nend\n"
        "subsection Mesh\n set Type = hyper rectangle\n"
        " set Lower corner = 0, 0\n set Upper corner = 0.5, 1\n"
        " set Subdivisions = 16, 32\n set Refinements = 1\nend\n"
        "subsection Boundary conditions\n set Free-slip = 0\n"
        " set No-slip = 1\n set Dirichlet velocity = 2\n"
        " set Do-nothing = 3\n set Velocity = 0; Um * (1 - 4 * x * x)\n"
        " set Velocity constants = Um = 0.2\nend\n"
        "subsection Forces\n set Body boundary ids =\n"
        " set Pressure point A = 0.1, 0.3\n set Pressure point B = 0.1, 0.7\n"
        "end\n"
        + tight;
    const auto automatic
      = run_with_coarse_solver(steady_half_channel,
                               "automatic",
                               "coarse_solve_steady_automatic");
    const auto chebyshev
      = run_with_coarse_solver(steady_half_channel,
                               "Chebyshev",
                               "coarse_solve_steady_chebyshev");
    if (rank == 0)
      report("steady half channel", automatic, chebyshev, "Chebyshev forced");
    check_coarse_path(checker,
                      automatic,
                      cg_amg_section,
                      chebyshev_section,
                      "steady half channel: automatic solves the coarse "
                      "level with CG + AMG only");
    check_coarse_path(checker,
                      chebyshev,
                      chebyshev_section,
                      cg_amg_section,
                      "steady half channel: 'Chebyshev' solves the coarse "
                      "level with the polynomial only");
    checker.check_relative(chebyshev.pressure_difference,
                           automatic.pressure_difference,
                           1e-8,
                           "steady half channel: delta_p with the "
                           "Chebyshev coarse solve against automatic");
  }

  return checker.exit_code();
}
