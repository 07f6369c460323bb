#include <particulate/fbm/prescribed_motion.h>

#include <algorithm>

namespace particulate {
  namespace fbm {
    template <int dim>
    PrescribedMotion<dim>::PrescribedMotion(const ParticleDescription &particle,
                                            const double               end_time)
      : start(particle.position)
      , start_orientation(particle.orientation)
      , displacement(particle.prescribed_displacement
                       .template create<dim>(dim, "Prescribed displacement"))
      , rotation_vector(particle.prescribed_rotation.template create<dim>(
          dim == 2 ? 1 : 3,
          "Prescribed rotation"))
      , h(1e-6 * std::max(1., end_time))
    {}



    template <int dim>
    Eigen::Vector3d
    PrescribedMotion<dim>::displacement_at(const double t) const
    {
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      displacement->set_time(t);
      for (unsigned int c = 0; c < dim; ++c)
        d[c] = displacement->value(dealii::Point<dim>(), c);
      return d;
    }



    template <int dim>
    Eigen::Quaterniond
    PrescribedMotion<dim>::rotation(const double t) const
    {
      rotation_vector->set_time(t);
      Eigen::Vector3d phi = Eigen::Vector3d::Zero();
      if (dim == 2)
        phi[2] = rotation_vector->value(dealii::Point<dim>(), 0);
      else
        for (unsigned int c = 0; c < 3; ++c)
          phi[c] = rotation_vector->value(dealii::Point<dim>(), c);
      const double angle = phi.norm();
      if (angle == 0.)
        return Eigen::Quaterniond::Identity();
      return Eigen::Quaterniond(Eigen::AngleAxisd(angle, phi / angle));
    }



    template <int dim>
    PrescribedState
    PrescribedMotion<dim>::state(const double t) const
    {
      PrescribedState s;
      s.position = start + displacement_at(t);
      s.velocity = (displacement_at(t + h) - displacement_at(t - h)) / (2. * h);
      const Eigen::Quaterniond r = rotation(t);
      s.orientation              = r * start_orientation;
      // omega from the rotation that takes R(t - h) to R(t + h) in 2h
      const Eigen::AngleAxisd turn(rotation(t + h) * rotation(t - h).inverse());
      s.angular_velocity = turn.angle() / (2. * h) * turn.axis();
      if (turn.angle() == 0.)
        s.angular_velocity.setZero();
      return s;
    }

    template class PrescribedMotion<2>;
    template class PrescribedMotion<3>;
  } // namespace fbm
} // namespace particulate
