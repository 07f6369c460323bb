// The time integrator of the flow (include/particulate/fluid/
// time_integrator.h), alone:
// - The stages of every scheme, applied to the scalar model problem
//   u' = -lambda u + cos t (what one stage solves for a single mode), reach
//   the closed-form solution at t = 1 with the scheme's order: 2 for
//   fractional-step theta and Crank-Nicolson, 1 for backward Euler
//   (observed order from 20 and 40 steps within 0.1). Each step's stages
//   tile the step, and theta_i + theta_e = 1 in every stage.
// - The first iterate of each stage: with 'Initial guess = extrapolated' a
//   field that is linear in time is predicted exactly (to 1e-12) from the
//   second step on, not in the first step or after forget_history(), and
//   with 'previous solution' never; a checkpoint of the integrator (save,
//   load into a new one) predicts what the original does.

#include <particulate/fluid/time_integrator.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <sstream>

using namespace dealii;
using namespace particulate;
using Scheme = core::TimeParameters::Scheme;

namespace {
  constexpr double lambda = 2.;

  double
  exact(const double t)
  {
    const double particular
      = (lambda * std::cos(t) + std::sin(t)) / (lambda * lambda + 1.);
    const double c = 1. - lambda / (lambda * lambda + 1.);
    return c * std::exp(-lambda * t) + particular;
  }

