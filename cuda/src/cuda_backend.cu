// CUDA path of ContainmentEngine: device memory, streams and the
// classification kernel (thesis §5.4.3: one thread per mesh point).
//
// Arithmetic: the kernel calls detail::classify_point(), whose float
// operations are __fmul_rn/__fadd_rn/__fsub_rn intrinsics that nvcc never
// fuses into FMAs; the target is also compiled with -fmad=false so that no
// other expression can be contracted behind our back. The CPU twin computes
// the same sequence of rounded operations, so results agree bit for bit.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "cuda_backend.h"
#include <cuda_runtime.h>

namespace particulate {
  namespace cuda {
    namespace detail {
      namespace {
        /** Turns a failed CUDA call into an exception naming the call and the
         * place. */
        void
        check_cuda(const cudaError_t error,
                   const char       *what,
                   const char       *file,
                   const int         line)
        {
          if (error == cudaSuccess)
            return;
          std::ostringstream msg;
          msg << "particulate CUDA containment: " << what << " failed at "
              << file << ":" << line << " with " << cudaGetErrorName(error)
              << " (" << cudaGetErrorString(error) << ")";
          throw std::runtime_error(msg.str());
        }

#define PARTICULATE_CUDA_CHECK(call) \
  check_cuda((call), #call, __FILE__, __LINE__)

        /** 128 rather than 256: within a few per cent either way on an H200,
         * faster where points walk the broad-phase grid (100 and 1000
         * bodies), whose work per point is uneven. */
        constexpr int threads_per_block = 128;
        constexpr int n_streams         = 3;

        /** Device allocation that only grows; freed in the destructor. */
        struct DeviceBuffer
        {
          void       *ptr   = nullptr;
          std::size_t bytes = 0;

          void
          reserve(const std::size_t b)
          {
            if (b <= bytes)
              return;
            if (ptr != nullptr)
              PARTICULATE_CUDA_CHECK(cudaFree(ptr));
            ptr   = nullptr;
            bytes = 0;
            PARTICULATE_CUDA_CHECK(cudaMalloc(&ptr, b));
            bytes = b;
          }

          ~DeviceBuffer()
          {
            if (ptr != nullptr)
              cudaFree(ptr); // no throwing from a destructor
          }
        };

        /** Page-locked host staging buffer that only grows. */
        struct PinnedBuffer
        {
          void       *ptr   = nullptr;
          std::size_t bytes = 0;

          void
          reserve(const std::size_t b)
          {
            if (b <= bytes)
              return;
            if (ptr != nullptr)
              PARTICULATE_CUDA_CHECK(cudaFreeHost(ptr));
            ptr   = nullptr;
            bytes = 0;
            PARTICULATE_CUDA_CHECK(cudaMallocHost(&ptr, b));
            bytes = b;
          }

          ~PinnedBuffer()
          {
            if (ptr != nullptr)
              cudaFreeHost(ptr);
          }
        };

        std::size_t
        align_up(const std::size_t x, const std::size_t a = 256)
        {
          return (x + a - 1) / a * a;
        }

        /**
         * One thread per point (thesis §5.4.3); every output element of the
         * range is written. Measured on an H200 and kept simple: staging the
         * points through shared memory or shuffles with 16-byte loads,
         * copying body records with 16-byte loads, giving each thread 2 or 4
         * points, bricked or 8-corner map layouts, two or four sphere
         * entries per loop step, and persistent grids were all slower or no
         * faster. What bounds it is the L2 traffic of the
         * map gathers and the latency of dependent loads (cell, body, map),
         * not DRAM; see doc/performance.md, "CUDA containment".
         */
        __global__ void
        __launch_bounds__(threads_per_block)
          classify_kernel(const SceneView scene,
                          const float *__restrict__ xyz,
                          const int n,
                          int *__restrict__ first_body,
                          float *__restrict__ distance)
        {
          const int p = blockIdx.x * threads_per_block + threadIdx.x;
          if (p >= n)
            return;
          int   f;
          float d;
          // Points and results stream through once: load and store them
          // evict-first (.cs), so that the L1 and L2 keep the map samples,
          // sphere entries and body records that neighbouring points reuse.
          classify_point(scene,
                         __ldcs(xyz + 3 * p),
                         __ldcs(xyz + 3 * p + 1),
                         __ldcs(xyz + 3 * p + 2),
                         distance != nullptr,
                         f,
                         d);
          if (first_body != nullptr)
            __stcs(first_body + p, f);
          if (distance != nullptr)
            __stcs(distance + p, d);
        }

        void
        launch_classify(const SceneView  &scene,
                        const float      *d_xyz,
                        const std::size_t n,
                        int              *d_first,
                        float            *d_dist,
                        cudaStream_t      stream)
        {
          if (n == 0)
            return;
          if (n > static_cast<std::size_t>(std::numeric_limits<int>::max() / 4))
            throw std::invalid_argument(
              "particulate CUDA containment: a kernel launch covers at most 2^29 points");
          const unsigned blocks = static_cast<unsigned>(
            (n + threads_per_block - 1) / threads_per_block);
          classify_kernel<<<blocks, threads_per_block, 0, stream>>>(
            scene,
            d_xyz,
            static_cast<int>(n),
            d_first,
            d_dist);
          PARTICULATE_CUDA_CHECK(cudaGetLastError());
        }
      } // namespace

