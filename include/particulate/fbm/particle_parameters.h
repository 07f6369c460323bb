#ifndef particulate_fbm_particle_parameters_h
#define particulate_fbm_particle_parameters_h

#include <particulate/core/function_expression.h>

#include <deal.II/base/parameter_handler.h>

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * subsection `Particles`: the rigid bodies of a fictitious-boundary run
     * (thesis §5.2-5.3) and the coupling options. All particles share one
     * shape, size and material; their number is the number of `Positions`.
     */
    struct ParticleParameters
    {
      /** Ball in 3D; disk (a cylinder of unit depth along z) in 2D. */
      enum class Shape
      {
        sphere,
        disk,
        cylinder ///< 3D: a circular cylinder along z of length 'Length'
      };
      /** How the particles move. */
      enum class Motion
      {
        free,      ///< Newton-Euler under fluid, gravity and contact forces
        fixed,     ///< at rest (an obstacle described by the FBM)
        prescribed ///< translated by a given displacement d(t)
      };

      Shape  shape  = Shape::sphere;
      double radius = 0.0075; ///< [m]
      /// Shape::cylinder: length along z [m]
      double length  = 0.;
      double density = 1120.; ///< particle density rho_p [kg/m^3]
      Motion motion  = Motion::free;
      /// Motion::prescribed: displacement from the initial position [m],
      /// dim components of t
      core::FunctionExpression prescribed_displacement;
      /// centres of mass [m] (z = 0 in 2D)
      std::vector<Eigen::Vector3d> positions;
      /// initial velocities [m/s], empty or one per particle
      std::vector<Eigen::Vector3d> velocities;
      Eigen::Vector3d              gravity = Eigen::Vector3d(0., 0., -9.81);
      /// world axes along which the particles may not move (symmetry)
      std::array<bool, 3> locked_translation = {{false, false, false}};
      /// world axes about which the particles may not rotate
      std::array<bool, 3> locked_rotation = {{false, false, false}};
      /// C in m_a = C rho_f V of the added-mass-corrected coupling
      double added_mass_coefficient = 1.;
      /// 'Constraint velocity = extrapolated': the covered nodes get the
      /// velocity predicted for the end of the step, U_n + dt a_n
      bool extrapolate_constraint_velocity = false;
      /// 'Interface position = midpoint': the covered nodes of a step are
      /// those of the particle moved to the middle of the step
      bool midpoint_interface_position = false;
      /// 'Force integral = stress and inertia': the loads include the
      /// momentum of the fluid in the cut cells (fluid_inertia_loads)
      bool force_includes_fluid_inertia = false;
      /// contact handling
      std::string contact_solver = "sequential impulses";
      double      restitution    = 0.;
      double      friction       = 0.;
      /// film thickness [m] kept between surfaces by the contact model;
      /// empty: one cell of the finest mesh level (see 'Contact distance')
      std::optional<double> contact_distance;
      /// faces of the mesh's bounding box that are walls for contacts, in
      /// the order x-, x+, y-, y+, z-, z+
      std::array<bool, 6> walls    = {{true, true, true, true, true, true}};
      unsigned int        substeps = 1;
      /// "auto", "cpu" or "cuda": how the FBM finds the nodes inside bodies
      std::string containment_backend = "auto";
      /// 'Covered nodes': "inside", "halfway" or "nearest"
      std::string covered_nodes = "inside";
      /// faces of the mesh's bounding box that are mirror planes of the
      /// set-up (x-, x+, y-, y+, z-, z+): the particles lie on them, and the
      /// loads integrated over the part of each body inside the mesh are
      /// completed by their mirror images
      std::array<bool, 6> symmetry_planes
        = {{false, false, false, false, false, false}};

      static void
      declare(dealii::ParameterHandler &prm);

      /**
       * Read the entries; @p dim is the space dimension of the run (it
       * decides how many coordinates a position has). Throws
       * std::runtime_error with the entry and what to write.
       */
      void
      parse(dealii::ParameterHandler &prm, const unsigned int dim);

      bool
      motion_is_fixed() const
      {
        return motion == Motion::fixed;
      }

      unsigned int
      n_particles() const
      {
        return positions.size();
      }
    };
  } // namespace fbm
} // namespace particulate

#endif
