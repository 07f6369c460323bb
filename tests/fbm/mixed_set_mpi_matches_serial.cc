// A mixed set of 26 bodies (prm/mixed-set: spheres of two sizes and
// densities, ellipsoids, boxes) in 3D on all ranks of MPI_COMM_WORLD equals
// the run on rank 0 alone to 1e-8: the final displacement, velocity and
// fluid force of every body, each relative to the largest of its kind over
// the bodies. The bricks start 0.5 mm above the floor's contact distance and
// the grains, their lowest points over the centres of four bricks, 0.2 mm
// above the bricks' (the first nine bodies, then the four grains), so that
// within the six steps the bricks meet the floor and grains meet bricks
// (checked: contact forces in the serial output); the Newton and FGMRES
// tolerances are tightened to 1e-10 so that the partitioning, which changes the
// preconditioners, enters below 1e-8.

#include <particulate/fbm/particulate_flow_simulation.h>

#include "../fluid/test_utilities.h"
#include "run_case.h"

using namespace particulate;

namespace {
  fbm::ParticulateFlowSummary
  run(MPI_Comm comm, const std::string &output)
  {
    const auto parameters = fbm::read_particulate_flow_case(
      testing::source_path("prm/mixed-set/mixed-set.prm"),
      "subsection Time\n set End time = 0.03\nend\n"
      "subsection Particles\n"
      " subsection Lattice bricks\n  set First position = 0.012, 0.012, "
      "0.0085\n end\n"
      " subsection Lattice grains\n  set First position = 0.0276, 0.0296, "
      "0.02097\n  set Spacing = 0.018, 0.018, 0\n end\n"
      "end\n"
      "subsection Nonlinear solver\n set Absolute tolerance = 1e-14\n"
      " set Relative tolerance = 1e-10\nend\n"
      "subsection Linear solver\n set Relative tolerance = 1e-10\nend\n");
    return testing::run_without_fields<3>(parameters,
                                          "mixed-set.prm",
                                          output,
                                          comm);
  }

  /** max_i |a_i - b_i| / max_i |b_i|. */
  double
  largest_difference(const std::vector<Eigen::Vector3d> &a,
                     const std::vector<Eigen::Vector3d> &b)
  {
    double difference = 0., size = 0.;
    for (unsigned int i = 0; i < b.size(); ++i)
      {
        difference = std::max(difference, (a[i] - b[i]).norm());
        size       = std::max(size, b[i].norm());
      }
    return difference / size;
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

  const auto parallel = run(MPI_COMM_WORLD, "mixed_set_parallel");
  if (rank == 0)
    {
      const auto serial = run(MPI_COMM_SELF, "mixed_set_serial");
      checker.check(parallel.n_steps == 6 && serial.n_steps == 6,
                    "six steps each");
      checker.check(serial.position.size() == 26
                      && parallel.position.size() == 26,
                    "26 bodies");
      // the displacements: positions less the start (same in both runs)
      std::vector<Eigen::Vector3d> moved_parallel, moved_serial;
      unsigned int                 touching = 0, grains_touching = 0;
      for (unsigned int i = 0; i < serial.position.size(); ++i)
        {
          const std::string series
            = "mixed_set_serial/particle_" + std::to_string(i) + ".dat";
          const double start = testing::read_column(series, "z").front();
          const Eigen::Vector3d origin(testing::read_column(series, "x")[0],
                                       testing::read_column(series, "y")[0],
                                       start);
          moved_parallel.push_back(parallel.position[i] - origin);
          moved_serial.push_back(serial.position[i] - origin);
          double contact = 0.;
          for (const double f : testing::read_column(series, "Fc_z"))
            contact = std::max(contact, std::abs(f));
          touching += contact > 0.;
          grains_touching += contact > 0. && i >= 9 && i < 13;
        }
      std::cout << touching << " of 26 bodies in contact during the run\n";
      checker.check(touching >= 9, "the bricks, at least, meet the floor");
      checker.check(grains_touching >= 1, "a grain meets a brick");
      const std::string ranks = " on " + std::to_string(n_ranks) + " ranks";
      const double      displacement
        = largest_difference(moved_parallel, moved_serial);
      const double velocity
        = largest_difference(parallel.velocity, serial.velocity);
      const double force = largest_difference(parallel.force, serial.force);
      std::cout << "largest differences, relative: displacement "
                << displacement << ", velocity " << velocity << ", force "
                << force << ranks << "\n";
      checker.check(displacement <= 1e-8, "displacements to 1e-8" + ranks);
      checker.check(velocity <= 1e-8, "velocities to 1e-8" + ranks);
      checker.check(force <= 1e-8, "fluid forces to 1e-8" + ranks);
    }
  int code = checker.exit_code();
  MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return code;
}
