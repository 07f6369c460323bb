// The stages of a coupled step (ParticulateFlowSimulation: move_mesh,
// impose_interface, advance_fluid, compute_loads, advance_bodies,
// write_output) driven one by one on prm/settling-disk (coarse mesh, the
// disk released at rest), each checked for what it must do:
// - set_up: the disk where the case puts it, at rest, with covered nodes;
// - move_mesh: a free disk on a fixed mesh does not move before the step; a
//   prescribed one (prm/oscillating-cylinder/laplace-alpha, coarse) moves to
//   its position at t_n+1 with the derivative of its displacement as its
//   velocity, and the carried mesh takes it along: it covers the same
//   number of nodes as before;
// - impose_interface: the first step imposes the disk's rest, the second
//   the velocity extrapolated to the end of the step, U_1 + k a_1 (the
//   case's 'Constraint velocity = extrapolated'), about the midpoint
//   X_1 + k/2 (U_1 + k/2 a_1) ('Interface position = midpoint');
// - advance_fluid and compute_loads: a fluid and a disk at rest stay at rest
//   (no kinetic energy, no load); once the disk moves down, the fluid moves
//   and its force on the disk points up, against the motion;
// - advance_bodies: from rest and with no load the disk's velocity after one
//   step is the closed form of the added-mass correction,
//   (rho_p - rho_f) / (rho_p + rho_f) g k (1e-14), and time and step number
//   advance;
// - the stages in this order are run(): a run of two steps ends in the same
//   state, bit for bit.
#include <particulate/fbm/particulate_flow_simulation.h>
#include <particulate/rigid/world.h>

