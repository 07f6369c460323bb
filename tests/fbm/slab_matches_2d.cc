// A 3D cylinder spanning a slab reproduces the 2D disk (Shape = cylinder).
//
// The oscillating cylinder of prm/oscillating-cylinder (thesis §6.3), coarse
// (h = 0.05 m, 2 cells per diameter) and over its first steps, once in 2D
// and once in the slab 2.2 x 0.41 x 0.1025 m extruded from the same cells
// (2 cell layers), with the cylinder's axis along z from wall to wall and
// free-slip front and back walls. The flow that does not depend on z and
// has no z velocity is then a solution of the 3D discrete problem (Q2 and
// P1disc contain the extruded 2D fields, and Gauss quadrature integrates
// their products in z exactly), so the 3D force and torque per unit span
// at every step, the covered nodes (every 2D node on each of the 2 * 2 + 1
// node layers) and the fluid's kinetic energy per unit span must equal the
// 2D run's to the solver tolerances, and the force along the axis must
// vanish. The torque part failed with the torque integrand at quadrature
// points (fbm/hydrodynamic_forces.h says why the covered nodes' arms fix
// it).

#include <particulate/fbm/particulate_flow_simulation.h>

#include <cstdio>
#include <string>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  const double span        = 0.1025;
  const int    layers      = 2; // cell layers across the span
  const int    node_layers = 2 * layers + 1;
  const char  *case_file = "prm/oscillating-cylinder/oscillating-cylinder.prm";
  const std::string coarse = "subsection Mesh\n set Subdivisions = 22, 4\n"
                             " set Refinements = 1\nend\n"
                             "subsection Time\n set End time = 0.05\nend\n"
                             "subsection Nonlinear solver\n"
                             " set Absolute tolerance = 1e-14\n"
                             " set Relative tolerance = 1e-10\nend\n"
                             "subsection Linear solver\n"
                             " set Relative tolerance = 1e-9\n"
                             " set Velocity preconditioner = geometric "
                             "multigrid\n"
                             " set Velocity operator = matrix-free\nend\n";

  struct Outcome
  {
    fbm::ParticulateFlowSummary summary;
    double                      fluid_energy  = 0.;
    double                      covered_nodes = 0.;
    /// particle_0.dat: per step t, ..., F_x F_y F_z (columns 10-12), T_x
    /// T_y T_z (13-15), ...
    std::vector<std::vector<double>> particle_series;
  };

  std::string
  scientific(const double x)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%.2e", x);
    return text;
  }

  template <int dim>
  Outcome
  run(const std::string &overrides, const std::string &output)
  {
    auto parameters
      = fbm::read_particulate_flow_case(testing::source_path(case_file),
                                        coarse + overrides);
    parameters.flow.output.directory = output;
    parameters.flow.output.write_vtu = false;
    std::filesystem::create_directories(output);
    fbm::ParticulateFlowSimulation<dim> simulation(parameters,
                                                   "oscillating-cylinder.prm",
                                                   MPI_COMM_WORLD);
    Outcome                             outcome;
    outcome.summary = simulation.run();
    // flow.dat: t, fluid kinetic energy, ...; particle_0.dat ends with the
    // number of covered velocity nodes
    outcome.fluid_energy
      = testing::read_time_series(output + "/flow.dat").back().at(1);
    outcome.particle_series
      = testing::read_time_series(output + "/particle_0.dat");
    outcome.covered_nodes
      = testing::read_column(output + "/particle_0.dat", "nodes_inside").back();
    return outcome;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;

  const Outcome planar = run<2>("", "slab_2d");
  const Outcome slab
    = run<3>("subsection Simulation\n set Dimension = 3\nend\n"
             "subsection Mesh\n set Lower corner = 0, 0, 0\n"
             " set Upper corner = 2.2, 0.41, 0.1025\n"
             " set Subdivisions = 22, 4, 1\nend\n"
             "subsection Boundary conditions\n set No-slip = 0, 1, 2, 3\n"
             " set Free-slip = 4, 5\nend\n"
             "subsection Particles\n"
             " subsection Shape disk\n  set Type = cylinder\n"
             "  set Length = 0.1025\n end\n"
             " subsection Particle 0\n  set Position = 1.1, 0.2, 0.05125\n"
             "  set Prescribed displacement = A * sin(2 * pi * f * t); 0; 0\n"
             " end\n"
             " set Domain walls = x-, x+, y-, y+\nend\n",
             "slab_3d");

  checker.check(planar.covered_nodes > 0., "the 2D disk covers velocity nodes");
  checker.check(slab.covered_nodes == node_layers * planar.covered_nodes,
                "the slab's cylinder covers the disk's nodes on each of the "
                  + std::to_string(node_layers) + " node layers ("
                  + std::to_string(slab.covered_nodes) + " against "
                  + std::to_string(planar.covered_nodes) + ")");
  const Eigen::Vector3d f2 = planar.summary.force[0];
  const Eigen::Vector3d f3 = slab.summary.force[0] / span;
  checker.check_relative(f3[0], f2[0], 1e-6, "drag per unit span, slab vs 2D");
  // the lift is small (the cylinder sits 5 mm below the mid-line): compare
  // it on the drag's scale
  checker.check(std::abs(f3[1] - f2[1]) < 1e-6 * std::abs(f2[0]),
                "lift per unit span, slab vs 2D (" + scientific(f3[1])
                  + " against " + scientific(f2[1]) + ")");
  checker.check(std::abs(f3[2]) < 1e-8 * std::abs(f2[0]),
                "no force along the cylinder's axis");
  // every step, force and torque about the axis (small: the cylinder
  // translates) on the scales of the drag and drag times radius
  const double arm  = 0.05;
  double       drag = 0., force_error = 0., torque_error = 0.;
  checker.check(slab.particle_series.size() == planar.particle_series.size(),
                "as many steps in 3D as in 2D");
  for (unsigned int i = 0; i < planar.particle_series.size(); ++i)
    {
      const auto &row2 = planar.particle_series[i];
      const auto &row3 = slab.particle_series[i];
      drag             = std::max(drag, std::abs(row2[10]));
      for (unsigned int d = 10; d < 12; ++d)
        force_error = std::max(force_error, std::abs(row3[d] / span - row2[d]));
      torque_error
        = std::max(torque_error, std::abs(row3[15] / span - row2[15]));
    }
  checker.check(force_error < 1e-6 * drag,
                "force per unit span at every step, slab vs 2D (largest "
                "difference "
                  + scientific(force_error / drag) + " of the drag)");
  checker.check(torque_error < 1e-6 * arm * drag,
                "torque per unit span at every step, slab vs 2D (largest "
                "difference "
                  + scientific(torque_error / (arm * drag))
                  + " of drag x radius)");
  checker.check_relative(slab.fluid_energy / span,
                         planar.fluid_energy,
                         1e-6,
                         "fluid kinetic energy per unit span, slab vs 2D");
  return checker.exit_code();
}
