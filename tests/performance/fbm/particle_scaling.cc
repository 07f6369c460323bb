// Benchmark (label performance): what a coupled step costs with 1 to
// 10 000 particles on a fixed mesh, per phase (issue "Many particles",
// doc/performance.md "Many particles").
//
// The case is tests/performance/fbm/particle_scaling.prm: equal spheres
// placed by the random fill in a closed box of water, falling from rest,
// as a user's run of that file would run them (fields written every step,
// the time series every step); their radius is scaled with the cells, so
// that each covers as many nodes on every mesh level. Per mesh level and number
// of spheres it runs the case twice, for `first` and for `first + steps` steps,
// and takes the difference of each timer section over the extra steps: the cost
// of a step of a long run, without the set-up and the one-time work of the
// first steps.
//
// It prints, per level, a table of seconds per step of
//  - containment (classifying the velocity nodes against the bodies),
//  - constraints (the rigid velocities at the covered nodes, the
//    predicted interface),
//  - force integrals (the stress over the cut cells),
//  - the rigid step (contacts, integration, the guards),
//  - the fluid solve (the rest of the coupled step),
//  - output (ParaView files) and the time series (.dat files),
// and the cost each extra particle adds to each phase (from the largest
// set against one sphere). A phase that grows as particles x nodes shows
// an added cost per particle that grows with the mesh level (8 times the
// nodes per level). Never gates on time.
//
// Usage: mpirun -np 2 bench_particle_scaling [--steps N] [--first N]
//          [--levels "1 2"] [--counts "1 10 100 1000 10000"]

#include <particulate/fbm/particulate_flow_simulation.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "../machine_measurements.h"
#include "../phase_table.h"

using namespace dealii;
using namespace particulate;
using namespace particulate::benchmarks;

namespace {
  const double fill_edge = 0.098 - 0.002; // the case file's fill box

  /** The spheres' radius, contact distance and clearance at mesh level
   *  @p level: the case file's at level 1, scaled with the cells, so that a
   *  sphere covers as many nodes at every level (a phase that costs
   *  particles x nodes then shows a larger cost per particle on the finer
   *  mesh). */
  double
  scaled(const double at_level_1, const unsigned int level)
  {
    return at_level_1 * std::pow(2., 1. - double(level));
  }

  /** A phase of the table and its timer section ("": the fluid solve,
   *  what the coupling's own sections leave of "coupled step (total)"). */
  struct Phase
  {
    std::string name, section;
  };

  const std::vector<Phase> phases{{"containment", "fbm: containment"},
                                  {"constraints", "fbm: constraints"},
                                  {"force integrals", "fbm: forces"},
                                  {"rigid step", "rigid bodies"},
                                  {"fluid solve", ""},
                                  {"output (ParaView)", "output"},
                                  {"time series (.dat)", "diagnostics"}};

  /** The coupling's own sections within "coupled step (total)". */
  const std::vector<std::string> coupling_sections{"fbm: containment",
                                                   "fbm: constraints",
                                                   "fbm: forces",
                                                   "rigid bodies"};

  std::vector<unsigned int>
  read_numbers(const std::string &text)
  {
    std::vector<unsigned int> n;
    std::istringstream        in(text);
    for (unsigned int v; in >> v;)
      n.push_back(v);
    return n;
  }

  struct Run
  {
    fbm::ParticulateFlowSummary summary;
    unsigned long               n_particles = 0, covered_nodes = 0;
    /// peak resident set: all ranks together, and the smallest rank's
    /// (one that writes no output)
    double resident = 0., resident_smallest = 0.;
  };

  Run
  run_case(const std::string &case_file,
           const unsigned int level,
           const unsigned int n_particles,
           const unsigned int n_steps,
           const MPI_Comm     comm)
  {
    const double radius = scaled(0.00134, level), gap = scaled(0.0002, level);
    const double bead           = 4. / 3. * M_PI * std::pow(radius, 3);
    const double solid_fraction = n_particles * bead / std::pow(fill_edge, 3);
    std::ostringstream overrides;
    overrides.precision(17);
    overrides << "subsection Mesh\n set Refinements = " << level
              << "\nend\nsubsection Time\n set End time = " << 0.001 * n_steps
              << "\nend\nsubsection Particles\n set Contact distance = " << gap
              << "\n subsection Shape bead\n  set Radius = " << radius
              << "\n end\n subsection Random fill beads\n"
              << "  set Solid fraction = " << solid_fraction
              << "\n  set Clearance = " << gap << "\n end\nend\n";
    auto p = fbm::read_particulate_flow_case(case_file, overrides.str());
    std::filesystem::create_directories(p.flow.output.directory);
    fbm::ParticulateFlowSimulation<3> simulation(p, case_file, comm);
    std::cout.setstate(std::ios::failbit); // the run's own log
    Run run;
    run.summary = simulation.run();
    std::cout.clear();
    const auto covered = simulation.n_covered_nodes();
    run.n_particles    = covered.size();
    run.covered_nodes  = std::accumulate(covered.begin(), covered.end(), 0ul);
    run.resident       = peak_resident_bytes(comm);
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    run.resident_smallest = Utilities::MPI::min(1024. * usage.ru_maxrss, comm);
    return run;
  }

  /** Seconds per extra step of @p phase between the two runs. */
  double
  per_step(const Phase       &phase,
           const Run         &shorter,
           const Run         &longer,
           const unsigned int extra_steps)
  {
    const auto seconds = [&](const Run &r) {
      const auto &s = r.summary;
      if (!phase.section.empty())
        return s.seconds(phase.section);
      double rest = s.seconds("coupled step (total)");
      for (const auto &name : coupling_sections)
        rest -= s.seconds(name);
      return rest;
    };
    return (seconds(longer) - seconds(shorter)) / extra_steps;
  }