  /** |u(1) - exact| with @p n steps; false in @p tiled when a step's
   *  stages do not tile it or a stage's weights do not sum to 1. */
  double
  model_problem_error(const Scheme scheme, const unsigned int n, bool &tiled)
  {
    const double k = 1. / n;
    double       u = 1.;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double t     = i * k;
        double       start = t;
        for (const fluid::Stage &s : fluid::stages_of_step(scheme, t, k))
          {
            tiled
              &= std::abs(s.time_old - start) < 1e-14
                 && std::abs(s.time_new - s.time_old - s.time_step) < 1e-14
                 && std::abs(s.theta_implicit + s.theta_explicit - 1.) < 1e-14;
            start = s.time_new;
            u     = (u
                 + s.time_step
                     * (-s.theta_explicit * lambda * u
                        + s.theta_implicit * std::cos(s.time_new)
                        + s.theta_explicit * std::cos(s.time_old)))
                / (1. + s.time_step * s.theta_implicit * lambda);
          }
        tiled &= std::abs(start - (t + k)) < 1e-14;
      }
    return std::abs(u - exact(1.));
  }

  bool
  check_order(const Scheme scheme, const double expected, const char *name)
  {
    bool         tiled  = true;
    const double coarse = model_problem_error(scheme, 20, tiled);
    const double fine   = model_problem_error(scheme, 40, tiled);
    const double order  = std::log2(coarse / fine);
    const bool   passed = tiled && std::abs(order - expected) < 0.1;
    std::printf("%s: %s, errors %.3e / %.3e at 20 / 40 steps, order %.3f "
                "(expected %.0f +- 0.1), stages %s\n",
                passed ? "PASS" : "FAIL",
                name,
                coarse,
                fine,
                order,
                expected,
                tiled ? "tile the steps" : "DO NOT tile the steps");
    return passed;
  }

  bool
  check_steady()
  {
    const auto stages = fluid::stages_of_step(Scheme::steady, 3., 0.5);
    const bool passed = stages.size() == 1 && stages[0].time_step == 0.
                        && stages[0].time_old == 3. && stages[0].time_new == 3.
                        && stages[0].mass_coefficient(1000.) == 0.;
    std::printf("%s: steady: one stage without time derivative\n",
                passed ? "PASS" : "FAIL");
    return passed;
  }

  using BlockVector = fluid::TimeIntegrator::BlockVector;

  /** The layout of the test's vectors: two blocks, one rank. */
  const std::vector<IndexSet> layout
    = {complete_index_set(3), complete_index_set(2)};

  /** The field a + b t, with a and b different in every entry. */
  void
  set_linear_field(BlockVector &v, const double t)
  {
    BlockVector  owned(layout, MPI_COMM_WORLD);
    unsigned int entry = 0;
    for (unsigned int b = 0; b < layout.size(); ++b)
      for (const auto i : layout[b])
        {
          owned.block(b)(i) = 1. + entry + (0.5 - entry) * t;
          ++entry;
        }
    owned.compress(VectorOperation::insert);
    v = owned;
  }

  /**
   * Advance @p steps steps of 0.1 with fractional-step theta, the stage
   * solver putting the exact linear field in place; returns the largest
   * difference between a stage's first iterate and the exact field, over
   * the last step.
   */
  double
  last_step_prediction_error(fluid::TimeIntegrator &integrator,
                             BlockVector           &solution,
                             const unsigned int     first_step,
                             const unsigned int     steps)
  {
    BlockVector old_solution(solution), exact_field(solution);
    double      error = 0.;
    for (unsigned int n = first_step; n < first_step + steps; ++n)
      {
        error = 0.;
        integrator.advance(n * 0.1,
                           0.1,
                           Scheme::fractional_step_theta,
                           solution,
                           old_solution,
                           [&](const fluid::Stage &stage) {
                             set_linear_field(exact_field, stage.time_new);
                             BlockVector difference(exact_field);
                             difference -= solution;
                             error = std::max(error, difference.linfty_norm());
                             solution = exact_field;
                             return fluid::SolveStatistics();
                           });
      }
    return error;
  }

  bool
  check_first_iterates()
  {
    const std::vector<IndexSet> owned
      = {complete_index_set(3), complete_index_set(2)};
    BlockVector solution(owned, MPI_COMM_WORLD);
    const auto  fresh = [&](const fluid::InitialGuess guess) {
      auto integrator = std::make_unique<fluid::TimeIntegrator>(guess);
      integrator->reinit(layout, layout, MPI_COMM_WORLD);
      set_linear_field(solution, 0.);
      return integrator;
    };
    bool       passed = true;
    const auto report = [&](const bool ok, const char *what, const double e) {
      std::printf("%s: %s (largest first-iterate error %.2e)\n",
                  ok ? "PASS" : "FAIL",
                  what,
                  e);
      passed &= ok;
    };

    auto         integrator = fresh(fluid::InitialGuess::extrapolated);
    const double first
      = last_step_prediction_error(*integrator, solution, 0, 1);
    report(first > 0.01, "extrapolated: the first step has no rate", first);
    const double later
      = last_step_prediction_error(*integrator, solution, 1, 3);
    report(later < 1e-12, "extrapolated: a linear field is predicted", later);

    std::stringstream checkpoint;
    integrator->save(checkpoint);
    const BlockVector saved_solution = solution;
    const double      continued
      = last_step_prediction_error(*integrator, solution, 4, 1);
    auto restarted = fresh(fluid::InitialGuess::extrapolated);
    restarted->load(checkpoint);
    solution = saved_solution;
    const double after_restart
      = last_step_prediction_error(*restarted, solution, 4, 1);
    report(after_restart < 1e-12 && continued < 1e-12,
           "extrapolated: a restarted integrator predicts as the original",
           after_restart);

    integrator->forget_history();
    const double forgotten
      = last_step_prediction_error(*integrator, solution, 5, 1);
    report(forgotten > 0.01,
           "extrapolated: no rate after forget_history()",
           forgotten);

    auto         plain = fresh(fluid::InitialGuess::previous_solution);
    const double never = last_step_prediction_error(*plain, solution, 0, 3);
    report(never > 0.01, "previous solution: never extrapolated", never);
    return passed;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             passed = true;
  passed
    &= check_order(Scheme::fractional_step_theta, 2., "fractional-step theta");
  passed &= check_order(Scheme::crank_nicolson, 2., "Crank-Nicolson");
  passed &= check_order(Scheme::backward_euler, 1., "backward Euler");
  passed &= check_steady();
  passed &= check_first_iterates();
  return passed ? 0 : 1;
}
