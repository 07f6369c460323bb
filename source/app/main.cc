// The `particulate` executable: parse the command line and the .prm file,
// then hand over to the simulation the file asks for.

#include <particulate/core/input_file.h>
#include <particulate/fbm/case_file.h>
#include <particulate/fbm/particulate_flow_simulation.h>
#include <particulate/fbm/rigid_bodies_simulation.h>
#include <particulate/fluid/flow_simulation.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>

namespace {
  using namespace particulate;

  void
  print_usage(std::ostream &out)
  {
    out << "Usage:\n"
           "  particulate CASE.prm               run a case (also under "
           "mpirun -np N)\n"
           "  particulate --validate CASE.prm    check a parameter file and "
           "exit\n"
           "  particulate --restart CASE.prm     continue a particulate flow "
           "run from the\n"
           "                                     checkpoint in its output "
           "folder (subsection\n"
           "                                     Checkpoint; same number of "
           "ranks)\n"
           "  particulate --print-parameters     list every parameter with "
           "its documentation,\n"
           "                                     default and valid values\n"
           "  particulate --print-parameters=markdown   the same as the "
           "Markdown reference\n"
           "                                            "
           "(doc/user/parameters.md)\n"
           "  particulate --help                 this text\n\n"
           "Cases live in prm/<case>/<case>.prm; see README.md and "
           "doc/user/parameters.md.\n";
  }

  template <int dim>
  void
  run_case(const fbm::ParticulateFlowParameters &parameters,
           const std::string                    &filename,
           MPI_Comm                              comm)
  {
    switch (parameters.flow.simulation.type)
      {
        case core::SimulationParameters::Type::particulate_flow:
          {
            fbm::ParticulateFlowSimulation<dim> simulation(parameters,
                                                           filename,
                                                           comm);
            simulation.run();
            return;
          }
        case core::SimulationParameters::Type::rigid_bodies:
          {
            fbm::RigidBodiesSimulation<dim> simulation(parameters,
                                                       filename,
                                                       comm);
            simulation.run();
            return;
          }
        case core::SimulationParameters::Type::fluid:
          break;
      }
    fluid::FlowSimulation<dim> simulation(parameters.flow, filename, comm);
    simulation.run();
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;

  std::vector<std::string> args(argv + 1, argv + argc);
  // While the case is read and checked every rank does the same work on the
  // same file and fails alike: one message (from rank 0) and a plain exit
  // then, instead of one copy per rank and MPI_Abort's banner.
  bool reading_input = true;
  try
    {
      if (args.empty() || args[0] == "--help" || args[0] == "-h")
        {
          if (root)
            print_usage(std::cout);
          return args.empty() ? 1 : 0;
        }
      if (args[0].rfind("--print-parameters", 0) == 0)
        {
          dealii::ParameterHandler prm;
          fbm::ParticulateFlowParameters::declare(
            prm,
            fbm::ParticleSetLayout::documentation());
          if (args[0] == "--print-parameters=markdown")
            {
              if (root)
                core::write_parameter_reference(prm, std::cout);
              return 0;
            }
          if (args[0] == "--print-parameters"
              || args[0] == "--print-parameters=prm")
            {
              if (root)
                core::write_parameter_listing(prm, std::cout);
              return 0;
            }
        }

      const bool        validate_only = args[0] == "--validate";
      const bool        restart       = args[0] == "--restart";
      const bool        with_option   = validate_only || restart;
      const std::string filename
        = with_option && args.size() > 1 ? args[1] : args[0];
      if (filename.rfind("--", 0) == 0 || (with_option && args.size() < 2))
        {
          if (root)
            {
              std::cerr << "particulate: unknown option or missing file '"
                        << filename << "'.\n\n";
              print_usage(std::cerr);
            }
          return 1;
        }

      dealii::ParameterHandler       prm;
      fbm::ParticulateFlowParameters all = fbm::read_case_file(prm, filename);
      all.restart                        = restart;
      if (restart
          && all.flow.simulation.type
               != core::SimulationParameters::Type::particulate_flow)
        throw std::runtime_error(filename
                                 + ": --restart continues 'particulate flow' "
                                   "runs; this case is a 'fluid' run.");
      const fluid::FlowCaseParameters &parameters = all.flow;
      const unsigned int               dim = parameters.simulation.dimension;
      fbm::check_case_against_mesh(all, filename, comm);
      reading_input = false;
      if (validate_only)
        {
          if (root)
            std::cout << filename << ": OK" << std::endl;
          return 0;
        }

      const std::string &dir = parameters.output.directory;
      if (root)
        {
          std::filesystem::create_directories(dir);
          std::ofstream used(dir + "/used_parameters.prm");
          core::write_parameter_listing(prm, used);
          std::cout
            << "Particulate: running " << filename << " (" << dim << "D) on "
            << dealii::Utilities::MPI::n_mpi_processes(comm)
            << " rank(s)\nOutput folder: "
            << std::filesystem::absolute(dir).lexically_normal().string()
            << std::endl;
        }
      MPI_Barrier(comm);
      if (dim == 2)
        run_case<2>(all, filename, comm);
      else
        run_case<3>(all, filename, comm);
    }
  catch (const std::bad_alloc &)
    {
      std::cerr
        << "\nparticulate: error: out of memory ("
        << (reading_input ? "while the case was read and checked" :
                            "during the run")
        << "): a rank could not allocate what the case needs. Use a "
           "coarser mesh or fewer particles, or fewer ranks per machine."
        << std::endl;
      if (!reading_input && dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
        MPI_Abort(comm, 1);
      return 1;
    }
  catch (const std::exception &e)
    {
      if (reading_input)
        {
          if (root)
            std::cerr << "\nparticulate: error: " << e.what() << std::endl;
          return 1;
        }
      std::cerr << "\nparticulate: error: " << e.what() << std::endl;
      // a rank that fails alone must not leave the others waiting
      if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
        MPI_Abort(comm, 1);
      return 1;
    }
  return 0;
}
