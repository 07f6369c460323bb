// Shared by the fbm tests that compare whole runs: run a particulate-flow
// case into an output folder of its own, without the ParaView fields.
#ifndef particulate_tests_fbm_run_case_h
#define particulate_tests_fbm_run_case_h

#include <particulate/fbm/particulate_flow_simulation.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <string>

namespace particulate {
  namespace testing {
    /** Run @p parameters (named @p case_name in messages) on @p comm into
     *  @p output (created by rank 0), writing the time series only. */
    template <int dim>
    fbm::ParticulateFlowSummary
    run_without_fields(fbm::ParticulateFlowParameters parameters,
                       const std::string             &case_name,
                       const std::string             &output,
                       MPI_Comm                       comm)
    {
      parameters.flow.output.directory = output;
      parameters.flow.output.write_vtu = false;
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        std::filesystem::create_directories(output);
      MPI_Barrier(comm);
      fbm::ParticulateFlowSimulation<dim> simulation(parameters,
                                                     case_name,
                                                     comm);
      return simulation.run();
    }
  } // namespace testing
} // namespace particulate

#endif
