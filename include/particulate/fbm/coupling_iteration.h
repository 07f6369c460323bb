#ifndef particulate_fbm_coupling_iteration_h
#define particulate_fbm_coupling_iteration_h

#include <Eigen/Core>

namespace particulate {
  namespace fbm {
    /**
     * The fixed point of an iterated coupled step ('Coupling = iterated').
     * The fluid is given the free bodies' velocities at the end of the
     * step, x; with its loads the bodies reach y = G(x). The step is done
     * when x = G(x): then the bodies move as they would with the loads of
     * the velocities they end with, an implicit coupling, whatever the
     * added mass.
     *
     * The next x is x + w (y - x), with Aitken's dynamic relaxation for w
     * (Küttler & Wall, Comput. Mech. 43, 2008): from the last two
     * residuals r = y - x,
     *   w_j = -w_{j-1} r_{j-1} . (r_j - r_{j-1}) / |r_j - r_{j-1}|^2,
     * which for one degree of freedom and a linear G is the secant method
     * and lands on the fixed point in one step. The first w of a step is 1:
     * the explicit step with the added mass, whose G contracts for the
     * added masses that keep the explicit coupling stable.
     *
     * The vectors stack the free bodies' generalized velocities, rotation
     * multiplied by the body's bounding radius, so that all entries are
     * speeds.
     */
    class CouplingIteration
    {
    public:
      /**
       * @param tolerance the step is converged when max |y - x| <=
       *   tolerance s, s the larger of max |y| (max over the entries) and
       *   the speed scale record() is given
       * @param max_iterations fluid solves a step may take
       */
      CouplingIteration(const double       tolerance,
                        const unsigned int max_iterations);

      /** Forget the last step's iterates. */
      void
      start_step();

      /**
       * Record the iterate: the velocities @p given to the fluid and those
       * @p reached by the bodies. Returns whether the step is converged.
       * @param speed_scale the motion's speed [m/s], for the tolerance
       *   where the bodies pass through rest: there the loads' own
       *   precision (that of the flow's solvers) gives a residual that is
       *   not small against the speed of the moment
       */
      bool
      record(const Eigen::VectorXd &given,
             const Eigen::VectorXd &reached,
             const double           speed_scale = 0.);

      /** Whether the step has used its iterations without converging. */
      bool
      exhausted() const
      {
        return iterations >= max_iterations;
      }

      /** The velocities to give the fluid next (after a record() that was
       *  not converged). */
      Eigen::VectorXd
      next_given() const;

      /** Fluid solves of the current step so far. */
      unsigned int
      n_iterations() const
      {
        return iterations;
      }

      /** max |y - x| / s of the last iterate. */
      double
      relative_residual() const;

    private:
      const double       tolerance;
      const unsigned int max_iterations;
      unsigned int       iterations = 0;
      double             relaxation = 1.;
      Eigen::VectorXd    given, residual, last_residual;
      double             speed = 0.;
    };
  } // namespace fbm
} // namespace particulate

#endif
