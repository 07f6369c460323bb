#include <particulate/core/checkpoint.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace particulate {
  namespace core {
    namespace {
      namespace fs = std::filesystem;

      const std::string magic = "PARTICULATE-CHECKPOINT-1";

      /** Whether @p value holds on every rank. */
      bool
      on_all_ranks(const bool value, MPI_Comm comm)
      {
        return dealii::Utilities::MPI::min(value ? 1 : 0, comm) == 1;
      }

      std::string
      rank_file(const std::string &folder, const unsigned int rank)
      {
        return folder + "/rank-" + std::to_string(rank) + ".bin";
      }
    } // namespace



    void
    CheckpointParameters::declare(dealii::ParameterHandler &prm)
    {
      namespace Patterns = dealii::Patterns;
      prm.enter_subsection("Checkpoint");
      prm.declare_entry(
        "Step interval",
        "0",
        Patterns::Integer(0),
        "Save the whole state of a particulate flow run (fluid solution, "
        "bodies, contact cache, output series) into "
        "'<Directory>/checkpoint/' every this many time steps (0: never by "
        "step count). 'particulate --restart CASE.prm' continues from it, "
        "on the same number of MPI ranks, exactly as the uninterrupted run "
        "would have continued.");
      prm.declare_entry("Wall-time interval",
                        "0",
                        Patterns::Double(0.),
                        "Also save whenever this many minutes of wall-clock "
                        "time have passed since the last save (0: never by "
                        "wall time). Long runs that may be cut off use it.");
      prm.leave_subsection();
    }



    void
    CheckpointParameters::parse(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpoint");
      step_interval = prm.get_integer("Step interval");
      wall_minutes  = prm.get_double("Wall-time interval");
      prm.leave_subsection();
    }



    Checkpoint::Checkpoint(const std::string &output_directory, MPI_Comm comm)
      : output_directory(output_directory)
      , communicator(comm)
    {}



    std::string
    Checkpoint::directory() const
    {
      return output_directory + "/checkpoint";
    }



    void
    Checkpoint::save(const std::function<void(std::ostream &)> &write_rank_data,
                     const double                               time,
                     const unsigned long                        step) const
    {
      const unsigned int rank
        = dealii::Utilities::MPI::this_mpi_process(communicator);
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(communicator);
      const std::string fresh = directory() + ".new",
                        stale = directory() + ".old";
      if (rank == 0)
        {
          fs::remove_all(fresh);
          fs::create_directories(fresh);
        }
      MPI_Barrier(communicator);

      bool written = false;
      {
        std::ofstream out(rank_file(fresh, rank), std::ios::binary);
        if (out)
          {
            write_binary_string(out, magic);
            write_binary<unsigned int>(out, n_ranks);
            write_binary<unsigned int>(out, rank);
            write_rank_data(out);
            out.flush();
            written = bool(out);
          }
      }
      if (!on_all_ranks(written, communicator))
        throw std::runtime_error("Cannot write the checkpoint into '" + fresh
                                 + "' (disk full or not writable?). The "
                                   "previous checkpoint is kept.");
      if (rank == 0)
        {
          std::ofstream info(fresh + "/info.txt");
          info << std::setprecision(17) << "time " << time << "\nstep " << step
               << "\nranks " << n_ranks << "\n";
          info.close();
          // swap: the old checkpoint goes only after the new one is in place
          fs::remove_all(stale);
          if (fs::exists(directory()))
            fs::rename(directory(), stale);
          fs::rename(fresh, directory());
          fs::remove_all(stale);
        }
      MPI_Barrier(communicator);
    }



    bool
    Checkpoint::exists() const
    {
      const unsigned int rank
        = dealii::Utilities::MPI::this_mpi_process(communicator);
      return on_all_ranks(fs::exists(rank_file(directory(), rank)),
                          communicator);
    }



    void
    Checkpoint::load(
      const std::function<void(std::istream &)> &read_rank_data) const
    {
      const unsigned int rank
        = dealii::Utilities::MPI::this_mpi_process(communicator);
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(communicator);
      if (!exists())
        throw std::runtime_error(
          "--restart: there is no complete checkpoint in '" + directory()
          + "'. Set 'Step interval' or 'Wall-time interval' in subsection "
            "'Checkpoint' and run the case without --restart first.");
      std::ifstream in(rank_file(directory(), rank), std::ios::binary);
      try
        {
          if (read_binary_string(in) != magic)
            throw std::runtime_error("it is not a Particulate checkpoint");
          const auto saved_ranks = read_binary<unsigned int>(in);
          if (saved_ranks != n_ranks)
            throw std::runtime_error(
              "it was written by " + std::to_string(saved_ranks)
              + " MPI rank(s), and this run has " + std::to_string(n_ranks)
              + "; restart with mpirun -np " + std::to_string(saved_ranks));
          if (read_binary<unsigned int>(in) != rank)
            throw std::runtime_error("the rank files are mixed up");
          read_rank_data(in);
        }
      catch (const std::exception &e)
        {
          throw std::runtime_error("Cannot restart from '" + directory()
                                   + "': " + e.what() + ".");
        }
    }



    void
    write_binary_string(std::ostream &out, const std::string &text)
    {
      write_binary<unsigned long>(out, text.size());
      out.write(text.data(), text.size());
    }



    std::string
    read_binary_string(std::istream &in)
    {
      const auto n = read_binary<unsigned long>(in);
      if (n > (1ul << 20))
        throw std::runtime_error("the checkpoint file is damaged");
      std::string text(n, ' ');
      in.read(text.data(), n);
      if (!in)
        throw std::runtime_error("the checkpoint file ends early");
      return text;
    }



    void
    write_binary_series(
      std::ostream                                      &out,
      const std::vector<std::pair<double, std::string>> &series)
    {
      write_binary<unsigned long>(out, series.size());
      for (const auto &[time, file] : series)
        {
          write_binary(out, time);
          write_binary_string(out, file);
        }
    }



    std::vector<std::pair<double, std::string>>
    read_binary_series(std::istream &in)
    {
      std::vector<std::pair<double, std::string>> series(
        read_binary<unsigned long>(in));
      for (auto &[time, file] : series)
        {
          time = read_binary<double>(in);
          file = read_binary_string(in);
        }
      return series;
    }



    void
    truncate_time_series(const std::string &filename, const double time)
    {
      std::ifstream in(filename);
      if (!in)
        throw std::runtime_error(
          "Cannot restart the time series '" + filename
          + "': the file is missing. Restart in the output folder of the "
            "run that wrote the checkpoint.");
      std::ostringstream kept;
      std::string        line;
      const double       eps = 1e-12 * std::max(1., std::abs(time));
      while (std::getline(in, line))
        {
          if (!line.empty() && line[0] != '#')
            {
              std::istringstream row(line);
              double             t = 0.;
              if (!(row >> t) || t > time + eps)
                continue;
            }
          kept << line << '\n';
        }
      in.close();
      std::ofstream out(filename, std::ios::trunc);
      out << kept.str();
    }
  } // namespace core
} // namespace particulate