      int
      cuda_device_count()
      {
        int n = 0;
        if (cudaGetDeviceCount(&n) != cudaSuccess)
          {
            cudaGetLastError(); // clear the sticky "no device/driver" error
            return 0;
          }
        return n;
      }

      struct CudaBackend::State
      {
        int                 device = 0;
        cudaDeviceProp      prop;
        std::vector<void *> shape_memory;
        PinnedBuffer        scene_host;
        DeviceBuffer        scene_device;
        DeviceBuffer        xyz, first, dist;
        cudaStream_t        streams[n_streams] = {};
        cudaEvent_t         scene_ready        = nullptr;

        ~State()
        {
          for (void *p : shape_memory)
            cudaFree(p);
          for (cudaStream_t s : streams)
            if (s != nullptr)
              cudaStreamDestroy(s);
          if (scene_ready != nullptr)
            cudaEventDestroy(scene_ready);
        }

        /**
         * Packs body table and broad-phase grid into one pinned buffer,
         * copies it to the device on stream 0 and records scene_ready.
         * Returns the SceneView with device pointers.
         */
        SceneView
        upload_scene(const SceneGrid &g)
        {
          const std::size_t off_bodies = 0;
          const std::size_t off_cells
            = align_up(off_bodies + g.bodies.size() * sizeof(BodyView));
          const std::size_t off_ids
            = align_up(off_cells + g.cell_start.size() * sizeof(int));
          const std::size_t total = align_up(
            off_ids
            + std::max<std::size_t>(1, g.body_ids.size()) * sizeof(int));
          // The previous call synchronised its streams, so the staging
          // buffer is free to overwrite.
          scene_host.reserve(total);
          scene_device.reserve(total);
          char *h = static_cast<char *>(scene_host.ptr);
          std::memcpy(h + off_bodies,
                      g.bodies.data(),
                      g.bodies.size() * sizeof(BodyView));
          std::memcpy(h + off_cells,
                      g.cell_start.data(),
                      g.cell_start.size() * sizeof(int));
          std::memcpy(h + off_ids,
                      g.body_ids.data(),
                      g.body_ids.size() * sizeof(int));
          PARTICULATE_CUDA_CHECK(cudaMemcpyAsync(scene_device.ptr,
                                                 h,
                                                 total,
                                                 cudaMemcpyHostToDevice,
                                                 streams[0]));
          PARTICULATE_CUDA_CHECK(cudaEventRecord(scene_ready, streams[0]));

          const char     *d = static_cast<const char *>(scene_device.ptr);
          const SceneView v
            = make_scene_view(g,
                              reinterpret_cast<const BodyView *>(d
                                                                 + off_bodies),
                              reinterpret_cast<const int *>(d + off_cells),
                              reinterpret_cast<const int *>(d + off_ids));
          return v;
        }

        void *
        allocate_and_copy(const void *src, const std::size_t bytes)
        {
          void *p = nullptr;
          PARTICULATE_CUDA_CHECK(
            cudaMalloc(&p, std::max<std::size_t>(bytes, 16)));
          shape_memory.push_back(p);
          PARTICULATE_CUDA_CHECK(
            cudaMemcpy(p, src, bytes, cudaMemcpyHostToDevice));
          return p;
        }
      };

      CudaBackend::CudaBackend()
        : state(new State)
      {
        if (cuda_device_count() == 0)
          throw std::runtime_error(
            "particulate CUDA containment: no CUDA device is visible (check the driver, "
            "CUDA_VISIBLE_DEVICES, or choose the CPU backend)");
        PARTICULATE_CUDA_CHECK(cudaGetDevice(&state->device));
        PARTICULATE_CUDA_CHECK(
          cudaGetDeviceProperties(&state->prop, state->device));
        for (cudaStream_t &s : state->streams)
          PARTICULATE_CUDA_CHECK(
            cudaStreamCreateWithFlags(&s, cudaStreamNonBlocking));
        PARTICULATE_CUDA_CHECK(
          cudaEventCreateWithFlags(&state->scene_ready,
                                   cudaEventDisableTiming));
      }

