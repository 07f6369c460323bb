#ifndef particulate_core_checkpoint_h
#define particulate_core_checkpoint_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <istream>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <mpi.h>

namespace particulate {
  namespace core {
    /** Subsection `Checkpoint`: when a run saves its state. */
    struct CheckpointParameters
    {
      /// save every this many time steps (0: not by step count)
      unsigned int step_interval = 0;
      /// save when this many wall-clock minutes passed since the last save
      /// (0: not by wall time), at the next step that is a multiple of
      /// wall_time_step_multiple
      double wall_minutes = 0.;

      /**
       * The steps a wall-time checkpoint may fall on. A checkpoint rebuilds
       * the solvers' preconditioners, as a restart from it must; with
       * wall-time checkpoints these steps rebuild them whether or not one
       * is written, so that neither the clock nor a restart changes the
       * numbers. Every tenth step costs one rebuild in ten steps.
       */
      static constexpr unsigned int wall_time_step_multiple = 10;

      /** Whether @p step is one a wall-time checkpoint may fall on. */
      bool
      wall_time_step(const unsigned long step) const
      {
        return wall_minutes > 0. && step % wall_time_step_multiple == 0;
      }

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);

      bool
      enabled() const
      {
        return step_interval > 0 || wall_minutes > 0.;
      }
    };

    /**
     * Checkpoint files of a distributed run in `<output>/checkpoint/`: one
     * binary file per rank (`rank-<r>.bin`, the rank's part of the state)
     * and `info.txt` (time, step, number of ranks, for people).
     *
     * A rank file starts with a header: the magic string, the format
     * version (checkpoint_format_version), the number of ranks, the rank,
     * the size of the rank's data and its CRC-32; the data follow. A new
     * checkpoint is written into `checkpoint.new/`, each file flushed to
     * the disk and read back against its checksum, and swapped in only when
     * every rank's file has passed; a run cut off while saving keeps its
     * previous checkpoint (in `checkpoint.old/` if it was cut off between
     * the two renames of the swap, where load() finds it too). load()
     * verifies every header and checksum on every rank before any rank
     * reads its state, so a damaged file stops all ranks with the same
     * message instead of leaving some in a collective read.
     */
    class Checkpoint
    {
    public:
      /** @param output_directory The run's 'Directory' of 'Output'. */
      Checkpoint(const std::string &output_directory, MPI_Comm comm);

      /**
       * Collective. Calls @p write_rank_data with this rank's stream and
       * swaps the new checkpoint in. @p time and @p step go to info.txt.
       */
      void
      save(const std::function<void(std::ostream &)> &write_rank_data,
           const double                               time,
           const unsigned long                        step) const;

      /** Whether a complete checkpoint exists (collective). */
      bool
      exists() const;

      /**
       * Collective. Verifies this rank's file of the last checkpoint (its
       * header, that as many ranks wrote it as run now, its size and
       * checksum) on every rank, then hands its data to @p read_rank_data
       * and checks that it read them all. Throws std::runtime_error naming
       * the folder, the file and what to do.
       */
      void
      load(const std::function<void(std::istream &)> &read_rank_data) const;

      /** The folder of the current checkpoint. */
      std::string
      directory() const;

    private:
      /** directory(), or the previous checkpoint if a save was cut off
       *  between the renames of its swap. */
      std::string
      complete_directory() const;

      std::string output_directory;
      MPI_Comm    communicator;
    };

    /**
     * Version of the layout of the checkpoint's rank data. Raise it with
     * every change of what a run writes into a checkpoint: a restart from a
     * file of another version is refused, with both versions named.
     */
    constexpr unsigned int checkpoint_format_version = 2;

    /** Writes the bytes of a trivially copyable value. */
    template <typename T>
    void
    write_binary(std::ostream &out, const T &value)
    {
      out.write(reinterpret_cast<const char *>(&value), sizeof(T));
    }

    /** Reads what write_binary() wrote; throws on a short file. */
    template <typename T>
    T
    read_binary(std::istream &in)
    {
      T value;
      in.read(reinterpret_cast<char *>(&value), sizeof(T));
      if (!in)
        throw std::runtime_error(
          "the checkpoint file ends early (it is truncated or from another "
          "version of Particulate)");
      return value;
    }

    /** A vector as its length and its elements. */
    template <typename T>
    void
    write_binary_vector(std::ostream &out, const std::vector<T> &values)
    {
      write_binary<unsigned long>(out, values.size());
      for (const T &v : values)
        write_binary(out, v);
    }

    template <typename T>
    std::vector<T>
    read_binary_vector(std::istream &in)
    {
      std::vector<T> values(read_binary<unsigned long>(in));
      for (T &v : values)
        v = read_binary<T>(in);
      return values;
    }

    /** A string as its length and its characters. */
    void
    write_binary_string(std::ostream &out, const std::string &text);
    std::string
    read_binary_string(std::istream &in);

    /** The (time, file) list behind a .pvd series. */
    void
    write_binary_series(
      std::ostream                                      &out,
      const std::vector<std::pair<double, std::string>> &series);
    std::vector<std::pair<double, std::string>>
    read_binary_series(std::istream &in);

    /**
     * Restart of a time series: keeps the header and the rows of
     * @p filename whose first column (the time) is at most @p time, and
     * drops the rows a cut-off run wrote after its last checkpoint and the
     * comment lines after the header (the note of why a run stopped). Call
     * on one rank.
     */
    void
    truncate_time_series(const std::string &filename, const double time);
  } // namespace core
} // namespace particulate

#endif
