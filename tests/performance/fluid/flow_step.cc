// Benchmark (label performance): the cost of a time step of the flow solver
// alone, per refinement level, on the two set-ups of issue 2:
//  - dfg-2d-2: the DFG 2D-2 case of the library (Re = 100, fractional-step
//    theta, dt = 0.01 s), 2D;
//  - channel-3d: the DFG 3D channel (prm/dfg-3d-1z) at the inflow of the
//    time-dependent 3D-2Z benchmark (Um = 2.25 m/s, Re = 100), fractional-step
//    theta, dt = 0.01 s.
// Each level runs the same steps from rest with output off and prints DoFs,
// velocity nodes, seconds per step (the run's "time step (total)" timer
// section: everything but diagnostics and output), microseconds per
// velocity-node-step per core, nonlinear and linear iterations (and the
// linear iterations per nonlinear step against the level before: the
// multigrid's robustness under refinement), memory per DoF and the
// bandwidth the assembled matrix reaches in a product, and the bandwidth
// bound of the linear solves (bandwidth_bound.h). Never gates on time.
//
// Usage: mpirun -np 2 bench_flow_step [--steps N] [--set "prm text"]
//          [dfg-2d-2 level...] [channel-3d level...]
// The peak resident set is a high-water mark: list the levels coarse to
// fine.

#include <particulate/fluid/flow_simulation.h>

#include <deal.II/base/mpi.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "../../fluid/test_utilities.h"
#include "../bandwidth_bound.h"
#include "../machine_measurements.h"
#include "../phase_table.h"

using namespace dealii;
using namespace particulate;
using namespace particulate::benchmarks;

namespace {
  struct Row
  {
    unsigned int          level;
    fluid::FlowRunSummary summary;
    double                step_seconds, spmv_bandwidth, resident, matrix_bytes;
  };

  template <int dim>
  Row
  run_level(const std::string &library_name,
            const std::string &overrides,
            const unsigned int level,
            MPI_Comm           comm)
  {
    auto parameters
      = testing::library_case(library_name,
                              overrides + "subsection Mesh\n set Refinements = "
                                + std::to_string(level) + "\nend\n");
    parameters.output.directory = "bench_flow_step_run";
    parameters.output.write_vtu = false;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::filesystem::create_directories(parameters.output.directory);
    MPI_Barrier(comm);
    fluid::FlowSimulation<dim> simulation(parameters, library_name, comm);
    double                     spmv = 0., matrix_bytes = 0.;
    simulation.set_flow_inspector([&](const fluid::NavierStokes<dim> &flow) {
      spmv = matrix_vector_bandwidth(flow, matrix_bytes);
    });
    std::cout.setstate(std::ios::failbit); // the run's own log
    const auto summary = simulation.run();
    std::cout.clear();
    return {level,
            summary,
            summary.seconds("time step (total)") / summary.n_steps,
            spmv,
            peak_resident_bytes(comm),
            matrix_bytes};
  }
} // namespace

namespace {
  const double time_step = 0.01;

  /** Run @p levels of @p setup. */
  std::vector<Row>
  run_setup(const std::string               &setup,
            const std::vector<unsigned int> &levels,
            const unsigned int               steps,
            const std::string               &extra,
            MPI_Comm                         comm)
  {
    const double k    = time_step;
    const auto   time = "subsection Time\n set Scheme = fractional-step "
                        "theta\n set Time step = "
                      + std::to_string(k) + "\n set End time = "
                      + std::to_string(steps * k) + "\nend\n";
    const unsigned int dim = setup == "dfg-2d-2" ? 2 : 3;
    std::vector<Row>   rows;
    for (const unsigned int level : levels)
      if (dim == 2)
        rows.push_back(run_level<2>("dfg-2d-2", time + extra, level, comm));
      else
        rows.push_back(run_level<3>(
          "dfg-3d-1z",
          time
            + "subsection Boundary conditions\n set Velocity constants = "
              "Um = 2.25, H = 0.41\nend\n"
            + extra,
          level,
          comm));
    return rows;
  }

