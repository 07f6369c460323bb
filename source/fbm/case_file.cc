#include <particulate/core/deal_ii_message.h>
#include <particulate/core/input_file.h>
#include <particulate/core/mesh.h>
#include <particulate/core/mesh_size.h>
#include <particulate/fbm/case_file.h>
#include <particulate/fbm/domain_box.h>
#include <particulate/fbm/particle_set_checks.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace fbm {
    namespace {
      /**
       * Run @p check; a refusal it throws is given the file's name (the
       * checks of values and combinations know the entry, not the file it
       * came from), and a deal.II exception becomes a std::runtime_error
       * with its explanation (deal.II's get_double() refuses a value its
       * pattern let through: a subnormal number such as 1e-310).
       */
      template <typename Check>
      void
      naming_the_file(const std::string &filename, const Check &check)
      {
        try
          {
            check();
          }
        catch (const dealii::ExceptionBase &e)
          {
            throw std::runtime_error(filename + ": "
                                     + core::one_line_explanation(e));
          }
        catch (const std::runtime_error &e)
          {
            const std::string message = e.what();
            if (message.find(filename) != std::string::npos)
              throw;
            throw std::runtime_error(filename + ": " + message);
          }
      }

      /** Expressions with the right number of components. */
      template <int dim>
      void
      check_expressions(const fluid::FlowCaseParameters &flow)
      {
        flow.fluid.properties.body_force.create<dim>(dim, "Fluid / Body force");
        flow.fluid.boundary_conditions.dirichlet_velocity
          .create<dim>(dim, "Boundary conditions / Velocity");
        flow.fluid.initial_velocity.create<dim>(dim,
                                                "Initial condition / Velocity");
      }

      template <int dim>
      void
      check_against_coarse_mesh(const ParticulateFlowParameters &parameters,
                                const std::string               &filename,
                                MPI_Comm                         comm)
      {
        const fluid::FlowCaseParameters &flow = parameters.flow;
        const bool                       with_fluid
          = flow.simulation.type
            != core::SimulationParameters::Type::rigid_bodies;
        if (with_fluid)
          check_expressions<dim>(flow);
        // the size first: the whole refined mesh is built on every rank
        core::check_mesh_size(flow.mesh,
                              dim,
                              core::coarse_cell_count(flow.mesh, dim));
        auto coarse        = flow.mesh;
        coarse.refinements = 0;
        dealii::parallel::fullydistributed::Triangulation<dim> tria(comm);
        core::create_mesh(coarse, tria);
        core::check_mesh_size(flow.mesh, dim, tria.n_global_active_cells());
        if (with_fluid)
          flow.fluid.boundary_conditions.check(core::global_boundary_ids(tria),
                                               filename);
        const auto [lower, upper] = core::global_bounding_box(tria, comm);
        Eigen::Vector3d low       = Eigen::Vector3d::Zero();
        Eigen::Vector3d up        = Eigen::Vector3d::Zero();
        for (unsigned int d = 0; d < dim; ++d)
          {
            low[d] = lower[d];
            up[d]  = upper[d];
          }
        check_inside_domain(
          parameters.particles.bodies,
          make_domain_box(flow.mesh, parameters.particles, low, up, dim));
        check_on_mirror_planes(parameters.particles.bodies,
                               low,
                               up,
                               parameters.particles.symmetry_planes,
                               dim);
      }
    } // namespace



    ParticulateFlowParameters
    read_case_file(dealii::ParameterHandler &prm,
                   const std::string        &filename,
                   const std::string        &overrides)
    {
      const core::InputOutline outline(filename);
      ParticulateFlowParameters::declare(prm, ParticleSetLayout::of(outline));
      core::parse_input_file(prm, outline);
      if (!overrides.empty())
        {
          std::istringstream stream(overrides);
          prm.parse_input(stream, filename + " (overrides)");
        }
      ParticulateFlowParameters parameters;
      naming_the_file(filename, [&]() { parameters.parse(prm, outline); });
      return parameters;
    }



    void
    check_particles_suit_the_run(const ParticulateFlowParameters &parameters,
                                 const std::string               &filename)
    {
      const ParticleParameters &particles = parameters.particles;
      if (parameters.flow.time.scheme == core::TimeParameters::Scheme::steady
          && (particles.any(ParticleMotion::free)
              || particles.any(ParticleMotion::prescribed)
              || particles.any(ParticleMotion::hinged)))
        throw std::runtime_error(
          filename
          + ": moving particles need a time-dependent scheme: set 'Scheme' "
            "in subsection 'Time' to 'fractional-step theta' (or set 'Motion "
            "= fixed' for every particle).");
      if (particles.n_particles() == 0)
        throw std::runtime_error(
          filename
          + ": a 'particulate flow' run needs at least one particle: add a "
            "subsection 'Particle 0' (or a 'Particle file', 'Lattice' or "
            "'Random fill') to subsection 'Particles'.");
    }



    void
    check_case_against_mesh(const ParticulateFlowParameters &parameters,
                            const std::string               &filename,
                            MPI_Comm                         comm)
    {
      if (parameters.flow.simulation.type
          == core::SimulationParameters::Type::particulate_flow)
        check_particles_suit_the_run(parameters, filename);
      naming_the_file(filename, [&]() {
        if (parameters.flow.simulation.dimension == 2)
          check_against_coarse_mesh<2>(parameters, filename, comm);
        else
          check_against_coarse_mesh<3>(parameters, filename, comm);
      });
    }
  } // namespace fbm
} // namespace particulate
