// The CPU path of ContainmentEngine (private to the library).
#ifndef particulate_cuda_src_cpu_backend_h
#define particulate_cuda_src_cpu_backend_h

#include <particulate/cuda/detail/point_query.h>

#include <cstddef>

namespace particulate {
  namespace cuda {
    namespace detail {
      /**
       * Runs classify_point() over n points on `threads` std::threads
       * (contiguous ranges; 0 = all hardware threads). Outputs may be null.
       */
      void
      classify_cpu(const SceneView &scene,
                   const float     *xyz,
                   std::size_t      n,
                   int             *first_body,
                   float           *distance,
                   unsigned         threads);
    } // namespace detail
  }   // namespace cuda
} // namespace particulate

#endif
