#ifndef particulate_fbm_particle_parameters_h
#define particulate_fbm_particle_parameters_h

#include <particulate/core/input_outline.h>
#include <particulate/fbm/particle_description.h>
#include <particulate/fbm/particle_set_parameters.h>
#include <particulate/rigid/contact_solver.h>

#include <deal.II/base/parameter_handler.h>

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace particulate {
  namespace fbm {
    /** 'Covered nodes': which velocity nodes take a body's rigid velocity. */
    enum class CoveredNodes
    {
      inside,
      halfway,
      nearest
    };

    /** 'Films between parts': the liquid between two parts of one
     *  articulated body where they are closer than a cell. */
    enum class PartFilms
    {
      /// its nodes stay free
      resolve,
      /// a free node within one node spacing of two parts takes the motion
      /// of the nearer one
      cover
    };

    /** 'Containment backend': how the covered nodes are found. */
    enum class ContainmentBackend
    {
      automatic,
      cpu,
      cuda
    };

    /** 'Coupling': how often a time step solves the fluid and moves the
     *  free bodies. */
    enum class Coupling
    {
      /// once: the fluid sees the velocities predicted from the last step
      explicit_step,
      /// again, from the step's start, until the velocities the fluid was
      /// given are those the bodies reach
      iterated
    };

    /** The name of @p choice in a case file ("inside", "auto", ...). */
    std::string
    to_string(CoveredNodes choice);
    std::string
    to_string(Coupling choice);
    std::string
    to_string(PartFilms choice);
    std::string
    to_string(ContainmentBackend choice);

    /**
     * subsection `Particles`: the rigid bodies of a fictitious-boundary run
     * (thesis §5.2-5.3) and the coupling options. The particles are
     * described one by one (`Particle <n>`), from a particle file, by
     * lattices and by random fills, each naming a shape template (`Shape
     * <name>`); see particle_set_parameters.h.
     */
    struct ParticleParameters
    {
      /// every particle of the run, in the order of their ids
      std::vector<ParticleDescription> bodies;
      Eigen::Vector3d                  gravity = Eigen::Vector3d(0., 0., -9.81);
      /// world axes along which the particles may not move (symmetry)
      std::array<bool, 3> locked_translation = {{false, false, false}};
      /// world axes about which the particles may not rotate
      std::array<bool, 3> locked_rotation = {{false, false, false}};
      /// C in m_a = C rho_f V of the added-mass-corrected coupling
      double   added_mass_coefficient = 2.;
      Coupling coupling               = Coupling::explicit_step;
      /// an iterated step ends when the velocities the fluid was given
      /// differ from those the bodies reached by at most this fraction of
      /// the bodies' speed (rotation counted at the bounding radius), or
      /// of the largest speed reached so far
      double       coupling_tolerance      = 1e-4;
      unsigned int max_coupling_iterations = 20;
      /// 'Constraint velocity = extrapolated': the covered nodes get the
      /// velocity predicted for the end of the step, U_n + dt a_n
      bool extrapolate_constraint_velocity = true;
      /// 'Interface position = midpoint': the covered nodes of a step are
      /// those of the particle moved and turned to the middle of the step
      bool midpoint_interface_position = true;
      /// 'Stage velocities = interpolated': a free body's covered nodes go
      /// from its velocity at t_n to the predicted one through the stages
      /// of a step, as a prescribed body's do, so that the force holds the
      /// added mass; 'held' keeps the predicted one from the first stage on
      bool interpolate_free_stage_velocities = true;
      /// 'Force integral = stress and inertia': the loads include the
      /// momentum of the fluid in the cut cells (fluid_inertia_loads), so
      /// that body and fluid exchange momentum exactly
      bool force_includes_fluid_inertia = true;
      /// contact handling
      rigid::ContactSolverType contact_solver
        = rigid::ContactSolverType::sequential_impulses;
      double restitution = 0.;
      double friction    = 0.;
      /// film thickness [m] kept between surfaces by the contact model;
      /// empty: one cell of the finest mesh level (see 'Contact distance')
      std::optional<double> contact_distance;
      /// faces of the mesh's bounding box that are walls for contacts, in
      /// the order x-, x+, y-, y+, z-, z+
      std::array<bool, 6> walls = {{true, true, true, true, true, true}};
      /// height [m] of a fluidized bed's distributor: the lowest wall (z-,
      /// y- in 2D) raised to it for the particles, while the liquid flows
      /// through; empty: the wall lies on the mesh's face
      std::optional<double> distributor_height;
      unsigned int          substeps            = 1;
      ContainmentBackend    containment_backend = ContainmentBackend::automatic;
      CoveredNodes          covered_nodes       = CoveredNodes::inside;
      PartFilms             part_films          = PartFilms::resolve;
      /// faces of the mesh's bounding box that are mirror planes of the
      /// set-up (x-, x+, y-, y+, z-, z+): the particles lie on them, and the
      /// loads integrated over the part of each body inside the mesh are
      /// completed by their mirror images
      std::array<bool, 6> symmetry_planes
        = {{false, false, false, false, false, false}};

      /**
       * Declare the entries, with the list subsections of @p layout (those
       * the case file holds; see ParticleSetLayout). Their defaults are the
       * values of a default-constructed ParticleParameters.
       */
      static void
      declare(dealii::ParameterHandler &prm, const ParticleSetLayout &layout);

      /**
       * Read the entries; @p dim is the space dimension of the run (it
       * decides how many coordinates a position has).
       * @param outline the case file, for the file and line of messages
       * @throw std::runtime_error naming the file, line and entry and what
       *   to write
       */
      void
      parse(dealii::ParameterHandler &prm,
            const unsigned int        dim,
            const core::InputOutline &outline);

      unsigned int
      n_particles() const
      {
        return bodies.size();
      }

      /** Whether some particle moves as @p motion. */
      bool
      any(const ParticleMotion motion) const;
    };
  } // namespace fbm
} // namespace particulate

#endif
