// The CUDA path of ContainmentEngine (private to the library). This header is
// plain C++ (no CUDA types) so that containment_engine.cc, compiled by the
// host compiler, can drive it; the implementation is cuda_backend.cu.
#ifndef particulate_cuda_src_cuda_backend_h
#define particulate_cuda_src_cuda_backend_h

#include <particulate/cuda/containment_engine.h>
#include <particulate/cuda/detail/point_query.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "uniform_grids.h"

namespace particulate {
  namespace cuda {
    namespace detail {
      /** Number of CUDA devices visible, 0 when there is no driver or device.
       */
      int
      cuda_device_count();

      /**
       * Device memory, streams and kernels. Shapes live on the device from
       * their upload to the destruction of the backend; per-call data (body
       * table, broad-phase grid, points, results) lives in buffers that grow
       * as needed and are reused.
       */
      class CudaBackend
      {
      public:
        CudaBackend();
        ~CudaBackend();
        CudaBackend(const CudaBackend &) = delete;
        CudaBackend &
        operator=(const CudaBackend &)
          = delete;

        std::string
        device_name() const;

        /** Copies a distance map to the device; returns its device view. */
        ShapeView
        upload_map(const ShapeView &host_view, std::size_t n_values);

        /** Copies a sphere grid to the device; returns its device view. */
        ShapeView
        upload_spheres(const ShapeView &host_view, const SphereGrid &grid);

        /**
         * Classifies n points: uploads the scene, then streams the points
         * through in chunks on several CUDA streams so that the copies in,
         * the kernel and the copies out of different chunks overlap.
         */
        void
        classify(const SceneGrid &scene,
                 const float     *xyz,
                 std::size_t      n,
                 int             *first_body,
                 float           *distance);

        /** See ContainmentEngine::time_kernel(). */
        KernelTiming
        time_kernel(const SceneGrid &scene,
                    const float     *xyz,
                    std::size_t      n,
                    bool             with_distance,
                    int              single_launches,
                    int              batch,
                    int              batches);

        /** See ContainmentEngine::measure_copy_bandwidth(). */
        double
        measure_copy_bandwidth(std::size_t bytes);

        void
        pin(const void *ptr, std::size_t bytes);

        void
        unpin(const void *ptr);

      private:
        struct State;
        std::unique_ptr<State> state;
      };
    } // namespace detail
  }   // namespace cuda
} // namespace particulate

#endif
