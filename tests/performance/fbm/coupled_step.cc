// Benchmark (label performance): the cost of one coupled time step of the
// fictitious boundary method on the ten Cate E4 set-up
// (prm/ten-cate/ten-cate-e4.prm: quarter box, sphere settling from rest),
// per refinement level, against the reference code's figures of issue 8.
//
// Per level it runs the case for a few steps with output off and prints
//  - DoFs, velocity nodes, seconds per coupled step (everything of a step
//    but output and diagnostics: the run's "coupled step (total)" timer
//    section divided by the steps), and the figure of merit,
//    microseconds per velocity-node-step per core; both also for the
//    steps after the first two, which carry the one-time set-ups (mesh,
//    DoFs, operators, the first multigrid hierarchies), i.e. what a step of
//    a long run costs;
//  - nonlinear and FGMRES iterations per step, velocity AMG set-ups;
//  - memory: the flow solver's matrices, preconditioners and vectors per
//    DoF, and the peak resident set of all ranks per DoF;
//  - bandwidth: a STREAM-like copy (read + write bytes) and read on all
//    ranks at once, and what the product with the final system matrix achieves
//    (its bytes, values and column indices, over its time); the peak
//    resident set is a high-water mark, so list the levels coarse to fine;
//  - the per-phase profile of the run's timers;
//  - the bandwidth bound of the linear solves: the bytes their parts must
//    stream (bandwidth_bound.h) over the read bandwidth, against the
//    FGMRES time measured.
// The default is the reference's set-up (Crank-Nicolson, dt = 1 ms).
// Never gates on time.
//
// Usage: mpirun -np 2 bench_coupled_step [--steps N]
//          [--scheme "Crank-Nicolson"|"fractional-step theta"]
//          [--time-step k] [--set "subsection...end"] level...

#include <particulate/fbm/particulate_flow_simulation.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

#include "../bandwidth_bound.h"
#include "../machine_measurements.h"
#include "../phase_table.h"

using namespace dealii;
using namespace particulate;
using namespace particulate::benchmarks;


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool                root = Utilities::MPI::this_mpi_process(comm) == 0;
  const auto                n_ranks = Utilities::MPI::n_mpi_processes(comm);
  unsigned int              steps   = 10;
  std::string               scheme  = "Crank-Nicolson", extra;
  double                    k       = 0.001;
  std::vector<unsigned int> levels;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--steps" && i + 1 < argc)
        steps = std::atoi(argv[++i]);
      else if (arg == "--scheme" && i + 1 < argc)
        scheme = argv[++i];
      else if (arg == "--time-step" && i + 1 < argc)
        k = std::atof(argv[++i]);
      else if (arg == "--set" && i + 1 < argc)
        extra += std::string(argv[++i]) + "\n";
      else
        levels.push_back(std::atoi(arg.c_str()));
    }
  if (levels.empty())
    levels = {1};

  const char       *source = std::getenv("PARTICULATE_SOURCE_DIR");
  const std::string case_file
    = std::string(source ? source : ".") + "/prm/ten-cate/ten-cate-e4.prm";

  struct Row
  {
    unsigned int                level;
    fbm::ParticulateFlowSummary summary;
    double step_seconds, later_step_seconds, spmv_bandwidth, resident,
      matrix_bytes;
  };
  std::vector<Row> rows;
  for (const unsigned int level : levels)
    {
      auto p = fbm::read_particulate_flow_case(
        case_file,
        "subsection Mesh\n set Refinements = " + std::to_string(level)
          + "\nend\nsubsection Time\n set Scheme = " + scheme
          + "\n set Time step = " + std::to_string(k) + "\n set End time = "
          + std::to_string(steps * k) + "\nend\n" + extra);
      p.flow.output.directory = "bench_coupled_step_run";
      p.flow.output.write_vtu = false;
      std::filesystem::create_directories(p.flow.output.directory);
      fbm::ParticulateFlowSimulation<3> simulation(p, case_file, comm);
      double                            spmv = 0., matrix_bytes = 0.;
      simulation.set_flow_inspector([&](const fluid::NavierStokes<3> &flow) {
        spmv = matrix_vector_bandwidth(flow, matrix_bytes);
      });
      std::cout.setstate(std::ios::failbit); // the run's own log
      const auto summary = simulation.run();
      std::cout.clear();
      const auto  &each  = summary.step_seconds;
      const double later = each.size() > 2 ?
                             std::accumulate(each.begin() + 2, each.end(), 0.)
                               / (each.size() - 2) :
                             std::nan("");
      rows.push_back({level,
                      summary,
                      summary.seconds("coupled step (total)") / summary.n_steps,
                      later,
                      spmv,
                      peak_resident_bytes(comm),
                      matrix_bytes});
    }
  // after the runs, so that its arrays do not count in their peak memory
  const double stream  = stream_copy_bandwidth(comm);
  const double reading = stream_read_bandwidth(comm);
  if (!root)
    return 0;

  std::printf("ten Cate E4, quarter box, %s, dt = %g s, %u steps per level, "
              "%u MPI ranks\nSTREAM-like bandwidth, all ranks at once: copy "
              "%.1f GB/s (read + write), read %.1f GB/s\n\n",
              scheme.c_str(),
              k,
              steps,
              n_ranks,
              stream,
              reading);
  std::printf("| level | cells/D | DoFs | velocity nodes | s per step | "
              "us per velocity-node-step per core | s per step, steps 3-N | "
              "us, steps 3-N | nonlinear its/step | "
              "FGMRES its/step | L_p CG its/solve | AMG set-ups | system "
              "matrix B/DoF | solver memory B/DoF | peak RSS B/DoF | SpMV "
              "GB/s (%% of read) |\n");
  std::printf(
    "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto &r : rows)
    {
      const auto  &s     = r.summary;
      const double nodes = s.n_velocity_dofs / 3.;
      std::printf(
        "| %u | %d | %lu | %.0f | %.3f | %.1f | %.3f | %.1f | %.2f | %.1f | "
        "%.1f | %.0f | %.0f | %.0f | %.0f | %.1f (%.0f %%) |\n",
        r.level,
        3 << r.level,
        s.n_dofs,
        nodes,
        r.step_seconds,
        r.step_seconds * n_ranks / nodes * 1e6,
        r.later_step_seconds,
        r.later_step_seconds * n_ranks / nodes * 1e6,
        double(s.nonlinear_iterations) / s.n_steps,
        double(s.linear_iterations) / s.n_steps,
        double(s.pressure_poisson_iterations)
          / std::max(s.pressure_poisson_solves, 1ul),
        s.phase_calls.count("fluid: velocity AMG setup") ?
          s.phase_calls.at("fluid: velocity AMG setup") :
          0.,
        r.matrix_bytes / s.n_dofs,
        double(s.flow_memory_bytes) / s.n_dofs,
        r.resident / s.n_dofs,
        r.spmv_bandwidth,
        100. * r.spmv_bandwidth / reading);
    }
  for (const auto &r : rows)
    {
      std::printf("\nSeconds per step, level %u:", r.level);
      for (const double seconds : r.summary.step_seconds)
        std::printf(" %.3f", seconds);
    }
  std::printf("\n\n");
  std::vector<ProfiledRun> runs;
  for (const auto &r : rows)
    runs.push_back(
      {"level " + std::to_string(r.level), &r.summary, r.summary.n_steps});
  print_phase_table(runs);
  print_bandwidth_bound(runs, reading);
  return 0;
}
