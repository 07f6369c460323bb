#ifndef particulate_fbm_hinged_motion_h
#define particulate_fbm_hinged_motion_h

#include <particulate/fbm/particle_description.h>
#include <particulate/fbm/prescribed_motion.h>

#include <deal.II/base/function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>

namespace particulate {
  namespace fbm {
    /**
     * The motion of a part of an articulated body (`Motion = hinged`): it
     * rides on its parent and turns relative to it about a hinge by the
     * angle beta(t). With the parent's pose (X_0, q_0) at t = 0 and
     * (X, q) now, Q = q q_0^-1, the hinge point p and axis a and the
     * part's pose (x_r, q_r) as the case file gives them (with the parent
     * at t = 0), R = R(a, beta(t)):
     *   x(t) = X + Q (p + R (x_r - p) - X_0),   q(t) = Q R q_r,
     * and the part moves with the parent's rigid velocity plus the hinge's
     * turn beta' Q a about the hinge's current position X + Q (p - X_0):
     *   u(x) = U + omega x (x - X) + beta' (Q a) x (x - p_now).
     */
    template <int dim>
    class HingedMotion
    {
    public:
      /**
       * @param part the part, its pose at beta = 0 and its hinge
       * @param parent_start where and how its parent starts (t = 0)
       * @param end_time the run's end time [s]: it sets the step of the
       *   central differences that give beta'
       * @throw std::runtime_error if the angle's expression does not parse
       *   or has more than one component, naming the entry
       */
      HingedMotion(const ParticleDescription &part,
                   const PrescribedState     &parent_start,
                   const double               end_time);

      /** The part's state at time @p t, its parent being in state
       *  @p parent. */
      PrescribedState
      state(const double t, const PrescribedState &parent) const;

      /** beta(t) [rad]. */
      double
      angle(const double t) const;

    private:
      Eigen::Vector3d                        reference_position;
      Eigen::Quaterniond                     reference_orientation;
      Eigen::Vector3d                        hinge_point;
      Eigen::Vector3d                        hinge_axis;
      Eigen::Vector3d                        parent_start_position;
      Eigen::Quaterniond                     parent_start_orientation;
      std::unique_ptr<dealii::Function<dim>> beta;
      double                                 h;
    };
  } // namespace fbm
} // namespace particulate

#endif
