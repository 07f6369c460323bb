// The distributed coupled solver reproduces the serial one: a disk settling
// in a closed box (prm/settling-disk, coarse mesh, 15 steps, thrown sideways
// and down at 2 cm/s so that it moves 0.3 mm, half a node spacing, and the
// set of constrained nodes changes) on all ranks of
// MPI_COMM_WORLD and on rank 0 alone. Velocity, position and fluid force of
// the disk agree to the solver tolerances (the partitioning changes the AMG,
// so agreement is not to round-off). This checks that the constraints inside
// the body, the decoupled pressures and the force integrals are consistent
// across ranks, also for cells on partition boundaries. All three markings
// of the covered nodes are run: 'halfway' and 'nearest' also need the node
// spacings shared across ranks, and decouple pressure modes of cut cells.
// 'inside' is also run with 'Coupling = iterated': every rank must take the
// same number of iterates in every step (the step's collective solves
// would otherwise hang), and their result is the serial one.

#include <particulate/fbm/particulate_flow_simulation.h>

#include <string>
#include <utility>
#include <vector>

#include "../fluid/test_utilities.h"
#include "run_case.h"

using namespace particulate;

namespace {
  fbm::ParticulateFlowSummary
  run(MPI_Comm           comm,
      const std::string &marking,
      const std::string &coupling,
      const std::string &output)
  {
    const auto parameters = fbm::read_particulate_flow_case(
      testing::source_path("prm/settling-disk/settling-disk.prm"),
      "subsection Mesh\n set Refinements = 4\nend\n"
      "subsection Time\n set End time = 0.015\nend\n"
      "subsection Particles\n"
      " subsection Particle 0\n  set Velocity = 0.02, -0.02\n end\n"
      " set Covered nodes = "
        + marking + "\n set Coupling = " + coupling
        + "\nend\n"
          "subsection Nonlinear solver\n set Absolute tolerance = 1e-14\n"
          " set Relative tolerance = 1e-10\nend\n"
          "subsection Linear solver\n set Relative tolerance = 1e-8\n"
          " set Pressure Poisson tolerance = 1e-8\nend\n");
    return testing::run_without_fields<2>(parameters,
                                          "settling-disk.prm",
                                          output,
                                          comm);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const unsigned int                       rank
    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const unsigned int n_ranks
    = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  checker.check(n_ranks > 1, "runs on more than one rank");

  for (const auto &[marking, coupling] :
       std::vector<std::pair<std::string, std::string>>{{"inside", "explicit"},
                                                        {"halfway", "explicit"},
                                                        {"nearest", "explicit"},
                                                        {"inside", "iterated"}})
    {
      const std::string           name     = marking + "_" + coupling;
      const auto                  parallel = run(MPI_COMM_WORLD,
                                marking,
                                coupling,
                                "settling_disk_parallel_" + name);
      fbm::ParticulateFlowSummary serial;
      if (rank == 0)
        {
          serial                  = run(MPI_COMM_SELF,
                       marking,
                       coupling,
                       "settling_disk_serial_" + name);
          const std::string ranks = " on " + std::to_string(n_ranks)
                                    + " ranks, '" + marking + "' marking, "
                                    + coupling + " coupling";
          checker.check(parallel.n_steps == serial.n_steps
                          && serial.n_steps == 15,
                        "same number of steps (15)");
          checker.check_relative(parallel.velocity[0][0],
                                 serial.velocity[0][0],
                                 1e-7,
                                 "horizontal velocity" + ranks);
          checker.check_relative(parallel.velocity[0][1],
                                 serial.velocity[0][1],
                                 1e-7,
                                 "settling velocity" + ranks);
          checker.check_relative(parallel.position[0][1] - 0.03,
                                 serial.position[0][1] - 0.03,
                                 1e-7,
                                 "distance fallen" + ranks);
          checker.check_relative(parallel.force[0][1],
                                 serial.force[0][1],
                                 1e-6,
                                 "vertical fluid force" + ranks);
        }
    }
  int code = checker.exit_code();
  MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return code;
}
