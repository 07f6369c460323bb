// Benchmark of point containment (thesis §6.8, Table 6.8 sizes): unit-cube
// lattices of 33^3 ... 129^3 points against 1 and 100 bodies, distance maps
// and inner spheres. For the GPU: kernel time (CUDA events, points resident
// on the device), end-to-end time of classify() with pinned host buffers
// (host broad-phase build, copies in, kernel, copies out), points per second
// and the fraction of the memory-bandwidth bound, from the device-to-device
// copy bandwidth measured in the same run. Kernel and copies are timed the
// same way: events around many launches (copies) back to back, rotating over
// buffers at least four times the L2 cache, divided by their number; the
// older figure, events around one launch, is printed beside it. For the CPU
// path on the same host: one thread and all hardware threads. A second table
// gives the cost of the call a coupled step makes (flags only) against the
// number of mesh bodies (1 to 1000 distance maps) on 65^3 and 129^3 nodes, with
// the number of flags that differ between the GPU and the CPU path. Prints the
// tables; never asserts on time.
//
// Usage: bench_containment [--quick] [--size N]... [--scene TEXT]
// [--kernel-only] [--launches N]
//   --quick: 33^3 and 49^3 only (mesh-body table: 33^3); --size: lattice
//   sizes to run (repeatable, both tables);
//   --scene: only scenes whose name contains TEXT ("map x1", "spheres",
//   "mesh bodies", ...; a final '$' anchors: "map x1$");
//   --kernel-only: only the kernel timings and the kernel table (GPU results
//   still checked against the CPU path), no CPU or end-to-end timings;
//   --launches N: time_kernel() makes N single launches and one batch of N
//   (default 20 single, 5 batches of 100), e.g. for a profiler.
#include <particulate/cuda/containment_engine.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "../tests/test_scenes.h"

using namespace particulate::cuda;
using namespace particulate::cuda::testing;

namespace {
  using Clock = std::chrono::steady_clock;

  /** Median wall time [ms] of f() over reps runs after one warm-up (only
   * the warm-up, and 0 returned, for reps <= 0). */
  template <typename F>
  double
  median_ms(const int reps, F f)
  {
    f();
    if (reps <= 0)
      return 0.;
    std::vector<double> t;
    for (int r = 0; r < reps; ++r)
      {
        const auto a = Clock::now();
        f();
        t.push_back(
          std::chrono::duration<double, std::milli>(Clock::now() - a).count());
      }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  }

  /** Whether a scene name contains `pattern`; a final '$' anchors it at the
   * end ("map x1$" selects "map x1" but not "map x100"). */
  bool
  selected(const std::string &name, const std::string &pattern)
  {
    if (!pattern.empty() && pattern.back() == '$')
      {
        const std::string p = pattern.substr(0, pattern.size() - 1);
        return name.size() >= p.size()
               && name.compare(name.size() - p.size(), p.size(), p) == 0;
      }
    return name.find(pattern) != std::string::npos;
  }

  /** How many launches time_kernel() makes (see KernelTiming). */
  struct Launches
  {
    int single = 20, batch = 100, batches = 5;

    /** engine.time_kernel() with these counts. */
    KernelTiming
    time(ContainmentEngine  &engine,
         const float        *xyz,
         const std::size_t   n,
         const BodyInstance *bodies,
         const std::size_t   m,
         const bool          with_distance) const
    {
      return engine
        .time_kernel(xyz, n, bodies, m, with_distance, single, batch, batches);
    }
  };

  struct Scene
  {
    std::string               name;
    std::vector<int>          handles_cpu, handles_gpu;
    std::vector<BodyInstance> bodies;
    bool                      maps;
  };

