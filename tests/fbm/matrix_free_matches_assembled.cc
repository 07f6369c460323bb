// The matrix-free velocity operator ('Velocity operator = matrix-free')
// applies the same velocity block as the assembled Jacobian, so a run with
// it must reproduce the assembled run; both use the geometric multigrid
// velocity preconditioner, so that the operator is the only difference.
// Each part exercises what the operator has to get right:
//  - DFG 2D-2, three fractional-step-theta steps (Newton term, convection,
//    Dirichlet inflow and no-slip rows, do-nothing outflow): c_D, c_L,
//    delta_p; again with a body force f(x, t) and a Carreau fluid;
//  - ten Cate E4 in the quarter box at Refinements = 0 (3D, free-slip
//    symmetry planes, a sphere thrown downwards so that the covered nodes
//    change and their velocities are imposed, 'nearest' marking so that
//    pressure modes of cut cells are decoupled): velocity and fluid force;
//  - the oscillating cylinder on a mesh adapted with Laplace-kappa every
//    step (the ALE mesh velocity in the convection): drag and lift.
// All on every rank of MPI_COMM_WORLD, solver tolerances tight: the two
// paths also form the Schur complement's L_p differently (an update of a
// kept sum against a product, equal to round-off), which with the default
// tolerances moved the cylinder's lift by 1e-8. The two
// operators differ by round-off only (measured: 1e-16 to 6e-11 relative in
// these quantities), so the bounds below leave room for other compilers,
// not for a different operator; FGMRES iteration counts must agree too
// (within 5 %; measured: identical).

#include <particulate/fbm/particulate_flow_simulation.h>
#include <particulate/fluid/flow_simulation.h>

#include <deal.II/base/mpi.h>

