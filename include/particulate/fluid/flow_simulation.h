#ifndef particulate_fluid_flow_simulation_h
#define particulate_fluid_flow_simulation_h

#include <particulate/core/mesh.h>
#include <particulate/core/simulation_parameters.h>
#include <particulate/fluid/fluid_parameters.h>
#include <particulate/fluid/run_profile.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <utility>

#include <mpi.h>

namespace particulate {
  namespace fluid {
    /** Everything a `Simulation / Type = fluid` case reads. */
    struct FlowCaseParameters
    {
      core::SimulationParameters simulation;
      core::TimeParameters       time;
      core::OutputParameters     output;
      core::MeshParameters       mesh;
      FluidParameters            fluid;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);
    };

    /** What a run measured last; used by tests and the final summary (and,
     *  by its RunProfile, the benchmarks). */
    struct FlowRunSummary : RunProfile
    {
      unsigned int  n_steps                 = 0;
      double        end_time                = 0.;
      double        drag_coefficient        = 0.; ///< surface integral
      double        lift_coefficient        = 0.;
      double        drag_coefficient_volume = 0.; ///< volume integral
      double        lift_coefficient_volume = 0.;
      double        pressure_difference     = 0.;
      double        kinetic_energy          = 0.;
      unsigned long n_dofs                  = 0;
      unsigned long n_cells                 = 0;
    };

    /**
     * The time loop of a pure flow case: mesh, solver, diagnostics every
     * step (the `.dat` time series), ParaView output every `Interval`
     * steps, a progress line per step and a timer summary at the end.
     */
    template <int dim>
    class FlowSimulation
    {
    public:
      /**
       * @param parameters Parsed parameters.
       * @param parameter_file Name of the `.prm`, for messages.
       * @param comm Communicator of the run.
       */
      FlowSimulation(const FlowCaseParameters &parameters,
                     const std::string        &parameter_file,
                     MPI_Comm                  comm);

      FlowRunSummary
      run();

      /**
       * @p inspector sees the flow solver at the end of run() (on every
       * rank; benchmarks time its matrix there).
       */
      void
      set_flow_inspector(
        std::function<void(const NavierStokes<dim> &)> inspector)
      {
        flow_inspector = std::move(inspector);
      }

    private:
      std::function<void(const NavierStokes<dim> &)> flow_inspector;
      const FlowCaseParameters                      &parameters;
      const std::string                              parameter_file;
      MPI_Comm                                       communicator;
    };
  } // namespace fluid
} // namespace particulate

#endif
