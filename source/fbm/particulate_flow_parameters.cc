#include <particulate/core/input_file.h>
#include <particulate/fbm/case_file.h>
#include <particulate/fbm/particulate_flow_simulation.h>
#include <particulate/fluid/tabulated_viscosity.h>

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace fbm {
    namespace {
      /** Whether the file sets an entry of subsection @p section. */
      bool
      sets_any_entry(const core::InputOutline &outline,
                     const std::string        &section)
      {
        for (const auto &statement : outline.statements())
          if (statement.keyword == core::InputOutline::Keyword::set
              && !statement.path.empty() && statement.path.front() == section)
            return true;
        return false;
      }
    } // namespace



    void
    ParticulateFlowParameters::declare(dealii::ParameterHandler &prm,
                                       const ParticleSetLayout  &layout)
    {
      fluid::FlowCaseParameters::declare(prm);
      ParticleParameters::declare(prm, layout);
      deformation::DeformationParameters::declare(prm);
      core::CheckpointParameters::declare(prm);
    }



    void
    ParticulateFlowParameters::parse(dealii::ParameterHandler &prm,
                                     const core::InputOutline &outline)
    {
      const std::string &filename = outline.filename();
      flow.parse(prm);
      // meshes named in the file are found next to it
      flow.mesh.base_directory
        = std::filesystem::path(filename).parent_path().string();
      if (flow.mesh.base_directory.empty())
        flow.mesh.base_directory = ".";
      // so is a viscosity table, read now so that a bad one stops the run
      // before anything is built
      std::string &table = flow.fluid.properties.viscosity_table;
      if (!table.empty() && std::filesystem::path(table).is_relative())
        table
          = (std::filesystem::path(flow.mesh.base_directory) / table).string();
      if (flow.fluid.properties.viscosity_model
          == fluid::ViscosityModelType::table)
        fluid::read_viscosity_table(table);
      particles.parse(prm, flow.simulation.dimension, outline);
      checkpoint.parse(prm);
      deformation.parse(prm);
      if (flow.simulation.type == core::SimulationParameters::Type::fluid
          && (deformation.method
                != deformation::DeformationParameters::Method::none
              || deformation.following
                   != deformation::DeformationParameters::Following::readapt))
        throw std::runtime_error(
          filename
          + ": subsection 'Mesh deformation' sets a 'Method' or 'Moving "
            "bodies', but 'Type' in subsection 'Simulation' is 'fluid': the "
            "mesh adapts to particles, and this case has none. Set 'Method = "
            "none' and 'Moving bodies = re-adapt', or 'Type = particulate "
            "flow'.");
      if (deformation.following
            == deformation::DeformationParameters::Following::carry_surface
          && deformation.method
               != deformation::DeformationParameters::Method::laplace_alpha)
        throw std::runtime_error(
          filename
          + ": subsection 'Mesh deformation': 'Moving bodies = carry surface "
            "vertices' needs 'Method = laplace-alpha', the only method that "
            "puts vertices onto the surfaces. Set 'Method = laplace-alpha' "
            "or 'Moving bodies = re-adapt'.");
      // Carrying the surface vertices moves the vertices of every level
      // of the hierarchy onto the surfaces, and the multigrid's coarse
      // levels may then no longer carry it (fbm_restart_matches_uninterrupted,
      // a disk near the floor: FGMRES stalled with it, not with AMG).
      auto &ruled_out = flow.fluid.linear_solver.multigrid_ruled_out_by;
      if (ruled_out.empty()
          && deformation.following
               == deformation::DeformationParameters::Following::carry_surface)
        ruled_out = "'Moving bodies = carry surface vertices'";
      // never ignore input silently
      using Type = core::SimulationParameters::Type;
      if (flow.simulation.type != Type::particulate_flow
          && checkpoint.enabled())
        throw std::runtime_error(
          filename
          + ": subsection 'Checkpoint' asks for checkpoints, which only "
            "'particulate flow' runs write so far. Set both intervals to 0.");
      if (flow.simulation.type == Type::rigid_bodies
          && particles.n_particles() == 0)
        throw std::runtime_error(
          filename
          + ": a 'rigid bodies' run needs at least one particle: add a "
            "subsection 'Particle 0' (or a 'Particle file', 'Lattice' or "
            "'Random fill') to subsection 'Particles'.");
      if (flow.simulation.type == Type::rigid_bodies
          && particles.any(ParticleMotion::hinged))
        throw std::runtime_error(
          filename
          + ": 'Motion = hinged' moves a body by the loads a fluid puts on "
            "its parts, and a 'rigid bodies' run has no fluid: set 'Type' in "
            "subsection 'Simulation' to 'particulate flow'.");
      if (flow.simulation.type != Type::fluid
          && sets_any_entry(outline, "Forces"))
        throw std::runtime_error(
          outline.where({"Forces"})
          + ": the drag and lift of a body-fitted obstacle, which 'fluid' "
            "runs only compute. A particulate flow run writes each "
            "particle's hydrodynamic force and torque to particle_<n>.dat; "
            "remove the subsection.");
      if (flow.simulation.type == core::SimulationParameters::Type::fluid
          && particles.n_particles() > 0)
        throw std::runtime_error(
          outline.where({"Particles"})
          + ": the case describes particles, but 'Type' in subsection "
            "'Simulation' is 'fluid', which has none. Set 'Type = "
            "particulate flow'.");
    }



    ParticulateFlowParameters
    read_particulate_flow_case(const std::string &filename,
                               const std::string &overrides)
    {
      dealii::ParameterHandler prm;
      return read_case_file(prm, filename, overrides);
    }
  } // namespace fbm
} // namespace particulate
