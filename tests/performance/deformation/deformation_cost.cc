// Benchmark (label performance): the cost of one mesh-deformation step of
// each method against one coupled time step on the same mesh, per level,
// on the oscillating-cylinder set-up (prm/oscillating-cylinder: channel
// 2.2 x 0.41 on 11 x 2 coarse cells, disk D = 0.1 at (1.1, 0.2)).
// Deformation: MovingMesh::adapt() (reset to the undeformed mesh and adapt,
// what a moving-body run does every step), the median of 5. Coupled step:
// one step of the plain-FBM case (fractional-step theta, dt = 0.01 s,
// prescribed cylinder), the wall time of a 3-step run minus that of a
// 1-step run, divided by 2 (so set-up and the first AMG build drop out).
// Prints a table; never gates on time.
// Usage: bench_deformation_cost [finest level, default 5]

#include <particulate/core/mesh.h>
#include <particulate/deformation/distance_field.h>
#include <particulate/deformation/moving_mesh.h>
#include <particulate/fbm/particulate_flow_simulation.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace dealii;
using namespace particulate;
using Method = deformation::DeformationParameters::Method;

namespace {
  double
  coupled_run_seconds(const unsigned int level, const unsigned int steps)
  {
    const char *root = std::getenv("PARTICULATE_SOURCE_DIR");
    auto        p    = fbm::read_particulate_flow_case(
      std::string(root ? root : ".")
        + "/prm/oscillating-cylinder/oscillating-cylinder.prm",
      "subsection Mesh\n set Refinements = " + std::to_string(level)
        + "\nend\nsubsection Time\n set End time = "
        + std::to_string(0.01 * steps) + "\nend\n");
    p.flow.output.directory = "bench_deformation_cost_run";
    p.flow.output.write_vtu = false;
    std::filesystem::create_directories(p.flow.output.directory);
    std::cout.setstate(std::ios::failbit); // the run's own log
    fbm::ParticulateFlowSimulation<2> simulation(p, "bench", MPI_COMM_SELF);
    const auto                        summary = simulation.run();
    std::cout.clear();
    return summary.wall_seconds;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               finest = argc > 1 ? std::atoi(argv[1]) : 5;
  const deformation::FunctionDistanceField<2> disk(
    [](const Point<2> &x) { return x.distance(Point<2>(1.1, 0.2)) - 0.05; });
  const std::vector<std::pair<Method, std::string>> methods{
    {Method::laplace_kappa, "laplace-kappa"},
    {Method::laplace_alpha, "laplace-alpha"},
    {Method::pde_basic, "pde-basic"},
    {Method::pde_robust, "pde-robust"}};

  std::printf("| level | cells | coupled step [ms] |");
  for (const auto &m : methods)
    std::printf(" %s [ms] (share) |", m.second.c_str());
  std::printf("\n|---|---|---|");
  for (std::size_t i = 0; i < methods.size(); ++i)
    std::printf("---|");
  std::printf("\n");
  for (unsigned int level = 3; level <= finest; ++level)
    {
      core::MeshParameters mesh;
      mesh.lower_corner = {0., 0.};
      mesh.upper_corner = {2.2, 0.41};
      mesh.subdivisions = {11, 2};
      mesh.refinements  = level;
      const double step
        = (coupled_run_seconds(level, 3) - coupled_run_seconds(level, 1)) / 2.;
      std::printf("| %u | %u | %.0f |", level, 22u << (2 * level), 1e3 * step);
      for (const auto &m : methods)
        {
          deformation::DeformationParameters p;
          p.method = m.first;
          p.width  = 0.1;
          deformation::MovingMesh<2> moving(mesh, p);
          std::vector<double>        seconds;
          for (unsigned int k = 0; k < 5; ++k)
            {
              const auto start = std::chrono::steady_clock::now();
              moving.adapt(disk);
              seconds.push_back(std::chrono::duration<double>(
                                  std::chrono::steady_clock::now() - start)
                                  .count());
            }
          std::nth_element(seconds.begin(), seconds.begin() + 2, seconds.end());
          std::printf(" %.2f (%.1f %%) |",
                      1e3 * seconds[2],
                      100. * seconds[2] / step);
        }
      std::printf("\n");
      std::fflush(stdout);
    }
  return 0;
}
