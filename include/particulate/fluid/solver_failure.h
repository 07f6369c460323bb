#ifndef particulate_fluid_solver_failure_h
#define particulate_fluid_solver_failure_h

#include <stdexcept>
#include <string>

namespace particulate {
  namespace fluid {
    /**
     * A flow solve that failed. It carries what the solver measured (which
     * solver, where it stopped, the residual and its target) apart from
     * the advice on what to do, so that a caller that knows more about the
     * step, like the coupled particulate flow, can name the likely cause
     * instead. what() is both: the flow solver's own advice suits a run
     * without particles.
     */
    class SolverFailure : public std::runtime_error
    {
    public:
      enum class Kind
      {
        /// FGMRES did not reach its tolerance
        linear,
        /// the Newton or Picard iteration did not reach its tolerance
        nonlinear,
        /// the residual is NaN or Inf
        non_finite
      };

      SolverFailure(const Kind         kind,
                    const std::string &measured,
                    const std::string &advice)
        : std::runtime_error(measured + " " + advice)
        , kind(kind)
        , measured(measured)
      {}

      /** Which solve failed. */
      const Kind kind;
      /** What the solver measured, without advice. */
      const std::string measured;
    };
  } // namespace fluid
} // namespace particulate

#endif
