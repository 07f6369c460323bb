#include <particulate/core/checkpoint.h>
#include <particulate/core/parameter_text.h>

#include <deal.II/base/mpi.h>

#include <boost/crc.hpp>

#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

namespace particulate {
  namespace core {
    namespace {
      namespace fs = std::filesystem;

      const std::string magic = "PARTICULATE-CHECKPOINT";

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

      std::uint32_t
      crc32_of(const std::string &data)
      {
        boost::crc_32_type crc;
        crc.process_bytes(data.data(), data.size());
        return crc.checksum();
      }

      /** What a rank file says about itself before its data. */
      struct RankFileHeader
      {
        unsigned int  format_version;
        unsigned int  n_ranks;
        unsigned int  rank;
        unsigned long data_size;
        std::uint32_t data_crc;
      };

      void
      write_header(std::ostream &out, const RankFileHeader &header)
      {
        write_binary_string(out, magic);
        write_binary(out, header.format_version);
        write_binary(out, header.n_ranks);
        write_binary(out, header.rank);
        write_binary(out, header.data_size);
        write_binary(out, header.data_crc);
      }

      /** The header of @p in; throws if it is not a checkpoint of this
       *  format version. Files of format 1 carried their version in the
       *  magic string. */
      RankFileHeader
      read_header(std::istream &in)
      {
        const auto length = read_binary<unsigned long>(in);
        if (length != magic.size() && length != magic.size() + 2)
          throw std::runtime_error("it is not a Particulate checkpoint");
        std::string found(length, ' ');
        in.read(found.data(), length);
        RankFileHeader header{};
        if (found == magic)
          header.format_version = read_binary<unsigned int>(in);
        else if (found == magic + "-1")
          header.format_version = 1;
        else
          throw std::runtime_error("it is not a Particulate checkpoint");
        if (header.format_version != checkpoint_format_version)
          throw std::runtime_error(
            "it has checkpoint format " + std::to_string(header.format_version)
            + " and this version of Particulate reads format "
            + std::to_string(checkpoint_format_version)
            + ": rerun the case from its start, or restart it with the "
              "version that wrote the checkpoint");
        header.n_ranks   = read_binary<unsigned int>(in);
        header.rank      = read_binary<unsigned int>(in);
        header.data_size = read_binary<unsigned long>(in);
        header.data_crc  = read_binary<std::uint32_t>(in);
        return header;
      }

      /**
       * The data of the rank file @p path after checking its header
       * against this run (@p n_ranks, @p rank), its length and its
       * checksum; throws a reason otherwise.
       */
      std::string
      read_verified_data(const std::string &path,
                         const unsigned int n_ranks,
                         const unsigned int rank)
      {
        std::ifstream in(path, std::ios::binary);
        if (!in)
          throw std::runtime_error("the file cannot be opened");
        const RankFileHeader header = read_header(in);
        if (header.n_ranks != n_ranks)
          throw std::runtime_error(
            "it was written by " + std::to_string(header.n_ranks)
            + " MPI rank(s), and this run has " + std::to_string(n_ranks)
            + "; restart with mpirun -np " + std::to_string(header.n_ranks));
        if (header.rank != rank)
          throw std::runtime_error("the rank files are mixed up");
        std::string data(header.data_size, '\0');
        in.read(data.data(), data.size());
        if (!in || in.peek() != std::ifstream::traits_type::eof())
          throw std::runtime_error(
            "the file is not as long as its header says (truncated or "
            "damaged)");
        if (crc32_of(data) != header.data_crc)
          throw std::runtime_error(
            "its data do not match their checksum (the file is corrupted)");
        return data;
      }

      /** Forces what was written to @p path (a file or a folder) onto the
       *  disk. */
      void
      flush_to_disk(const std::string &path)
      {
        const int fd = ::open(path.c_str(), O_RDONLY);
        if (fd >= 0)
          {
            ::fsync(fd);
            ::close(fd);
          }
      }

      /**
       * Fault injection for the regression test of a save cut off half-way:
       * with PARTICULATE_KILL_DURING_CHECKPOINT=N in the environment, rank 0
       * kills itself (SIGKILL) in the N-th save of the process, after
       * writing half of its data.
       */
      void
      kill_if_requested(const unsigned int rank)
      {
        static unsigned int n_saves = 0;
        ++n_saves;
        const char *requested
          = std::getenv("PARTICULATE_KILL_DURING_CHECKPOINT");
        if (rank == 0 && requested != nullptr
            && std::to_string(n_saves) == requested)
          ::raise(SIGKILL);
      }

      /**
       * Writes a rank file, flushes it to the disk and reads it back
       * against its checksum. Whether all of that succeeded.
       */
      bool
      write_verified_rank_file(const std::string    &path,
                               const RankFileHeader &header,
                               const std::string    &data)
      {
        {
          std::ofstream out(path, std::ios::binary);
          if (!out)
            return false;
          write_header(out, header);
          const std::size_t half = data.size() / 2;
          out.write(data.data(), half);
          out.flush();
          kill_if_requested(header.rank);
          out.write(data.data() + half, data.size() - half);
          out.flush();
          if (!out)
            return false;
        }
        flush_to_disk(path);
        try
          {
            read_verified_data(path, header.n_ranks, header.rank);
            return true;
          }
        catch (const std::exception &)
          {
            return false;
          }
      }
    } // namespace



