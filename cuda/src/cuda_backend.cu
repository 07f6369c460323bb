// CUDA path of ContainmentEngine: device memory, streams and the
// classification kernel (thesis §5.4.3: one thread per mesh point).
//
// Arithmetic: the kernel calls detail::classify_point(), whose float
// operations are __fmul_rn/__fadd_rn/__fsub_rn intrinsics that nvcc never
// fuses into FMAs; the target is also compiled with -fmad=false so that no
// other expression can be contracted behind our back. The CPU twin computes
// the same sequence of rounded operations, so results agree bit for bit.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

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
         * points (also as a grid-stride loop that loads the next point
         * before classifying the current one), 64 or 256 threads per block,
         * bricked or 8-corner map layouts, four sphere entries per loop step,
         * a kernel specialised at compile time for flags only or with
         * distances, L2 prefetch hints on the points, and persistent grids
         * were all slower or no faster. What bounds it is the L2 traffic of
         * the map gathers and the latency of dependent loads (cell, body,
         * map, sphere entries), not DRAM; see doc/performance.md, "CUDA
         * containment".
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

        /**
         * The reference for what the classification costs: the launch, loads
         * and stores of classify_kernel with a trivial function of the point
         * in place of classify_point() (used by time_kernel() only).
         */
        __global__ void
        __launch_bounds__(threads_per_block)
          io_only_kernel(const float *__restrict__ xyz,
                         const int n,
                         int *__restrict__ first_body,
                         float *__restrict__ distance)
        {
          const int p = blockIdx.x * threads_per_block + threadIdx.x;
          if (p >= n)
            return;
          const float x = __ldcs(xyz + 3 * p), y = __ldcs(xyz + 3 * p + 1),
                      z = __ldcs(xyz + 3 * p + 2);
          if (first_body != nullptr)
            __stcs(first_body + p, x + y > z ? 0 : -1);
          if (distance != nullptr)
            __stcs(distance + p, x - z);
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

      namespace {
        /** A pair of timing events, destroyed with the object. */
        struct EventPair
        {
          cudaEvent_t start = nullptr, stop = nullptr;

          EventPair()
          {
            PARTICULATE_CUDA_CHECK(cudaEventCreate(&start));
            if (cudaEventCreate(&stop) != cudaSuccess)
              {
                cudaEventDestroy(start);
                PARTICULATE_CUDA_CHECK(cudaGetLastError());
              }
          }

          ~EventPair()
          {
            cudaEventDestroy(start);
            cudaEventDestroy(stop);
          }

          /** Milliseconds from start to stop, once stop has happened. */
          double
          elapsed_ms() const
          {
            PARTICULATE_CUDA_CHECK(cudaEventSynchronize(stop));
            float ms = 0.f;
            PARTICULATE_CUDA_CHECK(cudaEventElapsedTime(&ms, start, stop));
            return ms;
          }
        };

        double
        median(std::vector<double> v)
        {
          std::sort(v.begin(), v.end());
          return v.size() % 2 == 1 ?
                   v[v.size() / 2] :
                   0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
        }

        /**
         * Number of copies of a working set of `bytes` that back-to-back
         * timings rotate over: enough that together they are at least four
         * times the L2 cache, so that a launch does not find its inputs in
         * the cache the previous launches left; between 1 and `at_most`.
         */
        int
        rotation_sets(const cudaDeviceProp &prop,
                      const std::size_t     bytes,
                      const int             at_most)
        {
          const double l2 = std::max(prop.l2CacheSize, 1);
          const double k
            = std::ceil(4. * l2 / double(std::max<std::size_t>(bytes, 1)));
          return static_cast<int>(
            std::max(1., std::min(k, double(std::max(1, at_most)))));
        }
      } // namespace

      KernelTiming
      CudaBackend::time_kernel(const SceneGrid  &scene,
                               const float      *xyz,
                               const std::size_t n,
                               const bool        with_distance,
                               const int         single_launches,
                               const int         batch,
                               const int         batches)
      {
        State       &s = *state;
        KernelTiming timing;
        if (n == 0)
          return timing;
        // One working set = points, flags and (optionally) distances.
        const std::size_t xyz_bytes   = align_up(3 * n * sizeof(float));
        const std::size_t first_bytes = align_up(n * sizeof(int));
        const std::size_t dist_bytes
          = with_distance ? align_up(n * sizeof(float)) : 0;
        const std::size_t set_bytes = xyz_bytes + first_bytes + dist_bytes;
        const int         sets      = rotation_sets(s.prop, set_bytes, batch);
        timing.buffer_sets          = sets;
        DeviceBuffer pool;
        pool.reserve(set_bytes * sets);
        char *const base = static_cast<char *>(pool.ptr);
        auto        set  = [&](const int k) { return base + k * set_bytes; };

        const cudaStream_t st = s.streams[0];
        PARTICULATE_CUDA_CHECK(cudaMemcpyAsync(set(0),
                                               xyz,
                                               3 * n * sizeof(float),
                                               cudaMemcpyHostToDevice,
                                               st));
        for (int k = 1; k < sets; ++k)
          PARTICULATE_CUDA_CHECK(cudaMemcpyAsync(set(k),
                                                 set(0),
                                                 3 * n * sizeof(float),
                                                 cudaMemcpyDeviceToDevice,
                                                 st));
        const SceneView view = s.upload_scene(scene); // on streams[0], in order
        auto            launch = [&](const int k) {
          char *p = set(k);
          launch_classify(view,
                          reinterpret_cast<const float *>(p),
                          n,
                          reinterpret_cast<int *>(p + xyz_bytes),
                          with_distance ? reinterpret_cast<float *>(
                            p + xyz_bytes + first_bytes) :
                                                     nullptr,
                          st);
        };

        EventPair ev;
        // Method 1: one launch between two events; the fastest.
        double best = HUGE_VAL;
        for (int r = -1; r < std::max(1, single_launches); ++r) // -1 warms up
          {
            PARTICULATE_CUDA_CHECK(cudaEventRecord(ev.start, st));
            launch(0);
            PARTICULATE_CUDA_CHECK(cudaEventRecord(ev.stop, st));
            const double ms = ev.elapsed_ms();
            if (r >= 0)
              best = std::min(best, ms);
          }
        timing.single_launch_ms = best;

        // Method 2: `batch` launches back to back between two events,
        // rotating over the working sets; the median over `batches`.
        int  c       = 0;
        auto batched = [&](const auto &launch_on_set) {
          for (int k = 0; k < sets; ++k) // warm-up pass
            launch_on_set(c++ % sets);
          std::vector<double> per_launch;
          for (int r = 0; r < std::max(1, batches); ++r)
            {
              PARTICULATE_CUDA_CHECK(cudaEventRecord(ev.start, st));
              for (int i = 0; i < std::max(1, batch); ++i)
                launch_on_set(c++ % sets);
              PARTICULATE_CUDA_CHECK(cudaEventRecord(ev.stop, st));
              per_launch.push_back(ev.elapsed_ms() / std::max(1, batch));
            }
          return median(per_launch);
        };
        timing.batched_ms = batched(launch);

        // Method 2 for io_only_kernel over the same working sets.
        const unsigned blocks = static_cast<unsigned>(
          (n + threads_per_block - 1) / threads_per_block);
        auto io_launch = [&](const int k) {
          char *p = set(k);
          io_only_kernel<<<blocks, threads_per_block, 0, st>>>(
            reinterpret_cast<const float *>(p),
            static_cast<int>(n),
            reinterpret_cast<int *>(p + xyz_bytes),
            with_distance ?
              reinterpret_cast<float *>(p + xyz_bytes + first_bytes) :
              nullptr);
          PARTICULATE_CUDA_CHECK(cudaGetLastError());
        };
        timing.io_only_ms = batched(io_launch);
        PARTICULATE_CUDA_CHECK(cudaStreamSynchronize(st));
        return timing;
      }

      double
      CudaBackend::measure_copy_bandwidth(const std::size_t bytes)
      {
        if (bytes == 0)
          return 0.;
        const std::size_t b     = align_up(bytes);
        const int         pairs = rotation_sets(state->prop, 2 * b, 100);
        DeviceBuffer      pool;
        pool.reserve(2 * b * pairs);
        char *const        base = static_cast<char *>(pool.ptr);
        const cudaStream_t st   = state->streams[0];
        PARTICULATE_CUDA_CHECK(cudaMemsetAsync(pool.ptr, 1, 2 * b * pairs, st));
        // Copy c goes within pair c % pairs, in alternating directions.
        auto copy = [&](const int c) {
          char *a = base + 2 * b * (c % pairs), *d = a + b;
          if ((c / pairs) % 2 == 1)
            std::swap(a, d);
          PARTICULATE_CUDA_CHECK(
            cudaMemcpyAsync(d, a, bytes, cudaMemcpyDeviceToDevice, st));
        };
        // At least 10 copies and about 4 GB per batch.
        const int copies = static_cast<int>(
          std::max(10., std::ceil(4e9 / (2. * double(bytes)))));
        int c = 0;
        for (int k = 0; k < pairs; ++k) // warm-up pass
          copy(c++);
        EventPair           ev;
        std::vector<double> ms;
        for (int r = 0; r < 5; ++r)
          {
            PARTICULATE_CUDA_CHECK(cudaEventRecord(ev.start, st));
            for (int i = 0; i < copies; ++i)
              copy(c++);
            PARTICULATE_CUDA_CHECK(cudaEventRecord(ev.stop, st));
            ms.push_back(ev.elapsed_ms());
          }
        PARTICULATE_CUDA_CHECK(cudaStreamSynchronize(st));
        // Bytes read plus bytes written, per second, in GB/s.
        return 2. * double(bytes) * copies / (1e-3 * median(ms)) / 1e9;
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
