// Validation (label validation): the steady DFG benchmarks with a body-fitted
// cylinder on a sequence of mesh levels, from the case library's own .prm:
//  - dfg-2d-1 (Schaefer & Turek 1996, 2D-1, Re = 20) against the reference
//    values c_D = 5.57953523384, c_L = 0.010618948146,
//    delta_p = 0.11752016697;
//  - dfg-3d-1z (3D-1Z, Re = 20) against the benchmark's intervals
//    c_D in [6.05, 6.25], c_L in [0.008, 0.010], delta_p in [0.165, 0.175]
//    and the later resolved values c_D = 6.18533, c_L = 0.009401 (John 2002;
//    Braack & Richter 2006).
// Prints a table per level (cells, DoFs, c_D, c_L, delta_p with their
// errors, Newton steps, linear iterations per Newton step, wall time) and
// writes it to <case>_levels.dat for doc/validation/dfg.md
// (scripts/validation/dfg.py plots it). Gates: each error (surface
// integrals and delta_p; for 3D-1Z delta_p against the middle of its
// interval) is smaller on the finest level than on the coarsest, and the
// finest level is within the regression gates of tests/fluid/dfg_2d_1 (2D:
// c_D and delta_p 0.5 %, c_L 3 %) or, in 3D, c_D and c_L inside the
// benchmark's intervals (delta_p converges slowest, from above: it is
// reported, doc/validation/dfg.md).
// Usage: validation_dfg_steady_levels dfg-2d-1|dfg-3d-1z coarsest finest

#include <particulate/fluid/flow_simulation.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  struct Reference
  {
    double c_d, c_l, delta_p;
  };

  template <int dim>
  fluid::FlowRunSummary
  run_level(const std::string &name, const unsigned int level)
  {
    return testing::run_library_case<dim>(name,
                                          "subsection Mesh\n set Refinements = "
                                            + std::to_string(level) + "\nend\n",
                                          MPI_COMM_WORLD,
                                          name + "_level_"
                                            + std::to_string(level));
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const std::string  name     = argc > 1 ? argv[1] : "dfg-2d-1";
  const unsigned int coarsest = argc > 2 ? std::atoi(argv[2]) : 1;
  const unsigned int finest   = argc > 3 ? std::atoi(argv[3]) : 4;
  const bool         root
    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  if ((name != "dfg-2d-1" && name != "dfg-3d-1z") || finest <= coarsest)
    {
      if (root)
        std::cerr << "usage: validation_dfg_steady_levels "
                     "dfg-2d-1|dfg-3d-1z coarsest finest (finest > coarsest)"
                  << std::endl;
      return 1;
    }
  const bool      three_d = name == "dfg-3d-1z";
  const Reference reference
    = three_d ? Reference{6.18533, 0.009401, 0.170} :
                Reference{5.57953523384, 0.010618948146, 0.11752016697};

  std::FILE *table
    = root ? std::fopen((name + "_levels.dat").c_str(), "w") : nullptr;
  if (table)
    std::fprintf(table,
                 "# level cells dofs c_D c_L delta_p c_D_volume c_L_volume "
                 "c_D_error c_L_error delta_p_error newton_steps "
                 "linear_per_newton wall_seconds\n");
  if (root)
    std::printf("%s: reference c_D = %.8g, c_L = %.8g, delta_p = %.8g%s\n"
                "| level | cells | DoFs | c_D | error | c_L | error | "
                "delta_p | error | c_D (volume) | Newton | linear/Newton | "
                "wall [s] |\n|---|---|---|---|---|---|---|---|---|---|---|---|"
                "---|\n",
                name.c_str(),
                reference.c_d,
                reference.c_l,
                reference.delta_p,
                three_d ? " (delta_p: middle of the benchmark's interval)" :
                          "");
  std::vector<std::array<double, 3>> errors;
  fluid::FlowRunSummary              last;
  for (unsigned int level = coarsest; level <= finest; ++level)
    {
      const auto s
        = three_d ? run_level<3>(name, level) : run_level<2>(name, level);
      last = s;
      const std::array<double, 3> e{
        {(s.drag_coefficient - reference.c_d) / reference.c_d,
         (s.lift_coefficient - reference.c_l) / reference.c_l,
         (s.pressure_difference - reference.delta_p) / reference.delta_p}};
      errors.push_back(e);
      const double per_newton
        = double(s.linear_iterations) / std::max(1ul, s.nonlinear_iterations);
      if (root)
        {
          std::printf("| %u | %lu | %lu | %.6f | %+.3f %% | %.6f | %+.2f %% "
                      "| %.6f | %+.3f %% | %.6f | %lu | %.1f | %.0f |\n",
                      level,
                      s.n_cells,
                      s.n_dofs,
                      s.drag_coefficient,
                      100. * e[0],
                      s.lift_coefficient,
                      100. * e[1],
                      s.pressure_difference,
                      100. * e[2],
                      s.drag_coefficient_volume,
                      s.nonlinear_iterations,
                      per_newton,
                      s.wall_seconds);
          std::fprintf(table,
                       "%u %lu %lu %.10g %.10g %.10g %.10g %.10g %.6g %.6g "
                       "%.6g %lu %.3f %.1f\n",
                       level,
                       s.n_cells,
                       s.n_dofs,
                       s.drag_coefficient,
                       s.lift_coefficient,
                       s.pressure_difference,
                       s.drag_coefficient_volume,
                       s.lift_coefficient_volume,
                       e[0],
                       e[1],
                       e[2],
                       s.nonlinear_iterations,
                       per_newton,
                       s.wall_seconds);
          std::fflush(stdout);
          std::fflush(table);
        }
    }
  if (table)
    std::fclose(table);

  const char *quantity[] = {"c_D", "c_L", "delta_p"};
  for (unsigned int q = 0; q < 3; ++q)
    checker.check(std::abs(errors.back()[q]) < std::abs(errors.front()[q]),
                  std::string(quantity[q])
                    + " error smaller on the finest level than on the "
                      "coarsest");
  if (three_d)
    {
      checker.check(last.drag_coefficient >= 6.05
                      && last.drag_coefficient <= 6.25,
                    "c_D in [6.05, 6.25]");
      checker.check(last.lift_coefficient >= 0.008
                      && last.lift_coefficient <= 0.010,
                    "c_L in [0.008, 0.010]");
    }
  else
    {
      checker.check_relative(last.drag_coefficient, reference.c_d, 5e-3, "c_D");
      checker.check_relative(last.lift_coefficient, reference.c_l, 3e-2, "c_L");
      checker.check_relative(last.pressure_difference,
                             reference.delta_p,
                             5e-3,
                             "delta_p");
    }
  return checker.exit_code();
}
