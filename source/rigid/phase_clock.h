#ifndef particulate_rigid_phase_clock_h
#define particulate_rigid_phase_clock_h

// The wall clock behind the per-phase times of rigid::StepStatistics, shared
// by the general step (world.cc) and the sphere-only DEM (sphere_dem.cc).

#include <chrono>

namespace particulate {
  namespace rigid {
    namespace detail {
      using Clock = std::chrono::steady_clock;

      inline double
      seconds_since(const Clock::time_point &t0)
      {
        return std::chrono::duration<double>(Clock::now() - t0).count();
      }
    } // namespace detail
  }   // namespace rigid
} // namespace particulate

#endif
