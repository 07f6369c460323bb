#include <particulate/fbm/coupling_iteration.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace particulate {
  namespace fbm {
    namespace {
      /** A change whose part orthogonal to the newer ones is below this
       *  share of its length adds no direction. */
      constexpr double dependence_threshold = 1e-2;

      double
      largest_entry(const Eigen::VectorXd &v)
      {
        return v.size() > 0 ? v.cwiseAbs().maxCoeff() : 0.;
      }
    } // namespace



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
      reached.resize(0);
      residual.resize(0);
      residual_changes.clear();
      reached_changes.clear();
    }



    bool
    CouplingIteration::record(const Eigen::VectorXd &given_now,
                              const Eigen::VectorXd &reached_now,
                              const double           speed_scale)
    {
      if (given_now.size() != reached_now.size())
        throw std::invalid_argument(
          "CouplingIteration: given and reached differ in size");
      ++iterations;
      const Eigen::VectorXd residual_now = reached_now - given_now;
      if (residual.size() == residual_now.size())
        add_change(reached_now, residual_now);
      reached  = reached_now;
      residual = residual_now;
      speed    = std::max(speed_scale, largest_entry(reached));
      return largest_entry(residual) <= tolerance * speed;
    }



    void
    CouplingIteration::add_change(const Eigen::VectorXd &reached_now,
                                  const Eigen::VectorXd &residual_now)
    {
      residual_changes.push_front(residual_now - residual);
      reached_changes.push_front(reached_now - reached);
      drop_dependent_changes();
    }



    void
    CouplingIteration::drop_dependent_changes()
    {
      // modified Gram-Schmidt, newest first
      std::vector<Eigen::VectorXd> basis;
      for (std::size_t j = 0; j < residual_changes.size();)
        {
          Eigen::VectorXd v      = residual_changes[j];
          const double    length = v.norm();
          for (const Eigen::VectorXd &q : basis)
            v -= q.dot(v) * q;
          const double orthogonal = v.norm();
          if (length == 0. || orthogonal < dependence_threshold * length)
            {
              residual_changes.erase(residual_changes.begin() + j);
              reached_changes.erase(reached_changes.begin() + j);
              continue;
            }
          basis.push_back(v / orthogonal);
          ++j;
        }
    }



    Eigen::VectorXd
    CouplingIteration::next_given() const
    {
      if (residual_changes.empty())
        return reached;
      const Eigen::Index n = residual.size();
      const Eigen::Index m = residual_changes.size();
      Eigen::MatrixXd    V(n, m), W(n, m);
      for (Eigen::Index j = 0; j < m; ++j)
        {
          V.col(j) = residual_changes[j];
          W.col(j) = reached_changes[j];
        }
      const Eigen::VectorXd c = V.colPivHouseholderQr().solve(-residual);
      return reached + W * c;
    }



    double
    CouplingIteration::relative_residual() const
    {
      const double largest = largest_entry(residual);
      return speed > 0. ? largest / speed : largest;
    }
  } // namespace fbm
} // namespace particulate