#include <filesystem>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  fbm::ParticulateFlowParameters
  case_parameters(const std::string &output)
  {
    auto parameters = fbm::read_particulate_flow_case(
      testing::source_path("prm/settling-disk/settling-disk.prm"),
      "subsection Mesh\n set Refinements = 4\nend\n"
      "subsection Time\n set End time = 0.002\nend\n");
    parameters.flow.output.directory = output;
    parameters.flow.output.write_vtu = false;
    std::filesystem::create_directories(output);
    return parameters;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const auto   parameters = case_parameters("coupled_step_stages");
  const auto  &p          = parameters.particles;
  const double k          = parameters.flow.time.time_step;
  const double rho_f      = parameters.flow.fluid.properties.density;

  fbm::ParticulateFlowSimulation<2> staged(parameters,
                                           "settling-disk.prm",
                                           MPI_COMM_WORLD);
  staged.set_up();
  const auto body = [&]() -> const rigid::RigidBody & {
    return staged.world().body(staged.body_ids()[0]);
  };
  const auto &state = [&]() -> const fbm::BodyCouplingState & {
    return staged.coupling_states()[0];
  };
  checker.check(body().position == p.bodies[0].position
                  && body().linear_velocity.isZero(),
                "set_up: the disk at its position, at rest");
  checker.check(staged.n_covered_nodes()[0] > 0,
                "set_up: the disk covers velocity nodes");

  // step 1: everything at rest
  staged.move_mesh(k);
  checker.check(body().position == p.bodies[0].position,
                "move_mesh: a free disk on a fixed mesh stays before the step");
  staged.impose_interface(k);
  checker.check(state().imposed_velocity.isZero()
                  && state().load_centre == p.bodies[0].position,
                "impose_interface: the disk's rest, about its centre");
  staged.advance_fluid(k);
  checker.check(staged.fluid_kinetic_energy() < 1e-30,
                "advance_fluid: a fluid at rest around a disk at rest stays");
  staged.compute_loads(k);
  checker.check(state().fluid_load.force.norm() < 1e-12,
                "compute_loads: no load from a fluid at rest");
  staged.advance_bodies(k);
  const double rho_p     = p.bodies[0].density;
  const double C         = p.added_mass_coefficient;
  const double free_fall = (rho_p - rho_f) / (rho_p + C * rho_f) * 9.81 * k;
  checker.check_relative(-body().linear_velocity[1],
                         free_fall,
                         1e-14,
                         "advance_bodies: the added-mass step from rest");
  checker.check(staged.time() == k && staged.step_number() == 1,
                "advance_bodies: time and step advance");
  staged.write_output(k);

  // step 2: the disk moves down
  const Eigen::Vector3d U = body().linear_velocity, X = body().position,
                        a = state().acceleration;
  staged.move_mesh(k);
  staged.impose_interface(k);
  checker.check((state().imposed_velocity - (U + k * a)).norm()
                  <= 1e-15 * U.norm(),
                "impose_interface: the extrapolated velocity U + k a");
  checker.check((state().load_centre - (X + 0.5 * k * (U + 0.5 * k * a))).norm()
                  <= 1e-15 * X.norm(),
                "impose_interface: about the midpoint of the step");
  checker.check(body().position == X && body().linear_velocity == U,
                "impose_interface: the disk itself keeps its state");
  staged.advance_fluid(k);
  checker.check(staged.fluid_kinetic_energy() > 0.,
                "advance_fluid: the moving disk sets the fluid in motion");
  staged.compute_loads(k);
  checker.check(state().fluid_load.force[1] > 0.,
                "compute_loads: the fluid's force opposes the fall");
  staged.advance_bodies(k);
  staged.write_output(k);

  // move_mesh with a prescribed disk on a mesh carried with it
  {
    auto oscillating = fbm::read_particulate_flow_case(
      testing::source_path("prm/oscillating-cylinder/laplace-alpha.prm"),
      "subsection Mesh\n set Refinements = 3\nend\n"
      "subsection Checkpoint\n set Wall-time interval = 0\nend\n");
    oscillating.flow.output.directory = "coupled_step_stages_prescribed";
    oscillating.flow.output.write_vtu = false;
    std::filesystem::create_directories(oscillating.flow.output.directory);
    fbm::ParticulateFlowSimulation<2> moved(oscillating,
                                            "laplace-alpha.prm",
                                            MPI_COMM_WORLD);
    moved.set_up();
    const unsigned long covered = moved.n_covered_nodes()[0];
    const double        dt      = oscillating.flow.time.time_step;
    moved.move_mesh(dt);
    moved.impose_interface(dt);
    const rigid::RigidBody &disk = moved.world().body(moved.body_ids()[0]);
    const double            A = 0.25, omega = 2. * M_PI * 0.25;
    checker.check_relative(disk.position[0],
                           1.1 + A * std::sin(omega * dt),
                           1e-15,
                           "move_mesh: a prescribed disk at its position at "
                           "t_n+1");
    checker.check_relative(disk.linear_velocity[0],
                           A * omega * std::cos(omega * dt),
                           1e-9, // central difference over 1.2e-5 s
                           "move_mesh: with the displacement's derivative as "
                           "its velocity");
    checker.check(moved.n_covered_nodes()[0] == covered,
                  "move_mesh: the carried mesh keeps the disk's "
                    + std::to_string(covered) + " covered nodes");
  }

  // the same two steps through run()
  const auto whole_parameters = case_parameters("coupled_step_stages_run");
  fbm::ParticulateFlowSimulation<2> whole(whole_parameters,
                                          "settling-disk.prm",
                                          MPI_COMM_WORLD);
  const auto                        summary = whole.run();
  checker.check(summary.n_steps == 2 && summary.position[0] == body().position
                  && summary.velocity[0] == body().linear_velocity
                  && summary.force[0] == state().fluid_load.force,
                "the stages in order are run(), bit for bit");
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "after two steps: y = " << body().position[1]
              << " m, v = " << body().linear_velocity[1]
              << " m/s, F_y = " << state().fluid_load.force[1] << " N\n";
  return checker.exit_code();
}
