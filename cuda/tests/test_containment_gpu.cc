// GPU path against the CPU path (label gpu; exits 77 = skipped when the
// library was built without CUDA or no device is visible).
//
// The two paths run the same rounded float operations, so flags and
// distances are expected to agree bit for bit; the acceptance
// criterion is looser (flags may differ within 1e-6 spacing of the zero
// level, distances to float rounding) and is what is asserted, while the
// exact agreement is reported.
#include <particulate/cuda/containment_engine.h>

#include <cstring>
#include <limits>
#include <stdexcept>

#include "reference.h"
#include "test_scenes.h"

using namespace particulate::cuda;
using namespace particulate::cuda::testing;

namespace {
  const float inf = std::numeric_limits<float>::infinity();

  struct Comparison
  {
    std::size_t n = 0, flag_mismatch = 0, flag_mismatch_off_surface = 0,
                dist_mismatch = 0, dist_beyond_rounding = 0, inside = 0;
  };

  /**
   * Compares GPU and CPU outputs. A flag mismatch counts against the test
   * unless the CPU distance of the point is within 1e-6 spacing of zero.
   */
  Comparison
  compare(const std::vector<int>   &fg,
          const std::vector<float> &dg,
          const std::vector<int>   &fc,
          const std::vector<float> &dc,
          const double              spacing)
  {
    Comparison c;
    c.n = fg.size();
    for (std::size_t p = 0; p < fg.size(); ++p)
      {
        c.inside += fc[p] >= 0;
        if (fg[p] != fc[p])
          {
            ++c.flag_mismatch;
            if (!(std::abs(dc[p]) <= 1e-6 * spacing))
              ++c.flag_mismatch_off_surface;
          }
        if (!dg.empty() && std::memcmp(&dg[p], &dc[p], 4) != 0)
          {
            ++c.dist_mismatch;
            const double tol = 4. * std::numeric_limits<float>::epsilon()
                               * std::max<double>(std::abs(dc[p]), spacing);
            if (!(dc[p] == inf && dg[p] == inf)
                && !(std::abs(double(dg[p]) - dc[p]) <= tol))
              ++c.dist_beyond_rounding;
          }
      }
    return c;
  }

  void
  report(const char *what, const Comparison &c)
  {
    std::printf(
      "  %-44s %8zu points, %7zu inside: flags differ %zu (off the surface %zu), "
      "distances differ %zu (beyond rounding %zu)\n",
      what,
      c.n,
      c.inside,
      c.flag_mismatch,
      c.flag_mismatch_off_surface,
      c.dist_mismatch,
      c.dist_beyond_rounding);
    PARTICULATE_CHECK(c.flag_mismatch_off_surface == 0
                        && c.dist_beyond_rounding == 0,
                      "%s: GPU and CPU disagree",
                      what);
    PARTICULATE_CHECK(c.inside > 0,
                      "%s: no point inside, the test proves nothing",
                      what);
  }

