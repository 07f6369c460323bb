#ifndef particulate_fbm_particle_description_h
#define particulate_fbm_particle_description_h

#include <particulate/core/function_expression.h>
#include <particulate/geometry/shape.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <string>

namespace particulate {
  namespace fbm {
    /** How a particle moves. */
    enum class ParticleMotion
    {
      /// Newton-Euler under fluid, gravity and contact forces
      free,
      /// at rest: an obstacle the flow sees through the fictitious boundary
      /// and the particles meet in contacts
      fixed,
      /// moved by a given displacement d(t) and rotation phi(t), whatever
      /// the fluid does
      prescribed,
      /// a part of an articulated body: carried by another particle (its
      /// parent) and turned relative to it about a hinge by a given angle
      /// beta(t); the parent feels the part's loads
      hinged
    };

    /** How a hinged part hangs on its parent (ParticleMotion::hinged). */
    struct HingeDescription
    {
      /// the index of the particle it is hinged to
      unsigned int parent = 0;
      /// a point on the hinge's axis [m] and the axis (unit), both in the
      /// world as the case file places the parent at t = 0; in 2D the axis
      /// is z
      Eigen::Vector3d point = Eigen::Vector3d::Zero();
      Eigen::Vector3d axis  = Eigen::Vector3d::UnitZ();
      /// beta(t) [rad], the turn about the axis (right-handed) from the pose
      /// the case file gives the part
      core::FunctionExpression angle;
    };

    /**
     * One particle of a run as the case file describes it, whichever way
     * it was written (a `Particle` subsection, a line of a particle file,
     * a lattice or a random fill): everything the coupled loop needs to
     * make its rigid body, its interface and the mesh that adapts to it.
     */
    struct ParticleDescription
    {
      /// the solid in its body frame (principal axes, centroid at 0)
      std::shared_ptr<const geometry::Shape> shape;
      /// the name of the shape template it uses
      std::string shape_name;
      /// rho_p [kg/m^3]
      double          density  = 0.;
      Eigen::Vector3d position = Eigen::Vector3d::Zero(); ///< centre [m]
      /// body-to-world rotation
      Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
      Eigen::Vector3d    velocity    = Eigen::Vector3d::Zero(); ///< [m/s]
      /// world frame [rad/s]
      Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
      ParticleMotion  motion           = ParticleMotion::free;
      /// ParticleMotion::prescribed: displacement from 'position' [m], dim
      /// components of t
      core::FunctionExpression prescribed_displacement;
      /// ParticleMotion::prescribed: rotation from 'orientation', as a
      /// rotation vector [rad] in the world frame (3D: 3 components; 2D: one,
      /// the angle about z)
      core::FunctionExpression prescribed_rotation;
      /// ParticleMotion::hinged: its parent, hinge and angle
      HingeDescription hinge;
      /// where the input describes it, for messages ("case.prm:40:
      /// subsection 'Particles / Particle 3'", "beads.csv:17")
      std::string origin;
    };
  } // namespace fbm
} // namespace particulate

#endif
