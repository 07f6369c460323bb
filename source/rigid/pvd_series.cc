#include <particulate/rigid/pvd_series.h>

#include <cstdio>
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



    void
    PvdSeries::add(const double time, const std::string &file)
    {
      // The collection references the pieces by their name relative to it.
      const auto slash = file.find_last_of('/');
      series.emplace_back(time,
                          slash == std::string::npos ? file :
                                                       file.substr(slash + 1));
      std::ofstream pvd(prefix + ".pvd");
      if (!pvd)
        throw std::runtime_error("rigid::PvdSeries: cannot write '" + prefix
                                 + ".pvd'; does the folder exist?");
      pvd
        << std::setprecision(12) << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
      for (const auto &s : series)
        pvd << "    <DataSet timestep=\"" << s.first
            << "\" group=\"\" part=\"0\" file=\"" << s.second << "\"/>\n";
      pvd << "  </Collection>\n</VTKFile>\n";
    }
  } // namespace rigid
} // namespace particulate