  /** GPU vs CPU on random points and random poses, for a set of scenes. */
  void
  test_random_scenes(ContainmentEngine            &gpu,
                     ContainmentEngine            &cpu,
                     const std::vector<TestShape> &shapes,
                     std::mt19937                 &rng)
  {
    double min_spacing = HUGE_VAL;
    for (const TestShape &s : shapes)
      if (s.is_map)
        min_spacing = std::min<double>(min_spacing, s.map.spacing[0]);

    const int shape_sets[4][2]
      = {{0, 3}, {3, 5}, {0, 5}, {0, 5}}; // maps, spheres, mixed
    const int   body_counts[4] = {1, 1, 100, 1};
    const char *names[4]       = {"distance maps, 1 body, 12 poses",
                                  "inner spheres, 1 body, 12 poses",
                                  "mixed, 100 bodies, 12 pose sets",
                                  "mixed, 1 body, far/NaN points"};
    for (int t = 0; t < 4; ++t)
      {
        Comparison total;
        for (int trial = 0; trial < 12; ++trial)
          {
            std::vector<BodyInstance> bodies(body_counts[t]);
            for (int b = 0; b < body_counts[t]; ++b)
              {
                const int lo = shape_sets[t][0], hi = shape_sets[t][1];
                bodies[b].shape = lo + (trial + b) % (hi - lo);
                random_rotation(rng, bodies[b].R);
                for (int a = 0; a < 3; ++a)
                  bodies[b].t[a] = float(std::uniform_real_distribution<double>(
                    body_counts[t] == 1 ? 0.4 : 0.,
                    body_counts[t] == 1 ? 0.6 : 1.)(rng));
              }
            const std::size_t np
              = 200000 + 37 * trial; // never a multiple of 256
            std::vector<float> xyz = random_points(rng, np, -0.1, 1.1);
            if (t == 3)
              for (std::size_t p = 0; p < np; p += 97)
                xyz[3 * p + (p % 3)]
                  = (p % 2) ? std::numeric_limits<float>::quiet_NaN() : 1e30f;
            std::vector<int>   fg(np, 0x5a5a5a5a), fc(np);
            std::vector<float> dg(np, -12345.f), dc(np);
            gpu.classify(xyz.data(),
                         np,
                         bodies.data(),
                         bodies.size(),
                         fg.data(),
                         dg.data());
            cpu.classify(xyz.data(),
                         np,
                         bodies.data(),
                         bodies.size(),
                         fc.data(),
                         dc.data());
            const Comparison c = compare(fg, dg, fc, dc, min_spacing);
            total.n += c.n;
            total.inside += c.inside;
            total.flag_mismatch += c.flag_mismatch;
            total.flag_mismatch_off_surface += c.flag_mismatch_off_surface;
            total.dist_mismatch += c.dist_mismatch;
            total.dist_beyond_rounding += c.dist_beyond_rounding;
            // Flags only (the kernel's early exit): same first body.
            std::vector<int> fo(np, 0x5a5a5a5a);
            gpu.classify(xyz.data(),
                         np,
                         bodies.data(),
                         bodies.size(),
                         fo.data(),
                         nullptr);
            const Comparison co = compare(fo, {}, fc, dc, min_spacing);
            total.flag_mismatch += co.flag_mismatch;
            total.flag_mismatch_off_surface += co.flag_mismatch_off_surface;
          }
        report(names[t], total);
      }
  }

  /**
   * Outputs poisoned on the host and stale on the device are all
   * overwritten, for sizes around the block size and the chunk size.
   */
  void
  test_poison_and_sizes(ContainmentEngine            &gpu,
                        ContainmentEngine            &cpu,
                        const std::vector<TestShape> &shapes,
                        std::mt19937                 &rng)
  {
    (void)shapes;
    std::vector<BodyInstance> bodies(30);
    for (int b = 0; b < 30; ++b)
      {
        bodies[b].shape = b % 5;
        random_rotation(rng, bodies[b].R);
        for (int a = 0; a < 3; ++a)
          bodies[b].t[a]
            = float(std::uniform_real_distribution<double>(0., 1.)(rng));
      }
    const std::uint32_t poison_bits = 0x7fbadbadu;
    float               poison;
    std::memcpy(&poison, &poison_bits, 4);
    std::size_t sizes[]
      = {1, 255, 256, 257, 1000, 131071, 131073, (std::size_t(1) << 20) + 3};
    for (const std::size_t np : sizes)
      {
        std::vector<float> xyz = random_points(rng, np, -0.1, 1.1);
        // First fill the device buffers with a scene's results, then
        // classify against no body at all: a point the kernel skipped would
        // keep a stale body index or distance.
        std::vector<int>   f(np, 0x5a5a5a5a), fc(np);
        std::vector<float> d(np, poison), dc(np);
        gpu.classify(xyz.data(),
                     np,
                     bodies.data(),
                     bodies.size(),
                     f.data(),
                     d.data());
        cpu.classify(xyz.data(),
                     np,
                     bodies.data(),
                     bodies.size(),
                     fc.data(),
                     dc.data());
        std::size_t bad = 0;
        for (std::size_t p = 0; p < np; ++p)
          bad += f[p] != fc[p] || std::memcmp(&d[p], &dc[p], 4) != 0;
        std::fill(f.begin(), f.end(), 0x5a5a5a5a);
        std::fill(d.begin(), d.end(), poison);
        gpu.classify(xyz.data(), np, nullptr, 0, f.data(), d.data());
        std::size_t stale = 0;
        for (std::size_t p = 0; p < np; ++p)
          stale += f[p] != -1 || d[p] != inf;
        PARTICULATE_CHECK(
          bad == 0 && stale == 0,
          "n = %zu: %zu points differ from the CPU, %zu not overwritten",
          np,
          bad,
          stale);
      }
    std::printf(
      "  n = 1, 255, 256, 257, 1000, 131071, 131073, 2^20+3: host poison and stale "
      "device results all overwritten, equal to the CPU\n");

    // Pinned host memory gives the same answers as pageable memory.
    const std::size_t  np  = 300007;
    std::vector<float> xyz = random_points(rng, np, -0.1, 1.1);
    std::vector<int>   f(np, 0x5a5a5a5a), fc(np);
    std::vector<float> d(np, poison), dc(np);
    gpu.pin_host_memory(xyz.data(), xyz.size() * sizeof(float));
    gpu.pin_host_memory(f.data(), f.size() * sizeof(int));
    gpu.pin_host_memory(d.data(), d.size() * sizeof(float));
    gpu.classify(xyz.data(),
                 np,
                 bodies.data(),
                 bodies.size(),
                 f.data(),
                 d.data());
    gpu.unpin_host_memory(xyz.data());
    gpu.unpin_host_memory(f.data());
    gpu.unpin_host_memory(d.data());
    cpu.classify(xyz.data(),
                 np,
                 bodies.data(),
                 bodies.size(),
                 fc.data(),
                 dc.data());
    std::size_t bad = 0;
    for (std::size_t p = 0; p < np; ++p)
      bad += f[p] != fc[p] || std::memcmp(&d[p], &dc[p], 4) != 0;
    PARTICULATE_CHECK(bad == 0, "pinned buffers: %zu points differ", bad);
    std::printf("  pinned host buffers: identical to the CPU path\n");
  }

