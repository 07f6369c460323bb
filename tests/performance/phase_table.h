#ifndef particulate_tests_performance_phase_table_h
#define particulate_tests_performance_phase_table_h

// The per-phase profile table the benchmarks print: one column per run,
// seconds per step of every timer section any run used.

#include <particulate/fluid/run_profile.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace particulate {
  namespace benchmarks {
    struct ProfiledRun
    {
      std::string              label;
      const fluid::RunProfile *profile;
      unsigned int             n_steps;
    };

    inline void
    print_phase_table(const std::vector<ProfiledRun> &runs)
    {
      std::printf("\nPer phase, seconds per step (slowest rank; nested "
                  "sections are part of the one above them):\n\n| phase |");
      for (const auto &run : runs)
        std::printf(" %s |", run.label.c_str());
      std::printf("\n|---|");
      for (std::size_t i = 0; i < runs.size(); ++i)
        std::printf("---|");
      std::printf("\n");
      std::vector<std::string> names;
      for (const auto &run : runs)
        for (const auto &[name, seconds] : run.profile->phase_seconds)
          if (std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(name);
      for (const auto &name : names)
        {
          std::printf("| %s |", name.c_str());
          for (const auto &run : runs)
            std::printf(" %.4f |", run.profile->seconds(name) / run.n_steps);
          std::printf("\n");
        }
    }
  } // namespace benchmarks
} // namespace particulate

#endif
