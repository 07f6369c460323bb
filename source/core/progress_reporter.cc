#include <particulate/core/progress_reporter.h>

#include <cmath>
#include <cstdio>

namespace particulate {
  namespace core {
    ProgressReporter::ProgressReporter(std::ostream &out,
                                       const double  start_time,
                                       const double  end_time)
      : out(out)
      , start_time(start_time)
      , end_time(end_time)
      , wall_start(std::chrono::steady_clock::now())
    {}

    double
    ProgressReporter::elapsed_seconds() const
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now()
                                           - wall_start)
        .count();
    }

    void
    ProgressReporter::report(const unsigned int step,
                             const double       time,
                             const double       time_step,
                             const std::string &solver_counts,
                             const double       resident_mib)
    {
      const double wall = elapsed_seconds();
      const double done = time - start_time;
      const double left
        = done > 0. ? wall * std::max(0., end_time - time) / done : 0.;
      char line[256];
      std::snprintf(line,
                    sizeof(line),
                    "step %6u  t = %-11.6g dt = %-10.4g %s  wall %s  left ~%s",
                    step,
                    time,
                    time_step,
                    solver_counts.c_str(),
                    format_duration(wall).c_str(),
                    format_duration(left).c_str());
      out << line;
      if (resident_mib >= 0.)
        out << "  memory " << static_cast<long>(std::lround(resident_mib))
            << " MiB";
      out << std::endl;
    }

    std::string
    format_duration(const double seconds)
    {
      char buffer[64];
      if (seconds < 60.)
        std::snprintf(buffer, sizeof(buffer), "%.1f s", seconds);
      else if (seconds < 3600.)
        std::snprintf(buffer,
                      sizeof(buffer),
                      "%d min %02d s",
                      int(seconds / 60.),
                      int(std::fmod(seconds, 60.)));
      else
        std::snprintf(buffer,
                      sizeof(buffer),
                      "%d h %02d min",
                      int(seconds / 3600.),
                      int(std::fmod(seconds, 3600.) / 60.));
      return buffer;
    }
  } // namespace core
} // namespace particulate
