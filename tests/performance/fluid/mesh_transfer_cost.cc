// Benchmark (label performance): the cost of carrying the flow over to a
// remeshed (re-adapted) mesh, NavierStokes::transfer_to_moved_mesh(), in
// 3D against the mesh size. A box of 4 x 4 x 8 cells refined r times, Q2/P1
// at rest; the interior vertices move by up to 0.3 (2.4 cells at r = 1,
// 19 at r = 4) along z, as a fresh adaptation moves a carried mesh back.
// Prints cells, velocity nodes, seconds and microseconds per node; the
// cost per node should not grow with the mesh (doc/performance.md, "Mesh
// transfer"). Never gates on time.
//
// Usage: mpirun -np 2 bench_mesh_transfer r...

#include <particulate/core/mesh.h>
#include <particulate/fluid/flow_simulation.h>
#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_tools.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../../fluid/test_utilities.h"

using namespace dealii;
using namespace particulate;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  if (root)
    std::printf("| refinements | cells | velocity nodes | transfer [s] | "
                "us per node per core |\n|---|---|---|---|---|\n");
  for (int a = 1; a < argc; ++a)
    {
      const auto parameters = testing::parameters_from_text(
        std::string("subsection Mesh\n set Type = hyper rectangle\n"
                    " set Lower corner = 0, 0, 0\n set Upper corner = 1, 1, 2\n"
                    " set Subdivisions = 4, 4, 8\n set Refinements = ")
          + argv[a] + "\nend\n",
        "bench_mesh_transfer");

      parallel::fullydistributed::Triangulation<3> tria(MPI_COMM_WORLD);
      core::create_mesh(parameters.mesh, tria);
      const std::vector<Point<3>> rest = tria.get_vertices();
      TimerOutput                 timer(MPI_COMM_WORLD,
                        std::cout,
                        TimerOutput::never,
                        TimerOutput::wall_times);
      fluid::NavierStokes<3>      flow(parameters.fluid, tria, timer);
      flow.setup_dofs();
      flow.set_initial_condition(0.);

      MPI_Barrier(MPI_COMM_WORLD);
      Timer clock;
      flow.transfer_to_moved_mesh([&]() {
        for (const auto &cell : tria.cell_iterators())
          for (const auto v : cell->vertex_indices())
            {
              Point<3>     x = rest[cell->vertex_index(v)];
              const double s = std::sin(M_PI * x[0]) * std::sin(M_PI * x[1])
                               * std::sin(M_PI * x[2] / 2.);
              x[2] += 0.3 * s;
              cell->vertex(v) = x;
            }
      });
      clock.stop();
      const double seconds
        = Utilities::MPI::max(clock.wall_time(), MPI_COMM_WORLD);
      const double nodes
        = DoFTools::count_dofs_per_fe_component(flow.get_dof_handler())[0];
      const double cores = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      if (root)
        std::printf("| %s | %u | %.0f | %.2f | %.1f |\n",
                    argv[a],
                    tria.n_global_active_cells(),
                    nodes,
                    seconds,
                    1e6 * seconds * cores / nodes);
    }
  return 0;
}
