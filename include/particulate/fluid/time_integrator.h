#ifndef particulate_fluid_time_integrator_h
#define particulate_fluid_time_integrator_h

#include <particulate/core/simulation_parameters.h>
#include <particulate/fluid/fluid_parameters.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <functional>
#include <iosfwd>
#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * One implicit stage of a one-step scheme (thesis eq. 5.14/5.16):
     *
     *   rho (u - u_old)/k + theta_i N(u) u + grad p
     *     = - theta_e N(u_old) u_old + theta_i f(t_new) + theta_e f(t_old)
     *
     * with N(v)u = rho (v - w).grad u - div(2 mu D(u)) and w the mesh
     * velocity (ALE). `time_step = 0` means the steady problem N(u)u + grad p
     * = f.
     */
    struct Stage
    {
      double time_step      = 0.; ///< k [s]; 0 for steady
      double theta_implicit = 1.;
      double theta_explicit = 0.;
      double time_old       = 0.; ///< [s]
      double time_new       = 0.; ///< [s]

      /** rho/k of the time derivative, 0 for the steady problem. */
      double
      mass_coefficient(const double density) const
      {
        return time_step == 0. ? 0. : density / time_step;
      }
    };

    /** Iteration counts of one stage or one macro step. */
    struct SolveStatistics
    {
      unsigned int nonlinear_iterations = 0;
      unsigned int linear_iterations    = 0;
      double       final_residual       = 0.;
      bool         used_fixed_point     = false;

      SolveStatistics &
      operator+=(const SolveStatistics &other);
    };

    /**
     * The stages of one macro step from @p time of length @p time_step:
     * three for fractional-step theta (thesis eq. 5.14), one for
     * Crank-Nicolson and backward Euler, and one with time_step = 0 for the
     * steady problem.
     */
    std::vector<Stage>
    stages_of_step(const core::TimeParameters::Scheme scheme,
                   const double                       time,
                   const double                       time_step);

    /**
     * The time integrator of the flow: runs the stages of a macro step
     * through a stage solver and chooses each stage's first Newton iterate.
     *
     * With 'Initial guess = extrapolated' that iterate is the solution at
     * the stage's start plus the rate of change over the last full time
     * step; otherwise the solution at the stage's start. The rate is taken
     * over whole steps because fractional-step theta's stages are not
     * equally accurate snapshots of the flow (the middle one swaps the
     * implicit and explicit weights), and the body velocities of an FBM run
     * jump at the start of each step: a rate from one stage to the next
     * extrapolates that noise.
     */
    class TimeIntegrator
    {
    public:
      using BlockVector = dealii::TrilinosWrappers::MPI::BlockVector;
      using StageSolver = std::function<SolveStatistics(const Stage &)>;

      explicit TimeIntegrator(const InitialGuess initial_guess);

      /** The solver's layout (locally owned and locally relevant DoFs
       *  per block); forgets the history. */
      void
      reinit(const std::vector<dealii::IndexSet> &owned,
             const std::vector<dealii::IndexSet> &relevant,
             const MPI_Comm                       communicator);

      /**
       * Advance @p solution (ghosted) from @p time by @p time_step with
       * @p scheme: before each stage, @p old_solution becomes the stage's
       * start value and @p solution its first iterate; then @p solve_stage
       * solves the stage in @p solution.
       */
      SolveStatistics
      advance(const double                       time,
              const double                       time_step,
              const core::TimeParameters::Scheme scheme,
              BlockVector                       &solution,
              BlockVector                       &old_solution,
              const StageSolver                 &solve_stage);

      /** The next step starts without extrapolation (after the solution
       *  was carried to another mesh). */
      void
      forget_history();

      /** What advance() keeps from one step to the next. */
      struct History
      {
        BlockVector previous_solution;
        double      previous_time         = 0.;
        bool        has_previous_solution = false;
      };

      History
      history() const
      {
        return {previous_solution, previous_time, has_previous_solution};
      }

      /** Return to @p kept, which history() gave on the same DoFs. */
      void
      restore(const History &kept)
      {
        previous_solution     = kept.previous_solution;
        previous_time         = kept.previous_time;
        has_previous_solution = kept.has_previous_solution;
      }

      /** Checkpoint: the kept solution (this rank's locally owned
       *  entries) and its time. */
      void
      save(std::ostream &out) const;

      /** Reads what save() wrote. Throws std::runtime_error when the DoF
       *  layout differs. */
      void
      load(std::istream &in);

      std::size_t
      memory_consumption() const;

    private:
      /** The rate of change over the last full step, if it is to be
       *  used for a step from @p time of length @p time_step. */
      bool
      compute_rate(const BlockVector &solution,
                   const double       time,
                   const double       time_step,
                   BlockVector       &rate) const;
      /** The locally owned DoFs per block, read from the layout that
       *  reinit() gave previous_solution. */
      std::vector<dealii::IndexSet>
      owned_partitioning() const;

      BlockVector
      make_owned_vector() const;

      const InitialGuess initial_guess;
      /// the solution at the start of the previous time step (ghosted);
      /// its layout is the solver's
      BlockVector previous_solution;
      double      previous_time         = 0.;
      bool        has_previous_solution = false;
    };
  } // namespace fluid
} // namespace particulate

#endif