  /** The tables of one set-up (rank 0). */
  void
  print_setup(const std::string      &setup,
              const std::vector<Row> &rows,
              const unsigned int      steps,
              const double            read_bandwidth,
              const unsigned int      n_ranks)
  {
    const double       k   = time_step;
    const unsigned int dim = setup == "dfg-2d-2" ? 2 : 3;
    std::printf("\n%s, fractional-step theta, dt = %g s, %u steps from rest "
                "per level, %u MPI ranks\n\n",
                setup.c_str(),
                k,
                steps,
                n_ranks);
    std::printf(
      "| level | cells | DoFs | velocity nodes | s per step | us "
      "per velocity-node-step per core | nonlinear its/step | "
      "linear its/step | linear its per nonlinear step (growth) | "
      "L_p CG its/solve | system matrix B/DoF | solver memory B/DoF | peak RSS B/DoF | "
      "SpMV GB/s (%% of read) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    double previous = 0.;
    for (const auto &r : rows)
      {
        const auto  &s     = r.summary;
        const double nodes = double(s.n_velocity_dofs) / dim;
        const double per_newton
          = double(s.linear_iterations) / s.nonlinear_iterations;
        char growth[32] = "";
        if (previous > 0.)
          std::snprintf(growth,
                        sizeof(growth),
                        " (%+.0f %%)",
                        100. * (per_newton / previous - 1.));
        previous = per_newton;
        std::printf("| %u | %lu | %lu | %.0f | %.3f | %.1f | %.2f | %.1f | "
                    "%.1f%s | %.1f | %.0f | %.0f | %.0f | %.1f (%.0f %%) |\n",
                    r.level,
                    s.n_cells,
                    s.n_dofs,
                    nodes,
                    r.step_seconds,
                    r.step_seconds * n_ranks / nodes * 1e6,
                    double(s.nonlinear_iterations) / s.n_steps,
                    double(s.linear_iterations) / s.n_steps,
                    per_newton,
                    growth,
                    double(s.pressure_poisson_iterations)
                      / std::max(s.pressure_poisson_solves, 1ul),
                    r.matrix_bytes / s.n_dofs,
                    double(s.flow_memory_bytes) / s.n_dofs,
                    r.resident / s.n_dofs,
                    r.spmv_bandwidth,
                    100. * r.spmv_bandwidth / read_bandwidth);
      }
    std::vector<ProfiledRun> runs;
    for (const auto &r : rows)
      runs.push_back(
        {"level " + std::to_string(r.level), &r.summary, r.summary.n_steps});
    print_phase_table(runs);
    print_bandwidth_bound(runs, read_bandwidth);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool   root  = Utilities::MPI::this_mpi_process(comm) == 0;
  unsigned int steps = 10;
  std::string  extra;
  std::vector<std::pair<std::string, std::vector<unsigned int>>> setups;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--steps" && i + 1 < argc)
        steps = std::atoi(argv[++i]);
      else if (arg == "--set" && i + 1 < argc)
        extra += std::string(argv[++i]) + "\n";
      else if (arg == "dfg-2d-2" || arg == "channel-3d")
        setups.push_back({arg, {}});
      else if (!setups.empty() && !arg.empty()
               && std::isdigit(static_cast<unsigned char>(arg[0])))
        setups.back().second.push_back(std::atoi(arg.c_str()));
      else
        {
          if (root)
            std::cerr << "bench_flow_step: unknown argument '" << arg
                      << "'\nusage: bench_flow_step [--steps N] [--set "
                         "\"prm text\"] dfg-2d-2 level... [channel-3d "
                         "level...]"
                      << std::endl;
          return 1;
        }
    }
  if (setups.empty())
    setups = {{"dfg-2d-2", {2, 3, 4}}, {"channel-3d", {0, 1}}};

  std::vector<std::vector<Row>> results;
  for (const auto &[setup, levels] : setups)
    results.push_back(
      run_setup(setup,
                levels.empty() ? std::vector<unsigned int>{1} : levels,
                steps,
                extra,
                comm));
  // after the runs, so that its arrays do not count in their peak memory
  const double stream  = stream_copy_bandwidth(comm);
  const double reading = stream_read_bandwidth(comm);
  if (!root)
    return 0;
  std::printf("STREAM-like bandwidth, all ranks at once: copy %.1f GB/s "
              "(read + write), read %.1f GB/s\n",
              stream,
              reading);
  for (std::size_t i = 0; i < setups.size(); ++i)
    print_setup(setups[i].first,
                results[i],
                steps,
                reading,
                Utilities::MPI::n_mpi_processes(comm));
  return 0;
}
