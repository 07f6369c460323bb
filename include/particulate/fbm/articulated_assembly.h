#ifndef particulate_fbm_articulated_assembly_h
#define particulate_fbm_articulated_assembly_h

#include <particulate/fbm/particle_description.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace particulate {
  namespace fbm {
    /** Where and how a particle starts (a prescribed or hinged one at its
     *  motion's state at t = 0). */
    struct BodyStart
    {
      Eigen::Vector3d    position         = Eigen::Vector3d::Zero();
      Eigen::Quaterniond orientation      = Eigen::Quaterniond::Identity();
      Eigen::Vector3d    velocity         = Eigen::Vector3d::Zero();
      Eigen::Vector3d    angular_velocity = Eigen::Vector3d::Zero();
    };

    /**
     * The particle whose rigid body carries particle @p i: the parent of a
     * hinged part, else @p i itself. An articulated body (a swimmer) is its
     * head with the parts hinged to it; the head moves as one rigid body
     * under the loads on all of them.
     */
    unsigned int
    assembly_head(const std::vector<ParticleDescription> &particles,
                  const unsigned int                      i);

    /** For each particle, the parts hinged to it (empty for most). */
    std::vector<std::vector<unsigned int>>
    hinged_parts(const std::vector<ParticleDescription> &particles);

    /** The mass and inertia an assembly's head moves with. */
    struct AssemblyInertia
    {
      /// [kg]
      double mass = 0.;
      /// about the head's centre, in the head's body frame [kg m^2]
      Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    };

    /**
     * The head @p head with its hinged @p parts where they start, each with
     * the density rho_p + @p extra_density (the coupling's added mass):
     * the summed masses, and the inertia about the head's centre (each
     * part's own, turned into place, plus its mass at its distance, the
     * parallel-axis theorem). The momentum of the parts' motion relative to
     * the head is not part of the model: exact where the motion follows
     * the force balance (a swimmer at low Reynolds number).
     */
    AssemblyInertia
    assembly_inertia(const std::vector<ParticleDescription> &particles,
                     const std::vector<BodyStart>           &starts,
                     const unsigned int                      head,
                     const std::vector<unsigned int>        &parts,
                     const double                            extra_density);
  } // namespace fbm
} // namespace particulate

#endif
