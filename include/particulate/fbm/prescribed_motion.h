#ifndef particulate_fbm_prescribed_motion_h
#define particulate_fbm_prescribed_motion_h

#include <particulate/fbm/particle_description.h>

#include <deal.II/base/function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>

namespace particulate {
  namespace fbm {
    /** Where a prescribed body is at a time and how it moves there. */
    struct PrescribedState
    {
      Eigen::Vector3d    position;         ///< [m]
      Eigen::Vector3d    velocity;         ///< [m/s]
      Eigen::Quaterniond orientation;      ///< body to world
      Eigen::Vector3d    angular_velocity; ///< world frame [rad/s]
    };

    /**
     * A motion given by a displacement d(t) from a body's initial position
     * and a rotation phi(t) applied to its initial orientation (`Motion =
     * prescribed` of a particle): x(t) = x_0 + d(t), q(t) = R(phi(t)) q_0,
     * phi a rotation vector (3D) or the angle about z (2D).
     */
    template <int dim>
    class PrescribedMotion
    {
    public:
      /**
       * @param particle its initial pose and the expressions of its motion
       * @param end_time the run's end time [s]: it sets the step of the
       *   central differences that give the velocities
       * @throw std::runtime_error if an expression does not parse or has
       *   another number of components, naming the entry
       */
      PrescribedMotion(const ParticleDescription &particle,
                       const double               end_time);

      /** The state at time @p t (the velocities by central differences of
       *  the expressions, which make them smooth). */
      PrescribedState
      state(const double t) const;

    private:
      /** The rotation R(phi(t)). */
      Eigen::Quaterniond
      rotation(const double t) const;

      Eigen::Vector3d
      displacement_at(const double t) const;

      Eigen::Vector3d                        start;
      Eigen::Quaterniond                     start_orientation;
      std::unique_ptr<dealii::Function<dim>> displacement;
      std::unique_ptr<dealii::Function<dim>> rotation_vector;
      double                                 h;
    };
  } // namespace fbm
} // namespace particulate

#endif
