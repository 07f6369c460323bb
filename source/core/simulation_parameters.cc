#include <particulate/core/input_file.h>
#include <particulate/core/parameter_text.h>
#include <particulate/core/simulation_parameters.h>

#include <algorithm>

namespace particulate {
  namespace core {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;

    void
    SimulationParameters::declare(ParameterHandler &prm)
    {
      const SimulationParameters defaults;
      prm.enter_subsection("Simulation");
      prm.declare_entry("Type",
                        "fluid",
                        Patterns::Selection(
                          "fluid|particulate flow|rigid bodies"),
                        "What to simulate. 'fluid': incompressible "
                        "Navier-Stokes flow around body-fitted obstacles. "
                        "'particulate flow': rigid particles (subsection "
                        "'Particles') in the fluid by the fictitious boundary "
                        "method. 'rigid bodies': the same particles under "
                        "gravity and contacts alone, without a fluid (no "
                        "buoyancy), in the box of the mesh with its walls and "
                        "with the fixed 'Time step'; the run writes the "
                        "particles' output of a particulate flow run.");
      prm.declare_entry("Dimension",
                        std::to_string(defaults.dimension),
                        Patterns::Integer(2, 3),
                        "Space dimension of the run (2 or 3).");
      prm.leave_subsection();
    }

    void
    SimulationParameters::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Simulation");
      const std::string name = prm.get("Type");
      type      = name == "particulate flow" ? Type::particulate_flow :
                  name == "rigid bodies"     ? Type::rigid_bodies :
                                               Type::fluid;
      dimension = prm.get_integer("Dimension");
      prm.leave_subsection();
    }



    double
    TimeParameters::next_time_step(const double dt, const double cfl) const
    {
      const double proposal = cfl > 0. ? dt * cfl_target / cfl : 1.2 * dt;
      return std::clamp(std::clamp(proposal, 0.8 * dt, 1.2 * dt),
                        minimum_time_step,
                        maximum_time_step);
    }



    void
    TimeParameters::declare(ParameterHandler &prm)
    {
      const TimeParameters defaults;
      prm.enter_subsection("Time");
      prm.declare_entry(
        "Scheme",
        "fractional-step theta",
        Patterns::Selection(
          "fractional-step theta|Crank-Nicolson|backward Euler|steady"),
        "Time discretisation (thesis §5.3.2). 'fractional-step theta' is "
        "strongly A-stable and second order; 'Crank-Nicolson' is second order "
        "without damping; 'backward Euler' is first order and strongly "
        "damping; 'steady' solves the stationary equations once.");
      prm.declare_entry("Time step",
                        number_text(defaults.time_step),
                        Patterns::Double(0.),
                        "Macro time step [s]. With fractional-step theta "
                        "one step is three substeps.");
      prm.declare_entry("End time",
                        number_text(defaults.end_time),
                        Patterns::Double(0.),
                        "Physical time at which the run stops [s].");
      prm.declare_entry("Adaptive time step",
                        flag_text(defaults.adaptive),
                        Patterns::Bool(),
                        "Choose the step from the CFL number after each step "
                        "(bounded by the minimum and maximum time step).");
      prm.declare_entry("CFL number",
                        number_text(defaults.cfl_target),
                        Patterns::Double(0.),
                        "Target CFL number max(|u| dt / h) for the adaptive "
                        "time step [-].");
      prm.declare_entry("Minimum time step",
                        number_text(defaults.minimum_time_step),
                        Patterns::Double(0.),
                        "Lower bound of the adaptive time step [s].");
      prm.declare_entry("Maximum time step",
                        number_text(defaults.maximum_time_step),
                        Patterns::Double(0.),
                        "Upper bound of the adaptive time step [s].");
      prm.leave_subsection();
    }

    void
    TimeParameters::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      const std::string s = prm.get("Scheme");
      scheme              = s == "steady"         ? Scheme::steady :
                            s == "backward Euler" ? Scheme::backward_euler :
                            s == "Crank-Nicolson" ? Scheme::crank_nicolson :
                                                    Scheme::fractional_step_theta;
      time_step           = core::get_positive_double(prm, "Time step", "Time");
      end_time            = prm.get_double("End time");
      adaptive            = prm.get_bool("Adaptive time step");
      cfl_target = core::get_positive_double(prm, "CFL number", "Time");
      minimum_time_step
        = core::get_positive_double(prm, "Minimum time step", "Time");
      maximum_time_step
        = core::get_positive_double(prm, "Maximum time step", "Time");
      prm.leave_subsection();
    }



    void
    OutputParameters::declare(ParameterHandler &prm)
    {
      const OutputParameters defaults;
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        defaults.directory,
                        Patterns::DirectoryName(),
                        "Folder for all results (created if missing). A "
                        "relative path is taken from the current directory.");
      prm.declare_entry("Interval",
                        std::to_string(defaults.interval),
                        Patterns::Integer(0),
                        "Write ParaView files at the start, every this many "
                        "time steps and at the last step (0: at the start "
                        "and the last step only). Time series (.dat) are "
                        "written every step.");
      prm.declare_entry("Write ParaView files",
                        flag_text(defaults.write_vtu),
                        Patterns::Bool(),
                        "Write .vtu/.pvtu/.pvd files of the flow field.");
      prm.declare_entry(
        "Particle files",
        "automatic",
        Patterns::Selection("automatic|each particle|shared"),
        "How a run with particles writes them. 'each particle': the time "
        "series particle_<i>.dat and the surface series "
        "particle_surfaces/body_<i>.pvd of every particle (one open file and "
        "one file per output step each). 'shared': one time series "
        "particles.dat with a row per particle and step (column id) and one "
        "file of all surfaces per output step, particle_surfaces_NNNNN.vtp "
        "(cell data id): the number of files does not grow with the "
        "particles. 'automatic': each particle up to 100 particles, shared "
        "above.");
      prm.leave_subsection();
    }

    void
    OutputParameters::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory               = prm.get("Directory");
      interval                = prm.get_integer("Interval");
      write_vtu               = prm.get_bool("Write ParaView files");
      const std::string files = prm.get("Particle files");
      particle_files          = files == "shared" ? ParticleFiles::shared :
                                files == "each particle" ? ParticleFiles::each_particle :
                                                           ParticleFiles::automatic;
      prm.leave_subsection();
    }
  } // namespace core
} // namespace particulate
