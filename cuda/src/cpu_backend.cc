// CPU twin of the CUDA kernel: the same classify_point() (detail/
// point_query.h), compiled by the host compiler with -ffp-contract=off.
#include "cpu_backend.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace particulate {
  namespace cuda {
    namespace detail {
      namespace {
        void
        classify_range(const SceneView  &scene,
                       const float      *xyz,
                       const std::size_t begin,
                       const std::size_t end,
                       int              *first_body,
                       float            *distance)
        {
          const bool want_distance = distance != nullptr;
          for (std::size_t p = begin; p < end; ++p)
            {
              int   f;
              float d;
              classify_point(scene,
                             xyz[3 * p],
                             xyz[3 * p + 1],
                             xyz[3 * p + 2],
                             want_distance,
                             f,
                             d);
              if (first_body)
                first_body[p] = f;
              if (distance)
                distance[p] = d;
            }
        }
      } // namespace

      void
      classify_cpu(const SceneView  &scene,
                   const float      *xyz,
                   const std::size_t n,
                   int              *first_body,
                   float            *distance,
                   unsigned          threads)
      {
        if (threads == 0)
          threads = std::max(1u, std::thread::hardware_concurrency());
        // Below a few thousand points per thread, spawning costs more than it
        // saves.
        const std::size_t min_per_thread = 4096;
        threads                          = static_cast<unsigned>(
          std::min<std::size_t>(threads,
                                std::max<std::size_t>(1, n / min_per_thread)));
        if (threads <= 1)
          {
            classify_range(scene, xyz, 0, n, first_body, distance);
            return;
          }
        std::vector<std::thread> pool;
        pool.reserve(threads);
        for (unsigned t = 0; t < threads; ++t)
          {
            const std::size_t begin = n * t / threads;
            const std::size_t end   = n * (t + 1) / threads;
            pool.emplace_back(classify_range,
                              std::cref(scene),
                              xyz,
                              begin,
                              end,
                              first_body,
                              distance);
          }
        for (std::thread &t : pool)
          t.join();
      }
    } // namespace detail
  }   // namespace cuda
} // namespace particulate
