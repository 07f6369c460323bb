// The grid-deformation test problem of thesis §5.6 (figure 5.4): the unit
// square on a uniform grid, monitor f(x) = min{1, max{|d - 0.25| / 0.25,
// eps}} with d the distance to the centre, i.e. cells eps times smaller on
// the circle of radius 0.25. For each level: the equidistribution error of
// the grid before and after the basic (BDM) and robust (RDM) deformation
// methods at eps = 0.1, and both methods at the harsher eps = 0.02.
//
// Usage: deformation_test_problem [OUTPUT_DIR [FINEST_LEVEL]]
// Writes OUTPUT_DIR/test-problem.dat (one row per level and method) and the
// deformed level-5 grids as gnuplot files; scripts/validation/
// deformation_test_problem.py draws doc/validation/deformation-*.png.
// Checks (exit 1 if violated): no run leaves an inverted cell; at eps = 0.1
// both methods reduce the L2 equidistribution error at least fivefold on
// every level from 4 up and the error falls with the level; at eps = 0.02
// the robust method succeeds on every level.

#include <particulate/deformation/mesh_quality.h>
#include <particulate/deformation/pde_deformation.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/tria.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace particulate::deformation;

namespace {
  std::function<double(const Point<2> &)>
  test_monitor(const double eps)
  {
    return [eps](const Point<2> &x) {
      const double d = x.distance(Point<2>(0.5, 0.5));
      return std::min(1., std::max(std::abs(d - 0.25) / 0.25, eps));
    };
  }

  struct Row
  {
    unsigned int          level;
    std::string           method;
    double                eps;
    bool                  success;
    unsigned int          steps;
    EquidistributionError before, after;
    MeshQuality           quality;
    unsigned int          fallbacks;
    double                seconds;
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string  output = argc > 1 ? argv[1] : "deformation-test-problem";
  const unsigned int finest = argc > 2 ? std::stoi(argv[2]) : 7;
  std::filesystem::create_directories(output);

  std::vector<Row> rows;
  bool             ok = true;
  for (unsigned int level = 3; level <= finest; ++level)
    for (const double eps : {0.1, 0.02})
      for (const bool robust : {false, true})
        {
          Triangulation<2> tria;
          GridGenerator::hyper_cube(tria);
          tria.refine_global(level);
          PdeDeformation<2>::Settings settings;
          settings.robust              = robust;
          settings.smallest_cell_ratio = eps;
          const PdeDeformation<2> method(settings);
          const auto              monitor = test_monitor(eps);

          Row row;
          row.level  = level;
          row.method = robust ? "robust" : "basic";
          row.eps    = eps;
          row.before = equidistribution_error(tria, monitor);
          Timer timer;
          try
            {
              const DeformationReport report
                = method.deform_to_monitor(tria, monitor);
              row.success   = true;
              row.steps     = report.steps;
              row.fallbacks = report.location_fallbacks;
            }
          catch (const DeformationError &e)
            {
              std::cout << "  level " << level << ", " << row.method << ", eps "
                        << eps << ": " << e.what() << '\n';
              row.success   = false;
              row.steps     = 1;
              row.fallbacks = 0;
            }
          row.seconds = timer.wall_time();
          row.after   = equidistribution_error(tria, monitor);
          row.quality = compute_mesh_quality(tria);
          rows.push_back(row);

          if (row.quality.n_inverted_cells > 0)
            {
              std::cout << "FAIL: inverted cells left behind\n";
              ok = false;
            }
          if (eps == 0.1 && level >= 4
              && !(row.success && row.after.l2 < row.before.l2 / 5.))
            {
              std::cout << "FAIL: level " << level << ' ' << row.method
                        << " at eps = 0.1 did not equidistribute\n";
              ok = false;
            }
          if (eps == 0.02 && robust && !row.success)
            {
              std::cout << "FAIL: the robust method failed at eps = 0.02\n";
              ok = false;
            }
          if (level == 5 && row.success)
            {
              std::ofstream grid(output + "/grid-" + row.method + "-eps"
                                 + (eps == 0.1 ? "0.1" : "0.02") + ".gnuplot");
              GridOut().write_gnuplot(tria, grid);
            }
        }

  // The error of each successful method at eps = 0.1 falls with the level.
  for (const std::string method : {"basic", "robust"})
    {
      double previous = 1e300;
      for (const Row &r : rows)
        if (r.method == method && r.eps == 0.1 && r.success)
          {
            if (!(r.after.l2 < previous))
              {
                std::cout << "FAIL: " << method
                          << " error does not fall with the level\n";
                ok = false;
              }
            previous = r.after.l2;
          }
    }

  std::ofstream dat(output + "/test-problem.dat");
  dat << "# level cells method eps success steps L2_before max_before "
         "L2_after max_after min_scaled_jacobian max_aspect_ratio "
         "fallbacks seconds\n";
  std::cout << "\n level  cells   method  eps   ok  steps  E_L2 before  E_L2 "
               "after  E_max after  min SJ   max AR   s\n";
  for (const Row &r : rows)
    {
      const unsigned int cells = 1u << (2 * r.level);
      dat << r.level << ' ' << cells << ' ' << r.method << ' ' << r.eps << ' '
          << r.success << ' ' << r.steps << ' ' << r.before.l2 << ' '
          << r.before.max << ' ' << r.after.l2 << ' ' << r.after.max << ' '
          << r.quality.min_scaled_jacobian << ' ' << r.quality.max_aspect_ratio
          << ' ' << r.fallbacks << ' ' << r.seconds << '\n';
      std::cout << std::setw(6) << r.level << std::setw(7) << cells
                << std::setw(9) << r.method << std::setw(6) << r.eps
                << std::setw(4) << (r.success ? "yes" : "no") << std::setw(6)
                << r.steps << std::setw(13) << std::setprecision(4)
                << r.before.l2 << std::setw(12) << r.after.l2 << std::setw(12)
                << r.after.max << std::setw(9) << r.quality.min_scaled_jacobian
                << std::setw(9) << r.quality.max_aspect_ratio << std::setw(8)
                << std::setprecision(3) << r.seconds << '\n';
    }
  std::cout << (ok ? "\nall checks passed\n" : "\nCHECKS FAILED\n");
  return ok ? 0 : 1;
}
