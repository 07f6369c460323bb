#ifndef particulate_fbm_prescribed_motion_h
#define particulate_fbm_prescribed_motion_h

#include <particulate/core/function_expression.h>

#include <deal.II/base/function.h>

#include <Eigen/Core>

#include <memory>
#include <utility>

namespace particulate {
  namespace fbm {
    /**
     * A motion given as a displacement d(t) from a body's starting position
     * (`Motion = prescribed`, subsection `Particles`): where the body is at
     * time t and how fast it moves there.
     */
    template <int dim>
    class PrescribedMotion
    {
    public:
      /**
       * @param displacement dim components of t [m]
       * @param end_time the run's end time [s]: it sets the step of the
       *   central difference that gives the velocity
       * @throw std::runtime_error if the expression does not parse or has
       *   another number of components, naming the entry
       */
      PrescribedMotion(const core::FunctionExpression &displacement,
                       const double                    end_time);

      /** Position [m] and velocity [m/s] at time @p t of a body that
       *  started at @p start (the velocity by a central difference of the
       *  displacement, which the expression makes smooth). */
      std::pair<Eigen::Vector3d, Eigen::Vector3d>
      state(const Eigen::Vector3d &start, const double t) const;

    private:
      std::unique_ptr<dealii::Function<dim>> displacement;
      double                                 h;
    };
  } // namespace fbm
} // namespace particulate

#endif
