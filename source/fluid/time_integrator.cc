#include <particulate/fluid/time_integrator.h>

#include <cmath>

#include "owned_entries_io.h"

namespace particulate {
  namespace fluid {
    SolveStatistics &
    SolveStatistics::operator+=(const SolveStatistics &other)
    {
      nonlinear_iterations += other.nonlinear_iterations;
      linear_iterations += other.linear_iterations;
      final_residual = other.final_residual;
      used_fixed_point |= other.used_fixed_point;
      return *this;
    }



    std::vector<Stage>
    stages_of_step(const core::TimeParameters::Scheme scheme,
                   const double                       time,
                   const double                       k)
    {
      using Scheme = core::TimeParameters::Scheme;
      switch (scheme)
        {
          case Scheme::steady:
            return {{0., 1., 0., time, time}};
          case Scheme::backward_euler:
            return {{k, 1., 0., time, time + k}};
          case Scheme::crank_nicolson:
            return {{k, 0.5, 0.5, time, time + k}};
          case Scheme::fractional_step_theta:
            {
              // thesis eq. 5.14
              const double theta       = 1. - std::sqrt(2.) / 2.;
              const double theta_prime = 1. - 2. * theta;
              const double alpha       = (1. - 2. * theta) / (1. - theta);
              const double beta        = 1. - alpha;
              const double t1          = time + theta * k;
              const double t2          = time + (1. - theta) * k;
              return {{theta * k, alpha, beta, time, t1},
                      {theta_prime * k, beta, alpha, t1, t2},
                      {theta * k, alpha, beta, t2, time + k}};
            }
        }
      return {};
    }



    TimeIntegrator::TimeIntegrator(const InitialGuess initial_guess)
      : initial_guess(initial_guess)
    {}



    void
    TimeIntegrator::reinit(const std::vector<dealii::IndexSet> &owned,
                           const std::vector<dealii::IndexSet> &relevant,
                           const MPI_Comm                       comm)
    {
      previous_solution.reinit(owned, relevant, comm);
      has_previous_solution = false;
    }



    std::vector<dealii::IndexSet>
    TimeIntegrator::owned_partitioning() const
    {
      std::vector<dealii::IndexSet> owned;
      for (unsigned int b = 0; b < previous_solution.n_blocks(); ++b)
        owned.push_back(previous_solution.block(b).locally_owned_elements());
      return owned;
    }



    TimeIntegrator::BlockVector
    TimeIntegrator::make_owned_vector() const
    {
      return BlockVector(owned_partitioning(),
                         previous_solution.block(0).get_mpi_communicator());
    }



    bool
    TimeIntegrator::compute_rate(const BlockVector &solution,
                                 const double       time,
                                 const double       k,
                                 BlockVector       &rate) const
    {
      if (initial_guess != InitialGuess::extrapolated || k <= 0.
          || !has_previous_solution || time <= previous_time)
        return false;
      rate                 = make_owned_vector();
      rate                 = solution;
      BlockVector previous = make_owned_vector();
      previous             = previous_solution;
      rate -= previous;
      rate *= 1. / (time - previous_time);
      return true;
    }



    SolveStatistics
    TimeIntegrator::advance(const double                       time,
                            const double                       k,
                            const core::TimeParameters::Scheme scheme,
                            BlockVector                       &solution,
                            BlockVector                       &old_solution,
                            const StageSolver                 &solve_stage)
    {
      BlockVector rate;
      const bool  extrapolate = compute_rate(solution, time, k, rate);
      previous_solution       = solution;
      previous_time           = time;
      has_previous_solution   = k > 0.;

      SolveStatistics total;
      for (const Stage &stage : stages_of_step(scheme, time, k))
        {
          old_solution = solution;
          if (extrapolate)
            {
              BlockVector guess = make_owned_vector();
              guess             = solution;
              guess.add(stage.time_new - stage.time_old, rate);
              solution = guess;
            }
          total += solve_stage(stage);
        }
      return total;
    }



    void
    TimeIntegrator::forget_history()
    {
      has_previous_solution = false;
    }



    void
    TimeIntegrator::save(std::ostream &out) const
    {
      core::write_binary<bool>(out, has_previous_solution);
      core::write_binary<double>(out, previous_time);
      if (has_previous_solution)
        write_owned(out, previous_solution, owned_partitioning());
    }



    void
    TimeIntegrator::load(std::istream &in)
    {
      has_previous_solution = core::read_binary<bool>(in);
      previous_time         = core::read_binary<double>(in);
      if (has_previous_solution)
        {
          BlockVector owned = make_owned_vector();
          read_owned(in, owned, owned_partitioning());
          previous_solution = owned;
        }
    }



    std::size_t
    TimeIntegrator::memory_consumption() const
    {
      return previous_solution.memory_consumption();
    }
  } // namespace fluid
} // namespace particulate
