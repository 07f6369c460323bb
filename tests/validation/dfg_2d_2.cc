// Validation (label validation): DFG benchmark 2D-2 (Schaefer & Turek 1996,
// Re = 100, periodic vortex shedding) from the case library's own .prm.
// After the run it reads the case's flow.dat back and measures, over the
// last `window` seconds (several shedding periods, once the flow is
// periodic):
//  - c_D,max and c_L,max, the largest drag and lift coefficients;
//  - the Strouhal number St = D / (U_mean T) with D = 0.1 m, U_mean = 1 m/s
//    and T the mean period between upward crossings of the lift through its
//    mean (crossing times linearly interpolated between steps).
// Gates: the benchmark's intervals c_D,max in [3.22, 3.24],
// c_L,max in [0.99, 1.01], St in [0.295, 0.305]. The time series stays in
// dfg_2d_2_output/flow.dat for the plot (scripts/validation/dfg.py).
// Usage: validation_dfg_2d_2 [refinements [time step [end time [window]]]]

#include <particulate/fluid/flow_simulation.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  /** The columns of a .dat time series written by core::TimeSeriesWriter,
   *  by the names of its header line. */
  std::map<std::string, std::vector<double>>
  read_time_series(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("cannot read " + file);
    std::string line;
    std::getline(in, line);
    std::istringstream       header(line.substr(1)); // after '#'
    std::vector<std::string> names;
    for (std::string name; header >> name;)
      names.push_back(name);
    std::map<std::string, std::vector<double>> columns;
    while (std::getline(in, line))
      {
        std::istringstream row(line);
        for (const auto &name : names)
          {
            double value;
            row >> value;
            columns[name].push_back(value);
          }
      }
    return columns;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const bool                               root
    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::string overrides;
  if (argc > 1)
    overrides += "subsection Mesh\n set Refinements = " + std::string(argv[1])
                 + "\nend\n";
  if (argc > 2)
    overrides += "subsection Time\n set Time step = " + std::string(argv[2])
                 + "\nend\n";
  if (argc > 3)
    overrides
      += "subsection Time\n set End time = " + std::string(argv[3]) + "\nend\n";
  const double window = argc > 4 ? std::atof(argv[4]) : 1.;

  const auto summary = testing::run_library_case<2>("dfg-2d-2",
                                                    overrides,
                                                    MPI_COMM_WORLD,
                                                    "dfg_2d_2_output");
  if (!root)
    return 0;
  auto         series = read_time_series("dfg_2d_2_output/flow.dat");
  const auto  &t = series["time"], &c_d = series["c_D"], &c_l = series["c_L"];
  const double start = summary.end_time - window;
  std::size_t  first = 0;
  while (first < t.size() && t[first] < start)
    ++first;
  if (t.size() - first < 10)
    {
      std::printf("too few steps in the last %g s\n", window);
      return 1;
    }
  double c_d_max = -1e300, c_l_max = -1e300, c_l_mean = 0.;
  for (std::size_t i = first; i < t.size(); ++i)
    {
      c_d_max = std::max(c_d_max, c_d[i]);
      c_l_max = std::max(c_l_max, c_l[i]);
      c_l_mean += c_l[i] / (t.size() - first);
    }
  std::vector<double> crossings;
  for (std::size_t i = first + 1; i < t.size(); ++i)
    if (c_l[i - 1] < c_l_mean && c_l[i] >= c_l_mean)
      crossings.push_back(t[i - 1]
                          + (t[i] - t[i - 1]) * (c_l_mean - c_l[i - 1])
                              / (c_l[i] - c_l[i - 1]));
  if (crossings.size() < 2)
    {
      std::printf("no shedding period in the last %g s\n", window);
      return 1;
    }
  const double period
    = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double strouhal = 0.1 / (1. * period);
  std::printf("DFG 2D-2, %lu DoFs, %u steps to t = %g s, evaluated over the "
              "last %g s (%zu periods):\n  c_D,max = %.4f  c_L,max = %.4f  "
              "St = %.4f  (period %.4f s)\n",
              summary.n_dofs,
              summary.n_steps,
              summary.end_time,
              window,
              crossings.size() - 1,
              c_d_max,
              c_l_max,
              strouhal,
              period);
  checker.check(c_d_max >= 3.22 && c_d_max <= 3.24, "c_D,max in [3.22, 3.24]");
  checker.check(c_l_max >= 0.99 && c_l_max <= 1.01, "c_L,max in [0.99, 1.01]");
  checker.check(strouhal >= 0.295 && strouhal <= 0.305, "St in [0.295, 0.305]");
  return checker.exit_code();
}
