#ifndef particulate_fbm_coupling_iteration_h
#define particulate_fbm_coupling_iteration_h

#include <Eigen/Core>

#include <deque>

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
     * The iterates are accelerated by the interface quasi-Newton method
     * with an inverse Jacobian from a least-squares model, IQN-ILS
     * (Degroote, Bathe & Vierendeels, Comput. Struct. 87, 2009). With the
     * residual r = G(x) - x, every iterate after the first adds the
     * columns dr = r_j - r_{j-1} to V and dy = y_j - y_{j-1} to W. The
     * next x is
     *   x_next = y + W c,   c = argmin |V c + r|,
     * the point where the residual, linearised over the directions
     * explored in this step, vanishes; in the directions not yet explored
     * it is the plain iteration x_next = y. For a linear G in n unknowns
     * this lands on the fixed point with the (n + 1)-th given x (IQN-ILS
     * then equals GMRES on (I - A) x = b); for one unknown it is the
     * secant method.
     *
     * Why not a scalar relaxation: in a set of bodies most modes of G are
     * contractions (the added mass C exceeds the body's true added mass),
     * but two bodies close to each other squeeze the liquid between them,
     * and the mode that moves them against each other has an added mass
     * far above C: there G expands. One relaxation factor cannot serve
     * both; the least-squares model picks the few expanding modes out of
     * the iterates.
     *
     * Columns that are nearly linear combinations of newer ones are
     * dropped (their part orthogonal to the newer ones below 1 % of their
     * length): they carry no new direction, only round-off.
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

      /** Directions the least-squares model holds after the last
       *  record(). */
      unsigned int
      n_directions() const
      {
        return residual_changes.size();
      }

      /** max |y - x| / s of the last iterate. */
      double
      relative_residual() const;

    private:
      /** Add the change from the previous iterate to V and W. */
      void
      add_change(const Eigen::VectorXd &reached_now,
                 const Eigen::VectorXd &residual_now);

      /** Drop the columns of V (and W) that newer ones nearly span. */
      void
      drop_dependent_changes();

      const double       tolerance;
      const unsigned int max_iterations;
      unsigned int       iterations = 0;
      Eigen::VectorXd    reached, residual;
      double             speed = 0.;
      /// V and W, newest column first
      std::deque<Eigen::VectorXd> residual_changes, reached_changes;
    };
  } // namespace fbm
} // namespace particulate

#endif
