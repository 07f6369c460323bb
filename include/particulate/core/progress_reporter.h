#ifndef particulate_core_progress_reporter_h
#define particulate_core_progress_reporter_h

#include <chrono>
#include <ostream>
#include <string>

namespace particulate {
  namespace core {
    /**
     * One line per time step: step, time, dt, the solver's own counts (as a
     * preformatted string), wall time so far, an estimate of the time
     * left from the average cost per unit of simulated time, and the
     * resident memory (of the largest rank) where @p resident_mib is not
     * negative.
     */
    class ProgressReporter
    {
    public:
      ProgressReporter(std::ostream &out,
                       const double  start_time,
                       const double  end_time);

      void
      report(const unsigned int step,
             const double       time,
             const double       time_step,
             const std::string &solver_counts,
             const double       resident_mib = -1.);

      /** Wall-clock seconds since construction. */
      double
      elapsed_seconds() const;

    private:
      std::ostream                         &out;
      double                                start_time, end_time;
      std::chrono::steady_clock::time_point wall_start;
    };

    /** "1 h 02 min", "3 min 20 s", "12.3 s". */
    std::string
    format_duration(const double seconds);
  } // namespace core
} // namespace particulate

#endif