  /** Poses: one body at the cube centre, or 100 on a jittered 5x5x4 lattice. */
  std::vector<BodyInstance>
  poses(std::mt19937 &rng, const int m, const int n_shapes)
  {
    std::vector<BodyInstance>              b(m);
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    for (int i = 0; i < m; ++i)
      {
        b[i].shape = i % n_shapes;
        random_rotation(rng, b[i].R);
        if (m == 1)
          b[i].t[0] = b[i].t[1] = b[i].t[2] = 0.5f;
        else
          {
            const int ix = i % 5, iy = (i / 5) % 5, iz = i / 25;
            b[i].t[0] = float(0.1 + 0.2 * ix + jitter(rng));
            b[i].t[1] = float(0.1 + 0.2 * iy + jitter(rng));
            b[i].t[2] = float(0.125 + 0.25 * iz + jitter(rng));
          }
      }
    return b;
  }

  /**
   * The table "containment per coupled step against the number of mesh
   * bodies": 1, 10, 100 and 1000 bodies given as distance maps of 32-64 cells
   * per edge (ellipsoid, elephant-like, torus; the size a mesh body's map has
   * in Particulate), of size about s = 0.04, scattered at random poses in the
   * unit cube without heavy overlap, against a fixed lattice of mesh nodes.
   * The call is the one the coupled step makes (fbm::FictitiousBoundary):
   * flags only, no distances. The first m bodies of one placement of 1000
   * make the scene of m bodies.
   */
  void
  mesh_body_table(ContainmentEngine      &cpu1,
                  ContainmentEngine      *gpu,
                  const std::vector<int> &sizes,
                  const bool              kernel_only,
                  const Launches         &launches)
  {
    const double                 s = 0.04;
    std::vector<DistanceMapData> maps
      = {sample_map_box(ellipsoid_sdf(0.9 * s, 0.6 * s, 0.45 * s),
                        {1.0 * s, 0.7 * s, 0.55 * s},
                        2.0 * s / 60),
         sample_map_box(elephant_sdf(s),
                        {1.05 * s, 0.53 * s, 0.6 * s},
                        2.1 * s / 64),
         sample_map_box(torus_sdf(0.6 * s, 0.25 * s),
                        {0.95 * s, 0.95 * s, 0.5 * s},
                        1.9 * s / 60)};
    std::vector<int> handles;
    for (const DistanceMapData &m : maps)
      {
        handles.push_back(cpu1.add_distance_map(m));
        if (gpu != nullptr && gpu->add_distance_map(m) != handles.back())
          throw std::logic_error("shape handles differ between the engines");
      }
    std::mt19937              rng(2024);
    std::vector<BodyInstance> all
      = scatter_bodies(rng, 1000, s, 1.8 * s, static_cast<int>(maps.size()));
    if (all.size() != 1000)
      throw std::logic_error("could not place 1000 bodies");
    for (BodyInstance &b : all)
      b.shape = handles[static_cast<std::size_t>(b.shape)];
    std::printf(
      "\nMesh bodies: maps of %dx%dx%d (ellipsoid), %dx%dx%d (elephant-like) "
      "and %dx%dx%d (torus) samples, bodies about %.2f long, centres at "
      "least %.3f apart\n",
      maps[0].nx,
      maps[0].ny,
      maps[0].nz,
      maps[1].nx,
      maps[1].ny,
      maps[1].nz,
      maps[2].nx,
      maps[2].ny,
      maps[2].nz,
      2. * s,
      1.8 * s);

    struct Row
    {
      int         m, n1;
      std::size_t n, inside, flag_diffs;
      double      cpu1_ms, kernel_ms, single_ms, e2e_ms;
    };
    std::vector<Row> rows;
    for (const int n1 : sizes)
      {
        std::vector<float> xyz = unit_cube_lattice(n1);
        const std::size_t  n   = xyz.size() / 3;
        std::vector<int>   f_cpu(n), f_gpu(n);
        if (gpu != nullptr)
          {
            gpu->pin_host_memory(xyz.data(), xyz.size() * sizeof(float));
            gpu->pin_host_memory(f_gpu.data(), n * sizeof(int));
          }
        for (const int m : {1, 10, 100, 1000})
          {
            Row r{};
            r.m  = m;
            r.n1 = n1;
            r.n  = n;
            if (kernel_only)
              {
                if (gpu != nullptr)
                  {
                    const KernelTiming kt = launches.time(*gpu,
                                                          xyz.data(),
                                                          n,
                                                          all.data(),
                                                          m,
                                                          false);
                    std::printf(
                      "mesh bodies x%d %d^3: kernel %.4f ms (1 launch %.4f ms)\n",
                      m,
                      n1,
                      kt.batched_ms,
                      kt.single_launch_ms);
                  }
                continue;
              }
            r.cpu1_ms = median_ms(n1 >= 97 ? 3 : 5, [&] {
              cpu1
                .classify(xyz.data(), n, all.data(), m, f_cpu.data(), nullptr);
            });
            r.inside  = std::count_if(f_cpu.begin(), f_cpu.end(), [](int f) {
              return f >= 0;
            });
            if (gpu != nullptr)
              {
                std::fill(f_gpu.begin(),
                          f_gpu.end(),
                          -2); // every flag is written
                r.e2e_ms = median_ms(20, [&] {
                  gpu->classify(xyz.data(),
                                n,
                                all.data(),
                                m,
                                f_gpu.data(),
                                nullptr);
                });
                const KernelTiming kt
                  = launches.time(*gpu, xyz.data(), n, all.data(), m, false);
                r.kernel_ms = kt.batched_ms;
                r.single_ms = kt.single_launch_ms;
                for (std::size_t p = 0; p < n; ++p)
                  r.flag_diffs += f_gpu[p] != f_cpu[p];
              }
            rows.push_back(r);
          }
        if (gpu != nullptr)
          {
            gpu->unpin_host_memory(xyz.data());
            gpu->unpin_host_memory(f_gpu.data());
          }
      }
    if (kernel_only)
      return;

    std::printf(
      "\n## Containment per coupled step against the number of mesh bodies (%s)\n\n",
      gpu != nullptr ? gpu->device_name().c_str() : "no GPU");
    std::printf(
      "| bodies | nodes | inside | CPU 1 thr ms | GPU kernel ms | kernel ms 1 launch "
      "| GPU e2e ms (pinned) "
      "| GPU e2e ns/node | GPU e2e us/body | e2e speed-up vs 1 thr | flag diffs GPU/CPU |\n");
    std::printf(
      "|-------:|-------|-------:|-------------:|--------------:|-------------------:"
      "|--------------------:"
      "|----------------:|----------------:|----------------------:|-------------------:|\n");
    for (const Row &r : rows)
      {
        char nodes[32];
        std::snprintf(nodes, sizeof nodes, "%d^3=%zu", r.n1, r.n);
        if (gpu != nullptr)
          std::printf(
            "| %6d | %-13s | %6zu | %12.2f | %13.4f | %18.4f | %19.3f | %15.4f | %15.3f "
            "| %20.1fx | %18zu |\n",
            r.m,
            nodes,
            r.inside,
            r.cpu1_ms,
            r.kernel_ms,
            r.single_ms,
            r.e2e_ms,
            1e6 * r.e2e_ms / double(r.n),
            1e3 * r.e2e_ms / r.m,
            r.cpu1_ms / r.e2e_ms,
            r.flag_diffs);
        else
          std::printf(
            "| %6d | %-13s | %6zu | %12.2f | %13s | %18s | %19s | %15s | %15s | %21s | %18s |\n",
            r.m,
            nodes,
            r.inside,
            r.cpu1_ms,
            "-",
            "-",
            "-",
            "-",
            "-",
            "-",
            "-");
      }
    std::printf(
      "\nFlags only (distance = nullptr), as fbm::FictitiousBoundary calls it each coupled "
      "step. Kernel: nodes on the device, 100 launches back to back / 100 (median of 5; "
      "1 launch: the fastest of 20 launches timed alone). e2e: classify() host to "
      "host with pinned buffers (input checks, broad-phase grid on the host, copies, "
      "kernel), median of 20. ns/node = e2e / nodes, us/body = e2e / bodies. CPU: the "
      "same call on the CPU path, 1 thread, median of 3-5. Flag diffs: nodes whose "
      "first_body differs between the GPU and the CPU path (must be 0).\n");
  }
} // namespace

