#ifndef particulate_tests_fluid_test_utilities_h
#define particulate_tests_fluid_test_utilities_h

// Small helpers shared by the fluid tests: build a case from .prm text and
// report checks in a uniform way.

#include <particulate/core/input_file.h>
#include <particulate/core/mesh.h>
#include <particulate/fluid/flow_simulation.h>
#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace particulate {
  namespace testing {
    /** Parse @p text (the contents of a .prm) into case parameters. */
    inline fluid::FlowCaseParameters
    parameters_from_text(const std::string &text, const std::string &name)
    {
      const std::string file = name + ".prm";
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::ofstream(file) << text;
      MPI_Barrier(MPI_COMM_WORLD);
      dealii::ParameterHandler prm;
      fluid::FlowCaseParameters::declare(prm);
      core::parse_input_file(prm, file);
      fluid::FlowCaseParameters parameters;
      parameters.parse(prm);
      return parameters;
    }

    /** Path of a file in the source tree (tests run in the build tree). */
    inline std::string
    source_path(const std::string &relative)
    {
      const char *root = std::getenv("PARTICULATE_SOURCE_DIR");
      return std::string(root ? root : ".") + "/" + relative;
    }

    /** The library case prm/<name>/<name>.prm with @p overrides (.prm
     *  text) applied. */
    inline fluid::FlowCaseParameters
    library_case(const std::string &name, const std::string &overrides)
    {
      dealii::ParameterHandler prm;
      fluid::FlowCaseParameters::declare(prm);
      core::parse_input_file(prm,
                             source_path("prm/" + name + "/" + name + ".prm"));
      std::istringstream text(overrides);
      prm.parse_input(text, "overrides");
      fluid::FlowCaseParameters parameters;
      parameters.parse(prm);
      return parameters;
    }

    /** The data rows of a time series written by the program (a `.dat`:
     *  '#' comment lines, then whitespace-separated numbers), one vector per
     *  row. Words are converted with std::stod, so a "nan" in the file
     *  becomes a NaN here rather than cutting the row short. */
    inline std::vector<std::vector<double>>
    read_time_series(const std::string &file)
    {
      std::ifstream                    in(file);
      std::vector<std::vector<double>> rows;
      for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#')
          {
            std::istringstream  words(line);
            std::vector<double> row;
            for (std::string word; words >> word;)
              row.push_back(std::stod(word));
            rows.push_back(std::move(row));
          }
      return rows;
    }

    /** Column @p name of the time series @p file, found by the names of
     *  its header line ('# time x y ...'); throws if it has none such. */
    inline std::vector<double>
    read_column(const std::string &file, const std::string &name)
    {
      std::ifstream in(file);
      std::string   header;
      std::getline(in, header);
      std::istringstream names(header.substr(header.find('#') + 1));
      std::size_t        index = 0;
      for (std::string word; names >> word; ++index)
        if (word == name)
          {
            std::vector<double> column;
            for (const auto &row : read_time_series(file))
              column.push_back(row.at(index));
            return column;
          }
      throw std::runtime_error(file + " has no column '" + name + "'");
    }

    /** .prm text for solver tolerances under which runs that differ only
     *  in a preconditioner or the partitioning agree to about 1e-8: Newton
     *  to 1e-12, FGMRES and the inner pressure-Poisson CG to 1e-8. */
    inline std::string
    tight_solver_tolerances()
    {
      return "subsection Nonlinear solver\n set Absolute tolerance = 1e-12\n"
             " set Relative tolerance = 1e-12\nend\n"
             "subsection Linear solver\n set Relative tolerance = 1e-8\n"
             " set Pressure Poisson tolerance = 1e-8\nend\n";
    }

    /** Run the library case @p name with @p overrides on @p comm, output
     *  (no VTU) into @p output. */
    template <int dim = 2>
    fluid::FlowRunSummary
    run_library_case(const std::string &name,
                     const std::string &overrides,
                     MPI_Comm           comm,
                     const std::string &output)
    {
      auto parameters             = library_case(name, overrides);
      parameters.output.directory = output;
      parameters.output.write_vtu = false;
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        std::filesystem::create_directories(output);
      MPI_Barrier(comm);
      fluid::FlowSimulation<dim> simulation(parameters, name, comm);
      return simulation.run();
    }

    /** A case's parameters, mesh and flow solver with its DoFs set up, on
     *  MPI_COMM_WORLD and without timer output: the set-up of the tests
     *  that work on a flow field without running the case. It keeps the
     *  parameters, which the solver refers to. */
    template <int dim>
    struct CaseFlow
    {
      explicit CaseFlow(fluid::FlowCaseParameters case_parameters)
        : parameters(std::move(case_parameters))
        , tria(MPI_COMM_WORLD)
        , timer(MPI_COMM_WORLD,
                std::cout,
                dealii::TimerOutput::never,
                dealii::TimerOutput::wall_times)
        , flow(parameters.fluid, meshed(tria, parameters), timer)
      {
        flow.setup_dofs();
      }

      const fluid::FlowCaseParameters                        parameters;
      dealii::parallel::fullydistributed::Triangulation<dim> tria;
      dealii::TimerOutput                                    timer;
      fluid::NavierStokes<dim>                               flow;

    private:
      static dealii::parallel::fullydistributed::Triangulation<dim> &
      meshed(dealii::parallel::fullydistributed::Triangulation<dim> &tria,
             const fluid::FlowCaseParameters                        &parameters)
      {
        core::create_mesh(parameters.mesh, tria);
        return tria;
      }
    };

    /** Print one check and remember whether it failed. */
    class Checker
    {
    public:
      void
      check(const bool ok, const std::string &what)
      {
        if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::cout << (ok ? "  ok    " : "  FAIL  ") << what << std::endl;
        failed |= !ok;
      }
      /** |value - reference| <= tolerance * |reference| */
      void
      check_relative(const double       value,
                     const double       reference,
                     const double       tolerance,
                     const std::string &what)
      {
        const double error = std::abs(value - reference) / std::abs(reference);
        char         numbers[160];
        std::snprintf(numbers,
                      sizeof(numbers),
                      " = %.12g, reference %.12g, relative error %.2e "
                      "(allowed %.1e)",
                      value,
                      reference,
                      error,
                      tolerance);
        check(error <= tolerance, what + numbers);
      }
      int
      exit_code() const
      {
        return failed ? 1 : 0;
      }

    private:
      bool failed = false;
    };

    /** Relative tolerances of check_coefficients(). */
    struct CoefficientTolerances
    {
      double drag, lift, pressure_difference;
    };

    /** c_D, c_L and delta_p of @p value against @p reference; @p label
     *  names the comparison. */
    inline void
    check_coefficients(Checker                     &checker,
                       const fluid::FlowRunSummary &value,
                       const fluid::FlowRunSummary &reference,
                       const CoefficientTolerances &tolerances,
                       const std::string           &label)
    {
      checker.check_relative(value.drag_coefficient,
                             reference.drag_coefficient,
                             tolerances.drag,
                             label + ": c_D");
      checker.check_relative(value.lift_coefficient,
                             reference.lift_coefficient,
                             tolerances.lift,
                             label + ": c_L");
      checker.check_relative(value.pressure_difference,
                             reference.pressure_difference,
                             tolerances.pressure_difference,
                             label + ": delta_p");
    }
  } // namespace testing
} // namespace particulate

#endif
