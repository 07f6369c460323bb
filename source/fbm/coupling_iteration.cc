#include <particulate/fbm/coupling_iteration.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace particulate {
  namespace fbm {
    CouplingIteration::CouplingIteration(const double       tolerance,
                                         const unsigned int max_iterations)
      : tolerance(tolerance)
      , max_iterations(max_iterations)
    {
      if (max_iterations == 0)
        throw std::invalid_argument(
          "CouplingIteration: at least one iteration");
    }



    void
    CouplingIteration::start_step()
    {
      iterations = 0;
      relaxation = 1.;
      last_residual.resize(0);
    }



    bool
    CouplingIteration::record(const Eigen::VectorXd &given_now,
                              const Eigen::VectorXd &reached,
                              const double           speed_scale)
    {
      if (given_now.size() != reached.size())
        throw std::invalid_argument(
          "CouplingIteration: given and reached differ in size");
      ++iterations;
      given    = given_now;
      residual = reached - given_now;
      speed    = std::max(speed_scale,
                       reached.size() > 0 ? reached.cwiseAbs().maxCoeff() : 0.);
      if (last_residual.size() == residual.size())
        {
          // Aitken: the relaxation of the secant through the last two
          // residuals; kept where they do not differ
          const Eigen::VectorXd change = residual - last_residual;
          const double          norm2  = change.squaredNorm();
          if (norm2 > 0.)
            relaxation *= -last_residual.dot(change) / norm2;
        }
      last_residual = residual;
      const double largest
        = residual.size() > 0 ? residual.cwiseAbs().maxCoeff() : 0.;
      return largest <= tolerance * speed;
    }



    Eigen::VectorXd
    CouplingIteration::next_given() const
    {
      return given + relaxation * residual;
    }



    double
    CouplingIteration::relative_residual() const
    {
      const double largest
        = residual.size() > 0 ? residual.cwiseAbs().maxCoeff() : 0.;
      return speed > 0. ? largest / speed : largest;
    }
  } // namespace fbm
} // namespace particulate