  /** A failing CUDA call surfaces as an exception naming the call. */
  void
  test_errors(ContainmentEngine &gpu)
  {
    try
      {
        int x = 0;
        gpu.unpin_host_memory(&x); // never registered
        PARTICULATE_CHECK(false, "unpinning unregistered memory did not throw");
      }
    catch (const std::runtime_error &e)
      {
        std::printf("  failing CUDA call -> %s\n", e.what());
        PARTICULATE_CHECK(std::strstr(e.what(), "cudaHostUnregister")
                            != nullptr,
                          "message does not name the call: %s",
                          e.what());
      }
  }
} // namespace

int
main()
{
  if (!ContainmentEngine::cuda_compiled())
    {
      std::printf("SKIPPED: particulate_containment was built without CUDA\n");
      return 77;
    }
  if (!ContainmentEngine::cuda_device_available())
    {
      std::printf("SKIPPED: no CUDA device visible\n");
      return 77;
    }
  try
    {
      ContainmentEngine gpu(Backend::cuda), cpu(Backend::cpu);
      std::printf("particulate containment, GPU vs CPU on %s (CPU: %s)\n",
                  gpu.device_name().c_str(),
                  cpu.device_name().c_str());
      std::mt19937              rng(2024);
      std::vector<TestShape>    shapes;
      std::vector<BodyInstance> unused;
      mixed_scene(rng, 1, 0.08, shapes, unused);
      // Larger shapes for the single-body scenes make most points meet them.
      std::vector<TestShape>    big;
      std::vector<BodyInstance> unused2;
      mixed_scene(rng, 1, 0.3, big, unused2);
      upload(gpu, big);
      upload(cpu, big);
      std::printf("random points and poses (shapes of half-size 0.3)\n");
      test_random_scenes(gpu, cpu, big, rng);
      ContainmentEngine gpu2(Backend::cuda), cpu2(Backend::cpu);
      upload(gpu2, shapes);
      upload(cpu2, shapes);
      std::printf("random points and poses (shapes of half-size 0.08)\n");
      test_random_scenes(gpu2, cpu2, shapes, rng);
      std::printf("output coverage and sizes\n");
      test_poison_and_sizes(gpu2, cpu2, shapes, rng);
      std::printf("error reporting\n");
      test_errors(gpu2);
    }
  catch (const std::exception &e)
    {
      std::printf("FAILED with exception: %s\n", e.what());
      return 1;
    }
  std::printf(failures() == 0 ? "all GPU containment checks passed\n" :
                                "%d GPU containment checks FAILED\n",
              failures());
  return failures() == 0 ? 0 : 1;
}