    void
    CheckpointParameters::declare(dealii::ParameterHandler &prm)
    {
      const CheckpointParameters defaults;
      namespace Patterns = dealii::Patterns;
      prm.enter_subsection("Checkpoint");
      prm.declare_entry(
        "Step interval",
        std::to_string(defaults.step_interval),
        Patterns::Integer(0),
        "Save the whole state of a particulate flow run (fluid solution, "
        "bodies, contact cache, output series) into "
        "'<Directory>/checkpoint/' every this many time steps (0: never by "
        "step count). 'particulate --restart CASE.prm' continues from it, "
        "on the same number of MPI ranks, exactly as the uninterrupted run "
        "would have continued.");
      prm.declare_entry("Wall-time interval",
                        number_text(defaults.wall_minutes),
                        Patterns::Double(0.),
                        "Also save once this many minutes of wall-clock "
                        "time have passed since the last save (0: never by "
                        "wall time), at the next step that is a multiple of "
                        "10. Long runs that may be cut off use it. Those "
                        "steps rebuild the solvers' preconditioners whether "
                        "or not a checkpoint is written, as a restart from "
                        "one does: the run's numbers depend neither on the "
                        "clock nor on a restart.");
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

      std::ostringstream stream;
      write_rank_data(stream);
      const std::string    data = stream.str();
      const RankFileHeader header{checkpoint_format_version,
                                  n_ranks,
                                  rank,
                                  data.size(),
                                  crc32_of(data)};
      const bool           written
        = write_verified_rank_file(rank_file(fresh, rank), header, data);
      if (!on_all_ranks(written, communicator))
        throw std::runtime_error(
          "Cannot write the checkpoint into '" + fresh
          + "' (disk full or not writable?): a rank file could not "
            "be written or did not read back intact. "
            "The previous checkpoint is kept.");
      if (rank == 0)
        {
          std::ofstream info(fresh + "/info.txt");
          info << std::setprecision(17) << "time " << time << "\nstep " << step
               << "\nranks " << n_ranks << "\n";
          info.close();
          flush_to_disk(fresh);
          // swap: the old checkpoint goes only after the new one is in
          // place (a checkpoint.old left by a save cut off in its swap, with
          // no checkpoint/ beside it, is the complete one until then)
          if (fs::exists(directory()))
            {
              fs::remove_all(stale);
              fs::rename(directory(), stale);
            }
          fs::rename(fresh, directory());
          flush_to_disk(output_directory);
          fs::remove_all(stale);
        }
      MPI_Barrier(communicator);
    }



    std::string
    Checkpoint::complete_directory() const
    {
      const unsigned int rank
        = dealii::Utilities::MPI::this_mpi_process(communicator);
      for (const std::string &folder : {directory(), directory() + ".old"})
        if (on_all_ranks(fs::exists(rank_file(folder, rank)), communicator))
          return folder;
      return "";
    }



    bool
    Checkpoint::exists() const
    {
      return !complete_directory().empty();
    }



    void
    Checkpoint::load(
      const std::function<void(std::istream &)> &read_rank_data) const
    {
      const unsigned int rank
        = dealii::Utilities::MPI::this_mpi_process(communicator);
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(communicator);
      const std::string folder = complete_directory();
      if (folder.empty())
        throw std::runtime_error(
          "--restart: there is no complete checkpoint in '" + directory()
          + "'. Set 'Step interval' or 'Wall-time interval' in subsection "
            "'Checkpoint' and run the case without --restart first.");

      // every rank's file is verified before any rank reads its state:
      // the reading is collective
      std::string data, problem;
      try
        {
          data = read_verified_data(rank_file(folder, rank), n_ranks, rank);
        }
      catch (const std::exception &e)
        {
          problem = "rank-" + std::to_string(rank) + ".bin: " + e.what();
        }
      for (const std::string &p :
           dealii::Utilities::MPI::all_gather(communicator, problem))
        if (!p.empty())
          throw std::runtime_error("Cannot restart from '" + folder + "': " + p
                                   + ".");

      std::istringstream in(data);
      try
        {
          read_rank_data(in);
          if (in.peek() != std::istringstream::traits_type::eof())
            throw std::runtime_error(
              "it holds more data than this version of Particulate reads");
        }
      catch (const std::exception &e)
        {
          throw std::runtime_error("Cannot restart from '" + folder
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
      const double       eps       = 1e-12 * std::max(1., std::abs(time));
      bool               in_header = true;
      while (std::getline(in, line))
        {
          const bool note = !line.empty() && line[0] == '#';
          if (note && !in_header)
            continue; // e.g. why a run stopped: the restart goes on
          if (!note)
            {
              in_header = false;
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
