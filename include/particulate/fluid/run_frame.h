#ifndef particulate_fluid_run_frame_h
#define particulate_fluid_run_frame_h

#include <particulate/core/progress_reporter.h>
#include <particulate/fluid/flow_simulation.h>
#include <particulate/fluid/navier_stokes.h>
#include <particulate/fluid/run_profile.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <memory>
#include <string>
#include <vector>

#include <mpi.h>

namespace particulate {
  namespace fluid {
    /**
     * What every run of a flow case holds and does around its solver, the
     * same for a pure flow (FlowSimulation) and a particulate flow
     * (fbm::ParticulateFlowSimulation): the rank-0 stream and the timers,
     * the mesh made from the case and checked against its boundary
     * conditions, the size line, the progress line, when a step ends the
     * run or writes fields, and the closing timer summary and run profile.
     */
    template <int dim>
    class RunFrame
    {
    public:
      /**
       * @param parameters the case
       * @param parameter_file its name, for messages
       * @param comm the run's communicator
       */
      RunFrame(const FlowCaseParameters &parameters,
               const std::string        &parameter_file,
               MPI_Comm                  comm);

      /**
       * Make the case's mesh (timed as "mesh") and check that every
       * boundary id of the conditions is on it.
       * @return the mesh's boundary ids
       */
      std::vector<dealii::types::boundary_id>
      create_mesh();

      /** "Mesh: <cells> cells, <n> DoFs (<u> velocity + <p> pressure) on
       *  <ranks> rank(s)". */
      std::string
      size_line(const NavierStokes<dim> &flow) const;

      /** Start the progress line at time @p start. */
      void
      start_progress(const double start);

      /** Report step @p step (printed by rank 0) with the solver's counts,
       *  @p more and the resident memory; collective. */
      void
      report_step(const unsigned int     step,
                  const double           time,
                  const double           time_step,
                  const SolveStatistics &statistics,
                  const std::string     &more = "") const;

      /** Whether @p time is the end time (to rounding). */
      bool
      at_end_time(const double time) const;

      /** Whether step @p step, ending at @p time, writes ParaView files:
       *  every 'Interval' steps, and the last. */
      bool
      fields_due(const unsigned int step, const double time) const;

      /** Wall seconds since start_progress(). */
      double
      elapsed_seconds() const;

      /** Print the timer summary and fill @p profile's timer and solver
       *  parts and its wall time; collective. */
      void
      finish(const NavierStokes<dim> &flow, RunProfile &profile) const;

      dealii::ConditionalOStream                             pcout;
      mutable dealii::TimerOutput                            timer;
      dealii::parallel::fullydistributed::Triangulation<dim> tria;

    private:
      const FlowCaseParameters               &case_parameters;
      const std::string                       parameter_file;
      MPI_Comm                                communicator;
      std::unique_ptr<core::ProgressReporter> progress;
    };
  } // namespace fluid
} // namespace particulate

#endif
