#include <particulate/core/time_series_writer.h>

#include <algorithm>
#include <iomanip>
#include <stdexcept>

namespace particulate {
  namespace core {
    TimeSeriesWriter::TimeSeriesWriter(const std::string              &filename,
                                       const std::vector<std::string> &columns,
                                       MPI_Comm                        comm,
                                       const bool                      append)
      : columns(columns)
    {
      int rank = 0;
      MPI_Comm_rank(comm, &rank);
      writer = rank == 0;
      if (!writer)
        return;
      out.open(filename, append ? std::ios::app : std::ios::trunc);
      if (!out)
        throw std::runtime_error("Cannot write the time series '" + filename
                                 + "'. Check that 'Directory' in subsection "
                                   "'Output' is writable.");
      if (!append)
        {
          out << "#";
          for (const auto &c : columns)
            out << ' ' << c;
          out << std::endl;
        }
      out << std::setprecision(12);
    }

    void
    TimeSeriesWriter::check_row(const std::vector<double> &values) const
    {
      if (values.size() != columns.size())
        throw std::logic_error("TimeSeriesWriter: row has "
                               + std::to_string(values.size()) + " values for "
                               + std::to_string(columns.size()) + " columns");
    }



    void
    TimeSeriesWriter::put_row(const std::vector<double> &values)
    {
      for (unsigned int i = 0; i < values.size(); ++i)
        out << (i > 0 ? " " : "") << values[i];
      out << '\n';
    }



    void
    TimeSeriesWriter::write_row(const std::vector<double> &values)
    {
      check_row(values);
      if (!writer)
        return;
      put_row(values);
      out.flush();
    }



    void
    TimeSeriesWriter::write_rows(const std::vector<std::vector<double>> &rows)
    {
      for (const auto &values : rows)
        check_row(values);
      if (!writer)
        return;
      for (const auto &values : rows)
        put_row(values);
      out.flush();
    }



    void
    TimeSeriesWriter::write_note(const std::string &text)
    {
      if (!writer)
        return;
      std::string line = text;
      std::replace(line.begin(), line.end(), '\n', ' ');
      out << "# " << line << std::endl;
    }
  } // namespace core
} // namespace particulate