int
main(int argc, char **argv)
{
  bool             quick = false;
  std::vector<int> only_sizes;
  std::string      only_scene;
  bool             kernel_only = false; // only time_kernel(), no CPU, no e2e
  Launches         launches;
  for (int a = 1; a < argc; ++a)
    {
      const std::string arg = argv[a];
      if (arg == "--quick")
        quick = true;
      else if (arg == "--size" && a + 1 < argc)
        only_sizes.push_back(std::atoi(argv[++a]));
      else if (arg == "--kernel-only")
        kernel_only = true;
      else if (arg == "--scene" && a + 1 < argc)
        only_scene = argv[++a];
      else if (arg == "--launches" && a + 1 < argc)
        {
          const int k = std::max(1, std::atoi(argv[++a]));
          launches    = Launches{k, k, 1};
        }
      else
        {
          std::printf(
            "usage: bench_containment [--quick] [--size N]... [--scene TEXT] [--kernel-only] "
            "[--launches N]\n");
          return 2;
        }
    }
  try
    {
      const bool        have_gpu = ContainmentEngine::cuda_device_available();
      ContainmentEngine cpu1(Backend::cpu, 1), cpu_all(Backend::cpu, 0);
      std::unique_ptr<ContainmentEngine> gpu;
      if (have_gpu)
        gpu.reset(new ContainmentEngine(Backend::cuda));
      const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
      std::printf(
        "particulate containment benchmark\n  GPU: %s\n  CPU: %u hardware threads\n",
        have_gpu ? gpu->device_name().c_str() : "none (CPU columns only)",
        hw);

      double bw = 0.; // GB/s, read + write
      if (have_gpu)
        {
          bw = gpu->measure_copy_bandwidth(std::size_t(512) << 20);
          std::printf(
            "  device copy bandwidth (cudaMemcpy D2D of 512 MiB, back to back, "
            "read+write): %.0f GB/s\n",
            bw);
        }

      // Shapes. One body: a torus of ring radius 0.3 and tube radius 0.12
      // in the unit cube; 100 bodies: sphere, torus and box of half-size 0.07.
      std::vector<DistanceMapData> maps1
        = {sample_map(torus_sdf(0.3, 0.12), 0.45, 96)};
      const double                 s = 0.07;
      std::vector<DistanceMapData> maps100
        = {sample_map(sphere_sdf(0.7 * s), s, 40),
           sample_map(torus_sdf(0.6 * s, 0.25 * s), s, 40),
           sample_map(box_sdf(0.8 * s, 0.5 * s, 0.3 * s), s, 40)};
      // Inner spheres carved from the same shapes: bounding spheres of a
      // lattice of cells, diameter about the 129^3 mesh spacing (thesis §6.8).
      std::vector<InnerSphereData> sph1
        = {carve_spheres(torus_sdf(0.3, 0.12), 0.45, 1. / 128)};
      std::vector<InnerSphereData> sph100
        = {carve_spheres(sphere_sdf(0.7 * s), s, s / 10),
           carve_spheres(torus_sdf(0.6 * s, 0.25 * s), s, s / 10),
           carve_spheres(box_sdf(0.8 * s, 0.5 * s, 0.3 * s), s, s / 10)};
      std::printf(
        "  shapes: 1 body = torus map 96^3 / %zu inner spheres; 100 bodies = 3 maps 40^3 / "
        "%zu+%zu+%zu inner spheres\n",
        sph1[0].r.size(),
        sph100[0].r.size(),
        sph100[1].r.size(),
        sph100[2].r.size());

      std::mt19937       rng(42);
      std::vector<Scene> scenes;
      for (int kind = 0; kind < 2; ++kind)
        for (const int m : {1, 100})
          {
            Scene sc;
            sc.maps = kind == 0;
            sc.name = std::string(sc.maps ? "map" : "spheres")
                      + (m == 1 ? " x1" : " x100");
            const auto      &mv = m == 1 ? maps1 : maps100;
            const auto      &sv = m == 1 ? sph1 : sph100;
            const int        ns = static_cast<int>(m == 1 ? 1 : 3);
            std::vector<int> hc, hall, hg;
            for (int i = 0; i < ns; ++i)
              {
                hc.push_back(sc.maps ? cpu1.add_distance_map(mv[i]) :
                                       cpu1.add_inner_spheres(sv[i]));
                hall.push_back(sc.maps ? cpu_all.add_distance_map(mv[i]) :
                                         cpu_all.add_inner_spheres(sv[i]));
                if (gpu)
                  hg.push_back(sc.maps ? gpu->add_distance_map(mv[i]) :
                                         gpu->add_inner_spheres(sv[i]));
              }
            sc.bodies = poses(rng, m, ns);
            // Handles agree across engines because shapes are added in the
            // same order; map the body shapes to the handles.
            for (BodyInstance &b : sc.bodies)
              b.shape = hc[b.shape];
            scenes.push_back(sc);
          }

      std::vector<int> sizes = {33, 49, 65, 97, 129};
      if (quick)
        sizes = {33, 49};
      if (!only_sizes.empty())
        sizes = only_sizes;

      struct Row
      {
        std::string scene;
        int         n1;
        std::size_t n, inside;
        double kernel_ms, e2e_ms, e2e_pageable_ms, cpu1_ms, cpuall_ms, bound_ms;
        double single_ms, io_only_ms, bytes, copy_same_ms;
        int    sets;
        bool   identical;
      };
      std::vector<Row> rows;
      for (const Scene &sc : scenes)
        for (const int n1 : sizes)
          {
            if (!selected(sc.name, only_scene))
              continue;
            std::vector<float> xyz = unit_cube_lattice(n1);
            const std::size_t  n   = xyz.size() / 3;
            std::vector<int>   f_cpu(n), f_gpu(n);
            std::vector<float> d_cpu(n), d_gpu(n);
            float             *dc = sc.maps ? d_cpu.data() : nullptr;
            float             *dg = sc.maps ? d_gpu.data() : nullptr;
            Row                r{};
            r.scene                = sc.name;
            r.n1                   = n1;
            r.n                    = n;
            const int  cpu_reps    = kernel_only ? 0 : n1 >= 97 ? 3 : 5;
            const auto classify_on = [&](ContainmentEngine &engine) {
              engine.classify(xyz.data(),
                              n,
                              sc.bodies.data(),
                              sc.bodies.size(),
                              f_cpu.data(),
                              dc);
            };
            if (!kernel_only)
              r.cpu1_ms = median_ms(cpu_reps, [&] { classify_on(cpu1); });
            r.cpuall_ms = median_ms(cpu_reps, [&] { classify_on(cpu_all); });
            r.inside    = std::count_if(f_cpu.begin(), f_cpu.end(), [](int f) {
              return f >= 0;
            });
            if (gpu)
              {
                gpu->pin_host_memory(xyz.data(), xyz.size() * sizeof(float));
                gpu->pin_host_memory(f_gpu.data(), n * sizeof(int));
                gpu->pin_host_memory(d_gpu.data(), n * sizeof(float));
                r.e2e_ms              = median_ms(kernel_only ? 0 : 20, [&] {
                  gpu->classify(xyz.data(),
                                n,
                                sc.bodies.data(),
                                sc.bodies.size(),
                                f_gpu.data(),
                                dg);
                });
                const KernelTiming kt = launches.time(*gpu,
                                                      xyz.data(),
                                                      n,
                                                      sc.bodies.data(),
                                                      sc.bodies.size(),
                                                      sc.maps);
                r.kernel_ms           = kt.batched_ms;
                r.single_ms           = kt.single_launch_ms;
                r.sets                = kt.buffer_sets;
                r.io_only_ms          = kt.io_only_ms;
                gpu->unpin_host_memory(xyz.data());
                gpu->unpin_host_memory(f_gpu.data());
                gpu->unpin_host_memory(d_gpu.data());
                // The same from ordinary (pageable) memory, as a caller with
                // its own std::vector would see it.
                r.e2e_pageable_ms = median_ms(kernel_only ? 0 : 5, [&] {
                  gpu->classify(xyz.data(),
                                n,
                                sc.bodies.data(),
                                sc.bodies.size(),
                                f_gpu.data(),
                                dg);
                });
                r.identical       = f_gpu == f_cpu
                              && (!sc.maps
                                  || std::memcmp(d_gpu.data(),
                                                 d_cpu.data(),
                                                 n * sizeof(float))
                                       == 0);
                // Compulsory traffic: read 12 B of point, write 4 B of flag
                // (+ 4 B of distance); bytes / (copy bandwidth).
                r.bytes    = double(n) * (12. + 4. + (sc.maps ? 4. : 0.));
                r.bound_ms = r.bytes / (bw * 1e9) * 1e3;
                // A copy that moves as many bytes (half read, half written),
                // timed the same way as the kernel.
                const double bw_same = gpu->measure_copy_bandwidth(
                  static_cast<std::size_t>(r.bytes / 2));
                r.copy_same_ms = r.bytes / (bw_same * 1e9) * 1e3;
              }
            rows.push_back(r);
            std::fflush(stdout);
          }

      if (!kernel_only)
        {
          // Fixed cost of a call, whatever the number of points: classify() of
          // a single point (input checks and broad-phase grid on the host; for
          // the GPU also the scene upload, one launch and the synchronisation).
          std::printf(
            "\nFixed cost per classify() call (one point, median of 50):\n");
          for (const Scene &sc : scenes)
            {
              if (!selected(sc.name, only_scene))
                continue;
              const float  one[3] = {0.5f, 0.5f, 0.5f};
              int          f;
              float        d;
              float       *dd  = sc.maps ? &d : nullptr;
              const double cpu = median_ms(50, [&] {
                cpu1
                  .classify(one, 1, sc.bodies.data(), sc.bodies.size(), &f, dd);
              });
              const double gpu_ms
                = gpu ? median_ms(50,
                                  [&] {
                                    gpu->classify(one,
                                                  1,
                                                  sc.bodies.data(),
                                                  sc.bodies.size(),
                                                  &f,
                                                  dd);
                                  }) :
                        0.;
              char g[32] = "-";
              if (gpu)
                std::snprintf(g, sizeof g, "%.3f ms", gpu_ms);
              std::printf("  %-12s CPU path %.3f ms, GPU path %s\n",
                          sc.name.c_str(),
                          cpu,
                          g);
            }

          std::printf(
            "\n## CUDA containment benchmark (%s; CPU path: 1 thread and %u threads)\n\n",
            have_gpu ? gpu->device_name().c_str() : "no GPU",
            hw);
          std::printf(
            "| scene        | points        | inside | kernel ms | kernel Gpts/s | %% of BW bound "
            "| e2e ms (pinned) | e2e Mpts/s | e2e ms (pageable) | CPU 1 thr ms | CPU %u thr ms "
            "| e2e speed-up vs 1 thr | vs %u thr | GPU==CPU |\n",
            hw,
            hw);
          std::printf(
            "|--------------|---------------|--------|-----------|---------------|---------------"
            "|-----------------|------------|-------------------|--------------|--------------"
            "|-----------------------|-----------|----------|\n");
          for (const Row &r : rows)
            {
              char pts[32];
              std::snprintf(pts, sizeof pts, "%d^3=%zu", r.n1, r.n);
              if (have_gpu)
                std::printf(
                  "| %-12s | %-13s | %6zu | %9.4f | %13.1f | %12.0f%% | %15.3f | %10.0f | %17.3f "
                  "| %12.2f | %12.2f | %20.1fx | %8.1fx | %-8s |\n",
                  r.scene.c_str(),
                  pts,
                  r.inside,
                  r.kernel_ms,
                  r.n / r.kernel_ms / 1e6,
                  100. * r.bound_ms / r.kernel_ms,
                  r.e2e_ms,
                  r.n / r.e2e_ms / 1e3,
                  r.e2e_pageable_ms,
                  r.cpu1_ms,
                  r.cpuall_ms,
                  r.cpu1_ms / r.e2e_ms,
                  r.cpuall_ms / r.e2e_ms,
                  r.identical ? "yes" : "NO");
              else
                std::printf(
                  "| %-12s | %-13s | %6zu | %9s | %13s | %13s | %15s | %10s | %17s | %12.2f | %12.2f "
                  "| %21s | %9s | %-8s |\n",
                  r.scene.c_str(),
                  pts,
                  r.inside,
                  "-",
                  "-",
                  "-",
                  "-",
                  "-",
                  "-",
                  r.cpu1_ms,
                  r.cpuall_ms,
                  "-",
                  "-",
                  "-");
            }
          std::printf(
            "\n%% of BW bound = time to move the compulsory bytes (12 B point read + 4 B flag + 4 B "
            "distance for maps, per point) at the measured copy bandwidth / kernel time. Kernel: points "
            "resident on the device, 100 launches back to back / 100, median of 5 (see the kernel "
            "table). e2e = classify() from host to host (broad-phase "
            "build, copies in, kernel, copies out), median of 20 (pinned) or 5 (pageable). CPU: same "
            "classify() on the CPU path, median of 3-5. Speed-ups use the pinned e2e time.\n");
        }

      if (have_gpu)
        {
          std::printf(
            "\n## Kernel time against the copy bandwidth (%s, copy bandwidth "
            "%.0f GB/s)\n\n",
            gpu->device_name().c_str(),
            bw);
          std::printf(
            "| scene        | points        | MB moved | bound us | same-bytes copy us "
            "| I/O-only kernel us "
            "| kernel us | %% of BW bound | %% of same-bytes copy | %% of I/O-only "
            "| kernel us 1 launch "
            "| %% of BW bound 1 launch | sets | GPU==CPU |\n");
          std::printf(
            "|--------------|---------------|---------:|---------:|-------------------:"
            "|-------------------:"
            "|----------:|--------------:|---------------------:|--------------:"
            "|------------------:"
            "|----------------------:|-----:|----------|\n");
          for (const Row &r : rows)
            {
              char pts[32];
              std::snprintf(pts, sizeof pts, "%d^3=%zu", r.n1, r.n);
              std::printf(
                "| %-12s | %-13s | %8.1f | %8.2f | %18.2f | %18.2f | %9.2f | %12.0f%% "
                "| %19.0f%% | %12.0f%% "
                "| %17.2f | %20.0f%% | %4d | %-8s |\n",
                r.scene.c_str(),
                pts,
                r.bytes / 1e6,
                1e3 * r.bound_ms,
                1e3 * r.copy_same_ms,
                1e3 * r.io_only_ms,
                1e3 * r.kernel_ms,
                100. * r.bound_ms / r.kernel_ms,
                100. * r.copy_same_ms / r.kernel_ms,
                100. * r.io_only_ms / r.kernel_ms,
                1e3 * r.single_ms,
                100. * r.bound_ms / r.single_ms,
                r.sets,
                r.identical ? "yes" : "NO");
            }
          std::printf(
            "\nMB moved: compulsory bytes (12 B point read, 4 B flag and, for maps, 4 B "
            "distance written, per point). Bound: MB moved at the copy bandwidth of a "
            "512 MiB cudaMemcpy. Same-bytes copy: a cudaMemcpy that reads and writes as "
            "many bytes in all, timed like the kernel. I/O-only kernel: the same launch, "
            "loads and stores with a trivial function of the point in place of the "
            "classification, timed like the kernel. Kernel: points on the device, 100 "
            "launches back to back between two events / 100, rotating over `sets` copies "
            "of points and outputs (at least 4x the L2 cache), median of 5; copies timed "
            "the same way. 1 launch: events around one launch, fastest of 20 (includes "
            "launch and event latency).\n");
        }

      if (selected("mesh bodies", only_scene))
        mesh_body_table(cpu1,
                        gpu.get(),
                        !only_sizes.empty() ? only_sizes :
                        quick               ? std::vector<int>{33} :
                                              std::vector<int>{65, 129},
                        kernel_only,
                        launches);
    }
  catch (const std::exception &e)
    {
      std::printf("benchmark failed: %s\n", e.what());
      return 1;
    }
  return 0;
}
