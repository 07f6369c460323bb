#ifndef particulate_cuda_containment_engine_h
#define particulate_cuda_containment_engine_h

#include <particulate/cuda/containment_types.h>

#include <cstddef>
#include <memory>
#include <string>

namespace particulate {
  namespace cuda {
    /** Where ContainmentEngine does its work. */
    enum class Backend
    {
      /** CUDA when the library was built with it and a device is present, else
         CPU. */
      automatic,
      /** The CPU path (std::thread over points). */
      cpu,
      /** The CUDA path; asking for it without a device throws. */
      cuda
    };

    /** "cpu" or "cuda" (automatic is never the backend of an engine). */
    const char *
    to_string(Backend backend);

    /** Result of ContainmentEngine::time_kernel(), times in milliseconds. */
    struct KernelTiming
    {
      /** Fastest of single launches, each timed alone by events. */
      double single_launch_ms = 0.;
      /** Median over batches of (batch of back-to-back launches) / batch. */
      double batched_ms = 0.;
      /**
       * batched_ms of a kernel with the same launch, loads and stores but
       * no classification (a trivial function of the point instead).
       */
      double io_only_ms = 0.;
      /** Copies of points and outputs the batched launches rotate over. */
      int buffer_sets = 0;
    };

    /**
     * Point containment for many points against many rigid bodies, on the GPU
     * or on the CPU with the same arithmetic (thesis §5.4.3 and §6.8).
     *
     * Usage: upload each shape once (add_distance_map(), add_inner_spheres())
     * and keep its handle; then, every time step, call classify() with the
     * mesh points and the bodies (handle + pose). The result for a point is
     * the index of the first body containing it (or -1) and, on request, the
     * minimum interpolated signed distance over the distance-map bodies.
     *
     * The CPU and the CUDA path evaluate exactly the same function,
     * detail::classify_point(), with the same sequence of separately rounded
     * float operations (no fused multiply-add on either side), so their flags
     * and distances agree bit for bit; see detail/point_query.h.
     *
     * Both paths cull bodies with a uniform world-space grid over the bodies'
     * bounding boxes, rebuilt on the host at each call (O(M) work), and the
     * inner-sphere test uses a uniform grid of spheres per shape, built once
     * at upload: each point reads only the spheres of its own cell.
     *
     * An engine is not thread-safe: use one per thread. Errors (bad input, a
     * failing CUDA call or launch) throw std::invalid_argument or
     * std::runtime_error with a message saying what went wrong and where.
     */
    class ContainmentEngine
    {
    public:
      /**
       * @param backend      where to compute (see Backend).
       * @param cpu_threads  threads of the CPU path; 0 = all hardware threads.
       */
      explicit ContainmentEngine(Backend  backend     = Backend::automatic,
                                 unsigned cpu_threads = 0);
      ~ContainmentEngine();
      ContainmentEngine(ContainmentEngine &&) noexcept;
      ContainmentEngine &
      operator=(ContainmentEngine &&) noexcept;
      ContainmentEngine(const ContainmentEngine &) = delete;
      ContainmentEngine &
      operator=(const ContainmentEngine &)
        = delete;

      /** Whether this library was compiled with its CUDA sources. */
      static bool
      cuda_compiled();

      /** Whether CUDA is compiled in and at least one device is visible. */
      static bool
      cuda_device_available();

      /** The backend in use: Backend::cpu or Backend::cuda. */
      Backend
      backend() const;

      /** A human-readable name of the device ("NVIDIA H100 ...", or "CPU, 16
       * threads"). */
      std::string
      device_name() const;

      /** Threads used by the CPU path (0 = all hardware threads). */
      void
      set_cpu_threads(unsigned n);

      /**
       * Uploads a distance map and returns its shape handle. Throws
       * std::invalid_argument for fewer than 2 points per axis, a value count
       * other than nx*ny*nz, a non-positive spacing or a non-finite value.
       */
      int
      add_distance_map(const DistanceMapData &map);

      /**
       * Uploads an inner-sphere set and returns its shape handle; builds the
       * uniform grid of spheres (cell size about the mean sphere diameter).
       * Throws std::invalid_argument for arrays of unequal length, an empty
       * set, a negative radius or a non-finite value.
       */
      int
      add_inner_spheres(const InnerSphereData &spheres);

      /** Number of shapes uploaded so far. */
      std::size_t
      n_shapes() const;

      /**
       * Classifies n world points against m bodies.
       *
       * @param xyz        3n floats, point p at xyz[3p], xyz[3p+1], xyz[3p+2]
       * [m].
       * @param n          number of points (any, 0 included).
       * @param bodies     m bodies: shape handle and pose.
       * @param m          number of bodies.
       * @param first_body n ints (or nullptr): index into bodies of the
       *                   lowest-numbered body containing the point, or -1.
       * @param distance   n floats (or nullptr): minimum interpolated signed
       *                   distance [m] over the distance-map bodies whose box
       *                   contains the point; +infinity where none does.
       *
       * Every element of the given outputs is written. For the fastest
       * transfers on the CUDA path, allocate or pin the buffers with
       * pin_host_memory(); pageable memory works too, only slower.
       */
      void
      classify(const float        *xyz,
               std::size_t         n,
               const BodyInstance *bodies,
               std::size_t         m,
               int                *first_body,
               float              *distance);

      /**
       * Page-locks host memory for fast asynchronous transfers (CUDA path;
       * a no-op on the CPU path). Undo with unpin_host_memory() before the
       * memory is freed.
       */
      void
      pin_host_memory(const void *ptr, std::size_t bytes);

      /** Undoes pin_host_memory(). */
      void
      unpin_host_memory(const void *ptr);

      /**
       * Benchmark aid (CUDA path only): kernel time of one classification of
       * all n points, which are uploaded first (no host copies timed). Two
       * methods, both with CUDA events:
       *
       * - `single_launch_ms`: events around one launch, the fastest of
       *   `single_launches` (after one warm-up). Includes the time from the
       *   first event to the start of the kernel and from its end to the
       *   second event (some microseconds), which is not kernel work.
       * - `batched_ms`: events around `batch` launches back to back, divided
       *   by `batch`; the median over `batches` such batches (after one
       *   warm-up pass). The launches rotate over `buffer_sets` copies of
       *   the points and outputs, as many as make their bytes at least four
       *   times the device's L2 cache (at most `batch`), so that the points
       *   come from device memory as they would in a time step, not from a
       *   cache that the previous launch filled.
       */
      KernelTiming
      time_kernel(const float        *xyz,
                  std::size_t         n,
                  const BodyInstance *bodies,
                  std::size_t         m,
                  bool                with_distance,
                  int                 single_launches,
                  int                 batch,
                  int                 batches);

      /**
       * Benchmark aid (CUDA path only): device-to-device copy bandwidth in
       * GB/s, counting bytes read plus bytes written, with the batched
       * method of time_kernel(): `cudaMemcpyAsync` of `bytes` bytes
       * repeated back to back between two events (at least 10 copies and
       * at least about 4 GB moved in all), rotating over enough buffer pairs
       * that their bytes are at least four times the L2 cache; the median of
       * 5 such batches.
       */
      double
      measure_copy_bandwidth(std::size_t bytes);

    private:
      struct Impl;
      std::unique_ptr<Impl> impl;
    };
  } // namespace cuda
} // namespace particulate

#endif
