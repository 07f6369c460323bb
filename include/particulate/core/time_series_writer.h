#ifndef particulate_core_time_series_writer_h
#define particulate_core_time_series_writer_h

#include <fstream>
#include <string>
#include <vector>

#include <mpi.h>

namespace particulate {
  namespace core {
    /**
     * A whitespace-separated time series (`.dat`) with a header line
     * `# time  c_D  c_L ...`, loadable with numpy.loadtxt. Rank 0 writes;
     * every call is flushed so that a run that stops early keeps all rows
     * written so far.
     */
    class TimeSeriesWriter
    {
    public:
      /**
       * @param filename Path of the file (its folder must exist).
       * @param columns Column names, without spaces.
       * @param comm Only rank 0 of @p comm writes.
       * @param append Continue an existing file (restart) instead of
       *   starting a new one.
       */
      TimeSeriesWriter(const std::string              &filename,
                       const std::vector<std::string> &columns,
                       MPI_Comm                        comm,
                       const bool                      append = false);

      /** Write one row; needs one value per column. */
      void
      write_row(const std::vector<double> &values);

      /** Write several rows, flushed once. */
      void
      write_rows(const std::vector<std::vector<double>> &rows);

      /** Write @p text as a comment line (`# text`, one line). */
      void
      write_note(const std::string &text);

      const std::vector<std::string> &
      column_names() const
      {
        return columns;
      }

    private:
      /** Throws unless @p values has one value per column. */
      void
      check_row(const std::vector<double> &values) const;

      /** One line of @p values, unflushed. */
      void
      put_row(const std::vector<double> &values);

      std::vector<std::string> columns;
      std::ofstream            out;
      bool                     writer;
    };
  } // namespace core
} // namespace particulate

#endif