  double
  whole_step(const Run &shorter, const Run &longer, const unsigned int extra)
  {
    double sum = 0.;
    for (const auto &name : {"coupled step (total)", "output", "diagnostics"})
      sum += longer.summary.seconds(name) - shorter.summary.seconds(name);
    return sum / extra;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool                root = Utilities::MPI::this_mpi_process(comm) == 0;
  const auto                n_ranks = Utilities::MPI::n_mpi_processes(comm);
  unsigned int              steps = 4, first = 2;
  std::vector<unsigned int> levels{1, 2}, counts{1, 10, 100, 1000, 10000};
  for (int i = 1; i + 1 < argc; i += 2)
    {
      const std::string arg = argv[i], value = argv[i + 1];
      if (arg == "--steps")
        steps = std::atoi(value.c_str());
      else if (arg == "--first")
        first = std::atoi(value.c_str());
      else if (arg == "--levels")
        levels = read_numbers(value);
      else if (arg == "--counts")
        counts = read_numbers(value);
    }

  const char       *source    = std::getenv("PARTICULATE_SOURCE_DIR");
  const std::string case_file = std::string(source ? source : ".")
                                + "/tests/performance/fbm/particle_scaling.prm";

  struct Row
  {
    unsigned int level;
    Run          shorter, longer;
  };
  std::vector<Row> rows;
  for (const unsigned int level : levels)
    for (const unsigned int n : counts)
      {
        Row row{level,
                run_case(case_file, level, n, first, comm),
                run_case(case_file, level, n, first + steps, comm)};
        if (root)
          std::fprintf(stderr,
                       "level %u, %lu spheres: %.2f s per step\n",
                       level,
                       row.longer.n_particles,
                       whole_step(row.shorter, row.longer, steps));
        rows.push_back(std::move(row));
      }
  if (!root)
    return 0;

  std::printf("Spheres falling in a closed box of water (radius 1.34 mm at "
              "level 1, scaled with the cells), fractional-step theta, dt = "
              "1 ms; seconds per step over steps %u to %u (the difference of "
              "two runs), %u MPI ranks\n",
              first + 1,
              first + steps,
              n_ranks);
  for (const unsigned int level : levels)
    {
      std::vector<const Row *> at_level;
      for (const auto &row : rows)
        if (row.level == level)
          at_level.push_back(&row);
      const auto &s = at_level.front()->longer.summary;
      std::printf("\nLevel %u: %lu DoFs, %.0f velocity nodes\n\n| phase |",
                  level,
                  s.n_dofs,
                  s.n_velocity_dofs / 3.);
      for (const Row *row : at_level)
        std::printf(" %lu spheres |", row->longer.n_particles);
      std::printf(" added per particle [us] |\n|---|");
      for (std::size_t i = 0; i <= at_level.size(); ++i)
        std::printf("---|");
      std::printf("\n");
      const Row   &fewest = *at_level.front(), &most = *at_level.back();
      const double added_particles
        = double(most.longer.n_particles) - fewest.longer.n_particles;
      for (const Phase &phase : phases)
        {
          std::printf("| %s |", phase.name.c_str());
          for (const Row *row : at_level)
            std::printf(" %.4f |",
                        per_step(phase, row->shorter, row->longer, steps));
          const double added
            = per_step(phase, most.shorter, most.longer, steps)
              - per_step(phase, fewest.shorter, fewest.longer, steps);
          std::printf(" %.2f |\n",
                      added_particles > 0 ? 1e6 * added / added_particles : 0.);
        }
      std::printf("| whole step |");
      for (const Row *row : at_level)
        std::printf(" %.4f |", whole_step(row->shorter, row->longer, steps));
      std::printf(" %.2f |\n",
                  added_particles > 0 ?
                    1e6
                      * (whole_step(most.shorter, most.longer, steps)
                         - whole_step(fewest.shorter, fewest.longer, steps))
                      / added_particles :
                    0.);
      std::printf("| covered velocity nodes |");
      for (const Row *row : at_level)
        std::printf(" %lu |", row->longer.covered_nodes);
      std::printf(" |\n| FGMRES its per step |");
      for (const Row *row : at_level)
        std::printf(" %.1f |",
                    double(row->longer.summary.linear_iterations
                           - row->shorter.summary.linear_iterations)
                      / steps);
      std::printf(" |\n| peak resident memory, all ranks [MiB] |");
      for (const Row *row : at_level)
        std::printf(" %.0f |", row->longer.resident / (1 << 20));
      std::printf(" |\n| peak resident memory, smallest rank [MiB] |");
      for (const Row *row : at_level)
        std::printf(" %.0f |", row->longer.resident_smallest / (1 << 20));
      std::printf(" |\n");
      // every timer section, over the extra steps
      std::vector<fluid::RunProfile> extra;
      for (const Row *row : at_level)
        {
          fluid::RunProfile d;
          for (const auto &[name, seconds] : row->longer.summary.phase_seconds)
            d.phase_seconds[name]
              = seconds - row->shorter.summary.seconds(name);
          extra.push_back(d);
        }
      std::vector<ProfiledRun> profiled;
      for (std::size_t i = 0; i < at_level.size(); ++i)
        profiled.push_back(
          {std::to_string(at_level[i]->longer.n_particles) + " spheres",
           &extra[i],
           steps});
      print_phase_table(profiled);
    }
  return 0;
}
