// The defaults live in one place: every parameter struct of a case file,
// default-constructed, equals what an empty case file gives when read. A case
// built in code (a test, a benchmark) therefore runs the method that a .prm
// run gets by default, and the declared default of an entry cannot drift
// from its struct. The check reads every scalar and choice field; it fails
// if a declaration writes a default of its own again.

#include <particulate/core/checkpoint.h>
#include <particulate/core/input_outline.h>
#include <particulate/core/mesh.h>
#include <particulate/core/simulation_parameters.h>
#include <particulate/deformation/deformation_parameters.h>
#include <particulate/fbm/particle_parameters.h>
#include <particulate/fluid/fluid_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <fstream>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  /** Declare with @p declare, read an empty file and parse with @p parse. */
  template <typename Parameters, typename Declare, typename Parse>
  Parameters
  read_from_empty_file(const Declare &declare, const Parse &parse)
  {
    dealii::ParameterHandler prm;
    declare(prm);
    prm.parse_input_from_string("");
    Parameters parameters;
    parse(prm, parameters);
    return parameters;
  }

  template <typename T>
  void
  check_equal(testing::Checker  &checker,
              const T           &read,
              const T           &constructed,
              const std::string &what)
  {
    checker.check(read == constructed,
                  what + ": an empty case file gives the struct's default");
  }

  void
  check_particles(testing::Checker &checker)
  {
    const std::string file = "parameter_defaults_empty.prm";
    std::ofstream(file) << "";
    const core::InputOutline outline(file);
    const auto read = read_from_empty_file<fbm::ParticleParameters>(
      [&](dealii::ParameterHandler &prm) {
        fbm::ParticleParameters::declare(prm,
                                         fbm::ParticleSetLayout::of(outline));
      },
      [&](dealii::ParameterHandler &prm, fbm::ParticleParameters &p) {
        p.parse(prm, 3, outline);
      });
    const fbm::ParticleParameters d{};
    check_equal(checker, read.gravity, d.gravity, "Particles: Gravity");
    check_equal(checker,
                read.locked_translation,
                d.locked_translation,
                "Particles: Locked translations");
    check_equal(checker,
                read.locked_rotation,
                d.locked_rotation,
                "Particles: Locked rotations");
    check_equal(checker,
                read.added_mass_coefficient,
                d.added_mass_coefficient,
                "Particles: Added mass coefficient");
    check_equal(checker,
                read.extrapolate_constraint_velocity,
                d.extrapolate_constraint_velocity,
                "Particles: Constraint velocity");
    check_equal(checker,
                read.midpoint_interface_position,
                d.midpoint_interface_position,
                "Particles: Interface position");
    check_equal(checker,
                read.force_includes_fluid_inertia,
                d.force_includes_fluid_inertia,
                "Particles: Force integral");
    check_equal(checker,
                read.contact_solver,
                d.contact_solver,
                "Particles: Contact solver");
    check_equal(checker,
                read.restitution,
                d.restitution,
                "Particles: Restitution");
    check_equal(checker, read.friction, d.friction, "Particles: Friction");
    check_equal(checker,
                read.contact_distance,
                d.contact_distance,
                "Particles: Contact distance");
    check_equal(checker, read.walls, d.walls, "Particles: Domain walls");
    check_equal(checker,
                read.substeps,
                d.substeps,
                "Particles: Rigid substeps");
    check_equal(checker,
                read.containment_backend,
                d.containment_backend,
                "Particles: Containment backend");
    check_equal(checker,
                read.covered_nodes,
                d.covered_nodes,
                "Particles: Covered nodes");
    check_equal(checker,
                read.symmetry_planes,
                d.symmetry_planes,
                "Particles: Symmetry planes");
    std::filesystem::remove(file);
  }

  void
  check_deformation(testing::Checker &checker)
  {
    using P         = deformation::DeformationParameters;
    const auto read = read_from_empty_file<P>(
      [](dealii::ParameterHandler &prm) { P::declare(prm); },
      [](dealii::ParameterHandler &prm, P &p) { p.parse(prm); });
    const P           d;
    const std::string s = "Mesh deformation: ";
    check_equal(checker, read.method, d.method, s + "Method");
    check_equal(checker, read.width, d.width, s + "Width");
    check_equal(checker, read.peak_weight, d.peak_weight, s + "Peak weight");
    check_equal(checker, read.relaxation, d.relaxation, s + "Relaxation");
    check_equal(checker,
                read.sweeps_per_level,
                d.sweeps_per_level,
                s + "Sweeps per level");
    check_equal(checker,
                read.smallest_cell_ratio,
                d.smallest_cell_ratio,
                s + "Smallest cell ratio");
    check_equal(checker, read.ode_steps, d.ode_steps, s + "ODE steps");
    check_equal(checker,
                read.step_ratio,
                d.step_ratio,
                s + "Robust step ratio");
    check_equal(checker,
                read.projection_range,
                d.projection_range,
                s + "Projection range");
    check_equal(checker,
                read.min_quality,
                d.min_quality,
                s + "Minimum cell quality");
    check_equal(checker, read.following, d.following, s + "Moving bodies");
    check_equal(checker,
                read.readaptation_quality,
                d.readaptation_quality,
                s + "Re-adaptation quality");
    check_equal(checker,
                read.readaptation_aspect_ratio,
                d.readaptation_aspect_ratio,
                s + "Re-adaptation aspect ratio");
    check_equal(checker,
                read.carried_zone_width,
                d.carried_zone_width,
                s + "Carried zone width");
    check_equal(checker,
                read.carried_zone_fade,
                d.carried_zone_fade,
                s + "Carried zone fade");
  }

  void
  check_fluid(testing::Checker &checker)
  {
    using F          = fluid::FluidProperties;
    const auto fluid = read_from_empty_file<F>(
      [](dealii::ParameterHandler &prm) { F::declare(prm); },
      [](dealii::ParameterHandler &prm, F &p) { p.parse(prm); });
    const F f;
    check_equal(checker, fluid.density, f.density, "Fluid: Density");
    check_equal(checker,
                fluid.dynamic_viscosity,
                f.dynamic_viscosity,
                "Fluid: Dynamic viscosity");
    check_equal(checker,
                fluid.viscosity_model,
                f.viscosity_model,
                "Fluid: Viscosity model");
    check_equal(checker,
                fluid.infinite_shear_viscosity,
                f.infinite_shear_viscosity,
                "Fluid: Infinite-shear viscosity");
    check_equal(checker,
                fluid.relaxation_time,
                f.relaxation_time,
                "Fluid: Relaxation time");
    check_equal(checker,
                fluid.power_law_index,
                f.power_law_index,
                "Fluid: Power-law index");
    check_equal(checker,
                fluid.consistency,
                f.consistency,
                "Fluid: Consistency");
    check_equal(checker,
                fluid.minimum_shear_rate,
                f.minimum_shear_rate,
                "Fluid: Minimum shear rate");
    check_equal(checker,
                fluid.viscosity_table,
                f.viscosity_table,
                "Fluid: Viscosity table");

    using N       = fluid::NonlinearSolverParameters;
    const auto nl = read_from_empty_file<N>(
      [](dealii::ParameterHandler &prm) { N::declare(prm); },
      [](dealii::ParameterHandler &prm, N &p) { p.parse(prm); });
    const N           n;
    const std::string sn = "Nonlinear solver: ";
    check_equal(checker, nl.method, n.method, sn + "Method");
    check_equal(checker,
                nl.absolute_tolerance,
                n.absolute_tolerance,
                sn + "Absolute tolerance");
    check_equal(checker,
                nl.relative_tolerance,
                n.relative_tolerance,
                sn + "Relative tolerance");
    check_equal(checker,
                nl.maximum_iterations,
                n.maximum_iterations,
                sn + "Maximum iterations");
    check_equal(checker,
                nl.initial_guess,
                n.initial_guess,
                sn + "Initial guess");

    using L       = fluid::LinearSolverParameters;
    const auto li = read_from_empty_file<L>(
      [](dealii::ParameterHandler &prm) { L::declare(prm); },
      [](dealii::ParameterHandler &prm, L &p) { p.parse(prm); });
    const L           l;
    const std::string sl = "Linear solver: ";
    check_equal(checker,
                li.relative_tolerance,
                l.relative_tolerance,
                sl + "Relative tolerance");
    check_equal(checker,
                li.maximum_iterations,
                l.maximum_iterations,
                sl + "Maximum iterations");
    check_equal(checker,
                li.krylov_size,
                l.krylov_size,
                sl + "Krylov subspace size");
    check_equal(checker,
                li.schur_approximation,
                l.schur_approximation,
                sl + "Schur complement approximation");
    check_equal(checker,
                li.pressure_poisson_tolerance,
                l.pressure_poisson_tolerance,
                sl + "Pressure Poisson tolerance");
    check_equal(checker,
                li.pressure_laplacian_smoother,
                l.pressure_laplacian_smoother,
                sl + "Pressure Laplacian smoother");
    check_equal(checker,
                li.velocity_preconditioner,
                l.velocity_preconditioner,
                sl + "Velocity preconditioner");
    check_equal(checker,
                li.chebyshev_degree,
                l.chebyshev_degree,
                sl + "Chebyshev degree");
    check_equal(checker,
                li.velocity_operator,
                l.velocity_operator,
                sl + "Velocity operator");
    check_equal(checker,
                li.multigrid_coarse_solver,
                l.multigrid_coarse_solver,
                sl + "Multigrid coarse solver");
    check_equal(checker,
                li.multigrid_on_moving_mesh,
                l.multigrid_on_moving_mesh,
                sl + "Multigrid on a moving mesh");
    check_equal(checker, li.amg_elliptic, l.amg_elliptic, sl + "AMG elliptic");
    check_equal(checker, li.amg_smoother, l.amg_smoother, sl + "AMG smoother");
    check_equal(checker,
                li.amg_smoother_sweeps,
                l.amg_smoother_sweeps,
                sl + "AMG smoother sweeps");
    check_equal(checker, li.verbose, l.verbose, sl + "Verbose");
  }

  /** A struct of core/ read from an empty file. */
  template <typename P>
  P
  read_core()
  {
    return read_from_empty_file<P>(
      [](dealii::ParameterHandler &prm) { P::declare(prm); },
      [](dealii::ParameterHandler &prm, P &p) { p.parse(prm); });
  }

  void
  check_core(testing::Checker &checker)
  {
    const auto sim = read_core<core::SimulationParameters>();
    const core::SimulationParameters s;
    check_equal(checker, sim.type, s.type, "Simulation: Type");
    check_equal(checker, sim.dimension, s.dimension, "Simulation: Dimension");

    const auto                 time = read_core<core::TimeParameters>();
    const core::TimeParameters t;
    check_equal(checker, time.scheme, t.scheme, "Time: Scheme");
    check_equal(checker, time.time_step, t.time_step, "Time: Time step");
    check_equal(checker, time.end_time, t.end_time, "Time: End time");
    check_equal(checker, time.adaptive, t.adaptive, "Time: Adaptive time step");
    check_equal(checker, time.cfl_target, t.cfl_target, "Time: CFL number");
    check_equal(checker,
                time.minimum_time_step,
                t.minimum_time_step,
                "Time: Minimum time step");
    check_equal(checker,
                time.maximum_time_step,
                t.maximum_time_step,
                "Time: Maximum time step");

    const auto                   output = read_core<core::OutputParameters>();
    const core::OutputParameters o;
    check_equal(checker, output.directory, o.directory, "Output: Directory");
    check_equal(checker, output.interval, o.interval, "Output: Interval");
    check_equal(checker,
                output.write_vtu,
                o.write_vtu,
                "Output: Write ParaView files");

    const auto                 mesh = read_core<core::MeshParameters>();
    const core::MeshParameters m;
    check_equal(checker, mesh.type, m.type, "Mesh: Type");
    check_equal(checker, mesh.refinements, m.refinements, "Mesh: Refinements");
    check_equal(checker,
                mesh.fine_cell_size,
                m.fine_cell_size,
                "Mesh: Fine cell size");
    check_equal(checker,
                mesh.grading_ratio,
                m.grading_ratio,
                "Mesh: Grading ratio");
    check_equal(checker,
                mesh.cylinder_shell_width,
                m.cylinder_shell_width,
                "Mesh: Cylinder shell width");
    check_equal(checker,
                mesh.cylinder_shells,
                m.cylinder_shells,
                "Mesh: Cylinder shells");
    check_equal(checker,
                mesh.cylinder_center_x,
                m.cylinder_center_x,
                "Mesh: Cylinder center x");
    check_equal(checker,
                mesh.channel_length,
                m.channel_length,
                "Mesh: Channel length");
    check_equal(checker,
                mesh.channel_depth,
                m.channel_depth,
                "Mesh: Channel depth");

    const auto checkpoint = read_core<core::CheckpointParameters>();
    const core::CheckpointParameters c;
    check_equal(checker,
                checkpoint.step_interval,
                c.step_interval,
                "Checkpoint: Step interval");
    check_equal(checker,
                checkpoint.wall_minutes,
                c.wall_minutes,
                "Checkpoint: Wall-time interval");
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  check_core(checker);
  check_particles(checker);
  check_deformation(checker);
  check_fluid(checker);
  return checker.exit_code();
}