#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  const std::string matrix_free = "subsection Linear solver\n"
                                  " set Velocity operator = matrix-free\n"
                                  "end\n";
  // the assembled side names its operator: a case file may ship either.
  // The V-cycle is rebuilt after every mesh motion: kept, its rebuilds
  // would fall where an iteration count crosses the keep rule's bound, so
  // the iteration totals would compare the rule, not the operators.
  const std::string multigrid
    = "subsection Linear solver\n"
      " set Velocity preconditioner = geometric multigrid\n"
      " set Velocity operator = assembled\n"
      " set Multigrid on a moving mesh = rebuild\nend\n";

  template <int dim>
  fbm::ParticulateFlowSummary
  run_particles(const std::string &case_file,
                const std::string &overrides,
                const std::string &output)
  {
    auto parameters
      = fbm::read_particulate_flow_case(testing::source_path(case_file),
                                        overrides);
    parameters.flow.output.directory = output;
    parameters.flow.output.write_vtu = false;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::create_directories(output);
    MPI_Barrier(MPI_COMM_WORLD);
    fbm::ParticulateFlowSimulation<dim> simulation(parameters,
                                                   case_file,
                                                   MPI_COMM_WORLD);
    return simulation.run();
  }

  double
  per_newton_step(const fluid::RunProfile &run)
  {
    return static_cast<double>(run.linear_iterations)
           / static_cast<double>(run.nonlinear_iterations);
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const auto                               report = [&](const std::string       &what,
                          const fluid::RunProfile &assembled,
                          const fluid::RunProfile &operator_run) {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << what << ": FGMRES iterations per Newton step, assembled "
                << per_newton_step(assembled) << ", matrix-free "
                << per_newton_step(operator_run) << std::endl;
    checker.check(std::abs(per_newton_step(operator_run)
                           - per_newton_step(assembled))
                    <= 0.05 * per_newton_step(assembled),
                  what + ": the same FGMRES iterations (within 5 %)");
  };

  // DFG 2D-2 as it is, then with the paths a library case does not take: a
  // body force varying in space and time (the stage's explicit part of the
  // residual) and a shear-rate dependent viscosity (mu at every quadrature
  // point)
  const std::string tight_dfg
    = "subsection Mesh\n set Refinements = 1\nend\n"
      "subsection Time\n set End time = 0.03\nend\n"
      "subsection Nonlinear solver\n set Absolute tolerance = 1e-12\n"
      " set Relative tolerance = 1e-12\nend\n"
      "subsection Linear solver\n set Relative tolerance = 1e-8\n"
      " set Pressure Poisson tolerance = 1e-8\nend\n"
      + multigrid;
  const std::vector<std::pair<std::string, std::string>> dfg_variants
    = {{"DFG 2D-2", ""},
       {"DFG 2D-2 with a body force f(x, t) and a Carreau fluid",
        "subsection Fluid\n set Body force = 0.5 * sin(20 * t) + y; x * y\n"
        " set Viscosity model = Carreau\n"
        " set Infinite-shear viscosity = 1e-4\n"
        " set Relaxation time = 1\n set Power-law index = 0.6\n"
        "end\n"}};
  for (unsigned int v = 0; v < dfg_variants.size(); ++v)
    {
      const auto &[label, fluid]  = dfg_variants[v];
      const std::string output    = "mf_dfg_" + std::to_string(v);
      const auto        assembled = testing::run_library_case("dfg-2d-2",
                                                       tight_dfg + fluid,
                                                       MPI_COMM_WORLD,
                                                       output + "_assembled");
      const auto        operator_run
        = testing::run_library_case("dfg-2d-2",
                                    tight_dfg + fluid + matrix_free,
                                    MPI_COMM_WORLD,
                                    output + "_matrix_free");
      testing::check_coefficients(checker,
                                  operator_run,
                                  assembled,
                                  {1e-9, 1e-8, 1e-9},
                                  label + ", matrix-free against assembled");
      report(label, assembled, operator_run);
    }

  {
    const std::string tight
      = "subsection Mesh\n set Refinements = 0\nend\n"
        "subsection Time\n set End time = 0.02\nend\n"
        "subsection Particles\n set Covered nodes = nearest\n"
        " subsection Particle 0\n  set Velocity = 0, 0, -0.05\n end\nend\n"
        "subsection Nonlinear solver\n set Absolute tolerance = 1e-14\n"
        " set Relative tolerance = 1e-10\nend\n"
        "subsection Linear solver\n set Relative tolerance = 1e-8\n"
        " set Pressure Poisson tolerance = 1e-8\nend\n"
        + multigrid;
    const auto assembled    = run_particles<3>("prm/ten-cate/ten-cate-e4.prm",
                                            tight,
                                            "mf_ten_cate_assembled");
    const auto operator_run = run_particles<3>("prm/ten-cate/ten-cate-e4.prm",
                                               tight + matrix_free,
                                               "mf_ten_cate_matrix_free");
    checker.check(assembled.n_steps == 4 && operator_run.n_steps == 4,
                  "ten Cate E4: 4 steps each");
    checker.check_relative(operator_run.velocity[0][2],
                           assembled.velocity[0][2],
                           1e-8,
                           "ten Cate E4 quarter box: settling velocity "
                           "matrix-free against assembled");
    checker.check_relative(operator_run.force[0][2],
                           assembled.force[0][2],
                           1e-7,
                           "ten Cate E4: vertical fluid force");
    report("ten Cate E4", assembled, operator_run);
  }

  {
    const std::string coarse
      = "subsection Mesh\n set Refinements = 3\nend\n"
        "subsection Time\n set End time = 0.05\nend\n"
        "subsection Nonlinear solver\n set Absolute tolerance = 1e-12\n"
        " set Relative tolerance = 1e-12\nend\n"
        "subsection Linear solver\n set Relative tolerance = 1e-8\n"
        " set Pressure Poisson tolerance = 1e-8\nend\n"
        // adapted afresh every step (the case file carries its mesh)
        "subsection Mesh deformation\n set Moving bodies = re-adapt\nend\n"
        + multigrid;
    const auto assembled
      = run_particles<2>("prm/oscillating-cylinder/laplace-kappa.prm",
                         coarse,
                         "mf_oscillating_assembled");
    const auto operator_run
      = run_particles<2>("prm/oscillating-cylinder/laplace-kappa.prm",
                         coarse + matrix_free,
                         "mf_oscillating_matrix_free");
    checker.check_relative(operator_run.force[0][0],
                           assembled.force[0][0],
                           1e-9,
                           "oscillating cylinder, Laplace-kappa (ALE): drag "
                           "force matrix-free against assembled");
    checker.check_relative(operator_run.force[0][1],
                           assembled.force[0][1],
                           1e-8,
                           "oscillating cylinder: lift force");
    report("oscillating cylinder", assembled, operator_run);
  }

  int code = checker.exit_code();
  MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return code;
}