      CudaBackend::~CudaBackend() = default;

      std::string
      CudaBackend::device_name() const
      {
        std::ostringstream s;
        s << state->prop.name << " (sm_" << state->prop.major
          << state->prop.minor << ", " << state->prop.multiProcessorCount
          << " SMs)";
        return s.str();
      }

      ShapeView
      CudaBackend::upload_map(const ShapeView  &host_view,
                              const std::size_t n_values)
      {
        // Regroup the samples by Quad: entry (i,j,k) holds the values at
        // (i,j), (i+1,j), (i,j+1), (i+1,j+1) of layer k (clamped at the far
        // faces, where no cell starts). Four times the memory, a quarter of
        // the loads.
        const int nx = host_view.n[0], ny = host_view.n[1], nz = host_view.n[2];
        std::vector<Quad> quads(n_values);
        const float      *v0 = host_view.values;
        for (int k = 0; k < nz; ++k)
          for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
              {
                const int i1       = std::min(i + 1, nx - 1),
                          j1       = std::min(j + 1, ny - 1);
                const size_t layer = std::size_t(nx) * ny * k;
                quads[i + std::size_t(nx) * j + layer]
                  = Quad{v0[i + std::size_t(nx) * j + layer],
                         v0[i1 + std::size_t(nx) * j + layer],
                         v0[i + std::size_t(nx) * j1 + layer],
                         v0[i1 + std::size_t(nx) * j1 + layer]};
              }
        ShapeView v = host_view;
        v.values    = nullptr;
        v.quads     = static_cast<const Quad *>(
          state->allocate_and_copy(quads.data(), n_values * sizeof(Quad)));
        return v;
      }

      ShapeView
      CudaBackend::upload_spheres(const ShapeView  &host_view,
                                  const SphereGrid &grid)
      {
        ShapeView v  = host_view;
        v.cell_start = static_cast<const int *>(
          state->allocate_and_copy(grid.cell_start.data(),
                                   grid.cell_start.size() * sizeof(int)));
        v.entries = static_cast<const SphereEntry *>(
          state->allocate_and_copy(grid.entries.data(),
                                   grid.entries.size() * sizeof(SphereEntry)));
        return v;
      }

      void
      CudaBackend::classify(const SceneGrid  &scene,
                            const float      *xyz,
                            const std::size_t n,
                            int              *first_body,
                            float            *distance)
      {
        if (n == 0)
          return;
        State &s = *state;
        s.xyz.reserve(3 * n * sizeof(float));
        if (first_body != nullptr)
          s.first.reserve(n * sizeof(int));
        if (distance != nullptr)
          s.dist.reserve(n * sizeof(float));
        const SceneView view = s.upload_scene(scene);
        for (cudaStream_t st : s.streams)
          PARTICULATE_CUDA_CHECK(cudaStreamWaitEvent(st, s.scene_ready, 0));

        float *d_xyz   = static_cast<float *>(s.xyz.ptr);
        int   *d_first = first_body ? static_cast<int *>(s.first.ptr) : nullptr;
        float *d_dist  = distance ? static_cast<float *>(s.dist.ptr) : nullptr;

        // Chunks of at least 128k points, at most 8 of them: enough to
        // overlap copy-in, kernel and copy-out, few enough that launch and
        // copy latencies stay small.
        const std::size_t chunk
          = std::max<std::size_t>(std::size_t(1) << 17,
                                  align_up((n + 7) / 8, threads_per_block));
        std::size_t c = 0;
        for (std::size_t off = 0; off < n; off += chunk, ++c)
          {
            const std::size_t  len = std::min(chunk, n - off);
            const cudaStream_t st  = s.streams[c % n_streams];
            PARTICULATE_CUDA_CHECK(cudaMemcpyAsync(d_xyz + 3 * off,
                                                   xyz + 3 * off,
                                                   3 * len * sizeof(float),
                                                   cudaMemcpyHostToDevice,
                                                   st));
            launch_classify(view,
                            d_xyz + 3 * off,
                            len,
                            d_first ? d_first + off : nullptr,
                            d_dist ? d_dist + off : nullptr,
                            st);
            if (first_body != nullptr)
              PARTICULATE_CUDA_CHECK(cudaMemcpyAsync(first_body + off,
                                                     d_first + off,
                                                     len * sizeof(int),
                                                     cudaMemcpyDeviceToHost,
                                                     st));
            if (distance != nullptr)
              PARTICULATE_CUDA_CHECK(cudaMemcpyAsync(distance + off,
                                                     d_dist + off,
                                                     len * sizeof(float),
                                                     cudaMemcpyDeviceToHost,
                                                     st));
          }
        for (cudaStream_t st : s.streams)
          PARTICULATE_CUDA_CHECK(cudaStreamSynchronize(st));
      }

