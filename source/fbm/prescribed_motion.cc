#include <particulate/fbm/prescribed_motion.h>

#include <algorithm>

namespace particulate {
  namespace fbm {
    template <int dim>
    PrescribedMotion<dim>::PrescribedMotion(
      const core::FunctionExpression &expression,
      const double                    end_time)
      : displacement(
        expression.template create<dim>(dim,
                                        "Particles / Prescribed displacement"))
      , h(1e-6 * std::max(1., end_time))
    {}



    template <int dim>
    std::pair<Eigen::Vector3d, Eigen::Vector3d>
    PrescribedMotion<dim>::state(const Eigen::Vector3d &start,
                                 const double           t) const
    {
      Eigen::Vector3d x = start, v = Eigen::Vector3d::Zero();
      for (unsigned int d = 0; d < dim; ++d)
        {
          displacement->set_time(t);
          x[d] += displacement->value(dealii::Point<dim>(), d);
          displacement->set_time(t + h);
          v[d] = displacement->value(dealii::Point<dim>(), d);
          displacement->set_time(t - h);
          v[d]
            = (v[d] - displacement->value(dealii::Point<dim>(), d)) / (2. * h);
        }
      return {x, v};
    }

    template class PrescribedMotion<2>;
    template class PrescribedMotion<3>;
  } // namespace fbm
} // namespace particulate
