#include <particulate/fbm/hinged_motion.h>

#include <algorithm>

namespace particulate {
  namespace fbm {
    template <int dim>
    HingedMotion<dim>::HingedMotion(const ParticleDescription &part,
                                    const PrescribedState     &parent_start,
                                    const double               end_time)
      : reference_position(part.position)
      , reference_orientation(part.orientation)
      , hinge_point(part.hinge.point)
      , hinge_axis(part.hinge.axis.normalized())
      , parent_start_position(parent_start.position)
      , parent_start_orientation(parent_start.orientation)
      , beta(part.hinge.angle.template create<dim>(1, "Hinge angle"))
      , h(1e-6 * std::max(1., end_time))
    {}



    template <int dim>
    double
    HingedMotion<dim>::angle(const double t) const
    {
      beta->set_time(t);
      return beta->value(dealii::Point<dim>(), 0);
    }



    template <int dim>
    PrescribedState
    HingedMotion<dim>::state(const double           t,
                             const PrescribedState &parent) const
    {
      const Eigen::Quaterniond carry
        = parent.orientation * parent_start_orientation.conjugate();
      const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle(t), hinge_axis));
      const Eigen::Vector3d    relative
        = hinge_point + turn * (reference_position - hinge_point);
      const Eigen::Vector3d hinge_now
        = parent.position + carry * (hinge_point - parent_start_position);
      const Eigen::Vector3d axis_now = carry * hinge_axis;
      const double          rate     = (angle(t + h) - angle(t - h)) / (2. * h);

      PrescribedState s;
      s.position = parent.position + carry * (relative - parent_start_position);
      s.orientation = (carry * turn * reference_orientation).normalized();
      s.velocity    = parent.velocity
                   + parent.angular_velocity.cross(s.position - parent.position)
                   + rate * axis_now.cross(s.position - hinge_now);
      s.angular_velocity = parent.angular_velocity + rate * axis_now;
      return s;
    }

    template class HingedMotion<2>;
    template class HingedMotion<3>;
  } // namespace fbm
} // namespace particulate