      double
      CudaBackend::time_kernel(const SceneGrid  &scene,
                               const float      *xyz,
                               const std::size_t n,
                               const bool        with_distance,
                               const int         repetitions)
      {
        State &s = *state;
        if (n == 0)
          return 0.;
        s.xyz.reserve(3 * n * sizeof(float));
        s.first.reserve(n * sizeof(int));
        if (with_distance)
          s.dist.reserve(n * sizeof(float));
        const cudaStream_t st = s.streams[0];
        PARTICULATE_CUDA_CHECK(cudaMemcpyAsync(s.xyz.ptr,
                                               xyz,
                                               3 * n * sizeof(float),
                                               cudaMemcpyHostToDevice,
                                               st));
        const SceneView view = s.upload_scene(scene);

        cudaEvent_t start, stop;
        PARTICULATE_CUDA_CHECK(cudaEventCreate(&start));
        PARTICULATE_CUDA_CHECK(cudaEventCreate(&stop));
        double best = HUGE_VAL;
        try
          {
            for (int r = -1; r < std::max(1, repetitions);
                 ++r) // r = -1 warms up
              {
                PARTICULATE_CUDA_CHECK(cudaEventRecord(start, st));
                launch_classify(view,
                                static_cast<const float *>(s.xyz.ptr),
                                n,
                                static_cast<int *>(s.first.ptr),
                                with_distance ?
                                  static_cast<float *>(s.dist.ptr) :
                                  nullptr,
                                st);
                PARTICULATE_CUDA_CHECK(cudaEventRecord(stop, st));
                PARTICULATE_CUDA_CHECK(cudaEventSynchronize(stop));
                float ms = 0.f;
                PARTICULATE_CUDA_CHECK(cudaEventElapsedTime(&ms, start, stop));
                if (r >= 0)
                  best = std::min(best, static_cast<double>(ms));
              }
          }
        catch (...)
          {
            cudaEventDestroy(start);
            cudaEventDestroy(stop);
            throw;
          }
        cudaEventDestroy(start);
        cudaEventDestroy(stop);
        return best;
      }

      double
      CudaBackend::measure_copy_bandwidth(const std::size_t bytes)
      {
        DeviceBuffer a, b;
        a.reserve(bytes);
        b.reserve(bytes);
        const cudaStream_t st = state->streams[0];
        PARTICULATE_CUDA_CHECK(cudaMemsetAsync(a.ptr, 1, bytes, st));
        PARTICULATE_CUDA_CHECK(cudaMemcpyAsync(b.ptr,
                                               a.ptr,
                                               bytes,
                                               cudaMemcpyDeviceToDevice,
                                               st)); // warm-up
        cudaEvent_t start, stop;
        PARTICULATE_CUDA_CHECK(cudaEventCreate(&start));
        PARTICULATE_CUDA_CHECK(cudaEventCreate(&stop));
        const int reps = 10;
        float     ms   = 0.f;
        try
          {
            PARTICULATE_CUDA_CHECK(cudaEventRecord(start, st));
            for (int r = 0; r < reps; ++r)
              PARTICULATE_CUDA_CHECK(cudaMemcpyAsync((r % 2) ? a.ptr : b.ptr,
                                                     (r % 2) ? b.ptr : a.ptr,
                                                     bytes,
                                                     cudaMemcpyDeviceToDevice,
                                                     st));
            PARTICULATE_CUDA_CHECK(cudaEventRecord(stop, st));
            PARTICULATE_CUDA_CHECK(cudaEventSynchronize(stop));
            PARTICULATE_CUDA_CHECK(cudaEventElapsedTime(&ms, start, stop));
          }
        catch (...)
          {
            cudaEventDestroy(start);
            cudaEventDestroy(stop);
            throw;
          }
        cudaEventDestroy(start);
        cudaEventDestroy(stop);
        // Bytes read plus bytes written, per second, in GB/s.
        return 2. * double(bytes) * reps / (1e-3 * ms) / 1e9;
      }

      void
      CudaBackend::pin(const void *ptr, const std::size_t bytes)
      {
        PARTICULATE_CUDA_CHECK(cudaHostRegister(const_cast<void *>(ptr),
                                                bytes,
                                                cudaHostRegisterDefault));
      }

      void
      CudaBackend::unpin(const void *ptr)
      {
        PARTICULATE_CUDA_CHECK(cudaHostUnregister(const_cast<void *>(ptr)));
      }
    } // namespace detail
  }   // namespace cuda
} // namespace particulate
