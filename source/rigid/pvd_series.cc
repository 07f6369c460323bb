#include <particulate/rigid/pvd_series.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace particulate {
  namespace rigid {
    PvdSeries::PvdSeries(std::string prefix)
      : prefix(std::move(prefix))
    {}



    std::string
    PvdSeries::next_file(const std::string &extension) const
    {
      char number[16];
      std::snprintf(number, sizeof number, "%05zu", series.size());
      return prefix + "_" + number + "." + extension;
    }



    namespace {
      const char *const pvd_end = "  </Collection>\n</VTKFile>\n";

      void
      write_entry(std::ostream                         &out,
                  const std::pair<double, std::string> &entry)
      {
        out << std::setprecision(12) << "    <DataSet timestep=\""
            << entry.first << "\" group=\"\" part=\"0\" file=\"" << entry.second
            << "\"/>\n";
      }
    } // namespace



    void
    PvdSeries::add(const double time, const std::string &file)
    {
      // The collection references the pieces by their name relative to it.
      const auto slash = file.find_last_of('/');
      series.emplace_back(time,
                          slash == std::string::npos ? file :
                                                       file.substr(slash + 1));
      if (!append_last_entry())
        rewrite();
    }



    bool
    PvdSeries::append_last_entry()
    {
      // Only a file this object wrote and that is still as it left it: then
      // the new entry replaces its closing tags, and a long series costs
      // the same per piece as a short one.
      const std::string name = prefix + ".pvd";
      std::error_code   error;
      if (series.size() < 2 || file_bytes == 0
          || std::filesystem::file_size(name, error) != file_bytes || error)
        return false;
      std::fstream pvd(name, std::ios::in | std::ios::out | std::ios::binary);
      const std::streamoff end_length = std::strlen(pvd_end);
      pvd.seekp(std::streamoff(file_bytes) - end_length);
      write_entry(pvd, series.back());
      pvd << pvd_end;
      const std::streamoff size = pvd.tellp();
      pvd.close();
      if (!pvd)
        return false;
      file_bytes = std::uintmax_t(size);
      return true;
    }



    void
    PvdSeries::rewrite()
    {
      const std::string name = prefix + ".pvd";
      std::ofstream     pvd(name, std::ios::binary);
      if (!pvd)
        throw std::runtime_error("rigid::PvdSeries: cannot write '" + name
                                 + "'; does the folder exist?");
      pvd << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"Collection\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n"
          << "  <Collection>\n";
      for (const auto &s : series)
        write_entry(pvd, s);
      pvd << pvd_end;
      const std::streamoff size = pvd.tellp();
      pvd.close();
      if (!pvd)
        throw std::runtime_error("rigid::PvdSeries: writing '" + name
                                 + "' failed; is the disk full?");
      file_bytes = std::uintmax_t(size);
    }
  } // namespace rigid
} // namespace particulate
