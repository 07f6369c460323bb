// CPU path of the containment library (label unit): interpolated distances
// and flags against closed-form signed distances, the culling grids against a
// brute-force reference with identical arithmetic, output coverage, odd sizes
// and input validation.
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

  /**
   * One distance-map body at a random pose: distances within the trilinear
   * interpolation error of the analytic SDF, flags equal to the sign of the
   * analytic SDF outside a band of that error, everything outside the map's
   * box outside.
   */
  void
  single_map_against_analytic(const char  *name,
                              const Sdf   &sdf,
                              const double half,
                              const int    n,
                              const double dist_tol, // < 0: only flags
                              const double min_radius)
  {
    std::mt19937          rng(11);
    ContainmentEngine     engine(Backend::cpu, 2);
    const DistanceMapData map = sample_map(sdf, half, n);
    const int             h   = engine.add_distance_map(map);
    const double          sp  = map.spacing[0];
    // Any 1-Lipschitz function differs from its trilinear interpolant by at
    // most the distance to the farthest cell corner, sqrt(3) h.
    const double band = std::sqrt(3.) * sp + 1e-5;

    std::size_t inside = 0, checked = 0;
    for (int trial = 0; trial < 4; ++trial)
      {
        BodyInstance body;
        body.shape = h;
        random_rotation(rng, body.R);
        for (int a = 0; a < 3; ++a)
          body.t[a] = float(
            0.3 + 0.4 * std::uniform_real_distribution<double>(0, 1)(rng));
        const std::size_t  np  = 60000;
        std::vector<float> xyz = random_points(rng, np, 0., 1.);
        std::vector<int>   first(np, 7);
        std::vector<float> dist(np, 7.f);
        engine.classify(xyz.data(), np, &body, 1, first.data(), dist.data());
        for (std::size_t p = 0; p < np; ++p)
          {
            const double x[3] = {xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]};
            double       xb[3];
            to_body_double(body, x, xb);
            double out = 0.; // how far outside the map box (<= 0: inside)
            for (int a = 0; a < 3; ++a)
              out = std::max({out, -half - xb[a], xb[a] - half});
            bool in_box = true;
            for (int a = 0; a < 3; ++a)
              in_box = in_box && std::abs(xb[a]) < half - 1e-5;
            if (out > 1e-5)
              {
                PARTICULATE_CHECK(
                  first[p] == -1 && dist[p] == inf,
                  "%s: point %zu outside the map box got first=%d dist=%g",
                  name,
                  p,
                  first[p],
                  dist[p]);
                continue;
              }
            if (!in_box)
              continue; // within rounding of the box faces
            ++checked;
            const double exact = sdf(xb[0], xb[1], xb[2]);
            if (dist_tol > 0.
                && std::sqrt(xb[0] * xb[0] + xb[1] * xb[1] + xb[2] * xb[2])
                     >= min_radius)
              PARTICULATE_CHECK(std::abs(dist[p] - exact) <= dist_tol,
                                "%s: distance %g vs analytic %g (tolerance %g)",
                                name,
                                dist[p],
                                exact,
                                dist_tol);
            PARTICULATE_CHECK(std::abs(dist[p] - exact) <= band,
                              "%s: distance %g vs analytic %g beyond sqrt(3) h",
                              name,
                              dist[p],
                              exact);
            if (exact <= -band)
              PARTICULATE_CHECK(first[p] == 0,
                                "%s: point %zu deep inside not flagged",
                                name,
                                p);
            if (exact >= band)
              PARTICULATE_CHECK(first[p] == -1,
                                "%s: point %zu far outside flagged",
                                name,
                                p);
            PARTICULATE_CHECK((first[p] == 0) == (dist[p] <= 0.f),
                              "%s: flag and distance sign disagree",
                              name);
            inside += first[p] == 0;
          }
      }
    PARTICULATE_CHECK(inside > 1000 && checked > 10000,
                      "%s: too few points tested (%zu inside of %zu)",
                      name,
                      inside,
                      checked);
    std::printf(
      "  %-6s map %d^3, h = %.4f: %zu points in the box, %zu inside\n",
      name,
      n,
      sp,
      checked,
      inside);
  }

  void
  test_analytic_maps()
  {
    std::printf("distance maps against analytic signed distances\n");
    // |x| - R has second derivatives <= 1/|x|: trilinear error <= 3 h^2 / (8
    // |x|).
    const double R = 0.3, half = 0.45;
    const int    n = 61;
    const double h = 2. * half / (n - 1);
    single_map_against_analytic("sphere",
                                sphere_sdf(R),
                                half,
                                n,
                                3. * h * h / (8. * 0.15) + 2e-6,
                                0.15);
    single_map_against_analytic("torus",
                                torus_sdf(0.25, 0.1),
                                0.4,
                                49,
                                -1.,
                                0.);
    single_map_against_analytic("box",
                                box_sdf(0.3, 0.2, 0.1),
                                0.4,
                                33,
                                -1.,
                                0.);
  }

  /** Grid nodes reproduce the stored samples exactly; the box is closed. */
  void
  test_nodes_and_box_edges()
  {
    std::printf("grid nodes and box edges\n");
    ContainmentEngine engine(Backend::cpu, 1);
    DistanceMapData   map = sample_map(torus_sdf(0.25, 0.1), 0.4, 17);
    const int         h   = engine.add_distance_map(map);
    BodyInstance      body;
    body.shape = h;
    std::vector<float> xyz;
    std::vector<float> expected;
    for (int k = 0; k < 16; ++k) // the last layer uses fraction 1: not exact
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i)
          {
            // Node coordinates recomputed the way the map defines them.
            xyz.push_back(map.origin[0] + i * map.spacing[0]);
            xyz.push_back(map.origin[1] + j * map.spacing[1]);
            xyz.push_back(map.origin[2] + k * map.spacing[2]);
            expected.push_back(map.values[i + 17 * (j + 17 * k)]);
          }
    const std::size_t  np = expected.size();
    std::vector<int>   first(np);
    std::vector<float> dist(np);
    engine.classify(xyz.data(), np, &body, 1, first.data(), dist.data());
    // The index u = (x - o) / h is not exactly i for every node because of
    // rounding; where it is, the value must be the sample itself.
    std::size_t exact = 0;
    for (std::size_t p = 0; p < np; ++p)
      {
        PARTICULATE_CHECK(std::abs(dist[p] - expected[p]) <= 1e-5f,
                          "node %zu: %g vs sample %g",
                          p,
                          dist[p],
                          expected[p]);
        exact += dist[p] == expected[p];
      }
    PARTICULATE_CHECK(exact > np / 2,
                      "only %zu of %zu nodes reproduced exactly",
                      exact,
                      np);

    // A map that is negative everywhere: inside its box, outside beyond it,
    // however negative the values (no extrapolation).
    DistanceMapData all_in;
    all_in.nx = all_in.ny = all_in.nz = 3;
    for (int a = 0; a < 3; ++a)
      {
        all_in.origin[a]  = 0.f;
        all_in.spacing[a] = 0.5f;
      }
    all_in.values.assign(27, -1.f);
    BodyInstance b2;
    b2.shape               = engine.add_distance_map(all_in);
    const float        nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> pts
      = {0.f,  0.f,  0.f,     1.f,  1.f, 1.f,  0.5f, 0.25f, 0.75f, -1e-4f, 0.5f,
         0.5f, 0.5f, 1.0001f, 0.5f, nan, 0.5f, 0.5f, 5.f,   5.f,   5.f};
    std::vector<int>   f(7);
    std::vector<float> d(7);
    engine.classify(pts.data(), 7, &b2, 1, f.data(), d.data());
    const int   fe[7] = {0, 0, 0, -1, -1, -1, -1};
    const float de[7] = {-1.f, -1.f, -1.f, inf, inf, inf, inf};
    for (int p = 0; p < 7; ++p)
      PARTICULATE_CHECK(f[p] == fe[p] && d[p] == de[p],
                        "box edge point %d: first=%d dist=%g, expected %d %g",
                        p,
                        f[p],
                        d[p],
                        fe[p],
                        de[p]);
  }

  /** 100 mixed bodies: grids vs brute force, bit for bit. */
  void
  test_culling_exact()
  {
    std::printf("100 mixed bodies: culling grids against brute force\n");
    std::mt19937              rng(5);
    std::vector<TestShape>    shapes;
    std::vector<BodyInstance> bodies;
    mixed_scene(rng, 100, 0.08, shapes, bodies);
    ContainmentEngine engine(Backend::cpu, 2);
    upload(engine, shapes);
    const std::size_t  np  = 150001;
    std::vector<float> xyz = random_points(rng, np, -0.1, 1.1);
    std::vector<int>   first(np), ref_first, first_only(np);
    std::vector<float> dist(np), ref_dist;
    engine.classify(xyz.data(),
                    np,
                    bodies.data(),
                    bodies.size(),
                    first.data(),
                    dist.data());
    engine.classify(xyz.data(),
                    np,
                    bodies.data(),
                    bodies.size(),
                    first_only.data(),
                    nullptr);
    reference_classify(shapes, bodies, xyz, ref_first, ref_dist);
    std::size_t bad_f = 0, bad_d = 0, bad_fo = 0, inside = 0, finite_d = 0;
    for (std::size_t p = 0; p < np; ++p)
      {
        bad_f += first[p] != ref_first[p];
        bad_fo += first_only[p] != ref_first[p];
        bad_d += std::memcmp(&dist[p], &ref_dist[p], sizeof(float)) != 0;
        inside += first[p] >= 0;
        finite_d += dist[p] != inf;
      }
    PARTICULATE_CHECK(
      bad_f == 0 && bad_fo == 0 && bad_d == 0,
      "%zu flags, %zu flags (no distance), %zu distances differ",
      bad_f,
      bad_fo,
      bad_d);
    PARTICULATE_CHECK(inside > np / 50,
                      "only %zu points inside a body",
                      inside);
    std::printf("  %zu points, %zu inside a body, %zu within a map box: %s\n",
                np,
                inside,
                finite_d,
                bad_f + bad_fo + bad_d == 0 ? "identical to brute force" :
                                              "DIFFERENT");
  }

  /** Inner spheres: grid vs brute force; carved spheres lie inside the body. */
  void
  test_spheres()
  {
    std::printf("inner spheres\n");
    std::mt19937           rng(7);
    std::vector<TestShape> shapes(2);
    shapes[0].is_map  = false;
    shapes[0].spheres = random_sphere_pack(rng, 2000, 0.3, 0.002, 0.08);
    shapes[1].is_map  = false;
    const Sdf torus   = torus_sdf(0.25, 0.1);
    shapes[1].spheres = carve_spheres(torus, 0.4, 0.01);
    ContainmentEngine engine(Backend::cpu, 2);
    upload(engine, shapes);
    for (int s = 0; s < 2; ++s)
      {
        std::vector<BodyInstance> bodies(1);
        bodies[0].shape = s;
        random_rotation(rng, bodies[0].R);
        bodies[0].t[0] = bodies[0].t[1] = bodies[0].t[2] = 0.5f;
        const std::size_t  np                            = 100000;
        std::vector<float> xyz = random_points(rng, np, 0.05, 0.95);
        std::vector<int>   first(np, 3), ref_first;
        std::vector<float> dist(np, 3.f), ref_dist;
        engine.classify(xyz.data(),
                        np,
                        bodies.data(),
                        1,
                        first.data(),
                        dist.data());
        reference_classify(shapes, bodies, xyz, ref_first, ref_dist);
        std::size_t bad = 0, inside = 0, outside_torus = 0;
        for (std::size_t p = 0; p < np; ++p)
          {
            bad += first[p] != ref_first[p];
            PARTICULATE_CHECK(dist[p] == inf,
                              "sphere bodies contribute no distance");
            inside += first[p] == 0;
            if (s == 1 && first[p] == 0)
              {
                const double x[3]
                  = {xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]};
                double xb[3];
                to_body_double(bodies[0], x, xb);
                outside_torus += torus(xb[0], xb[1], xb[2]) > 1e-5;
              }
          }
        PARTICULATE_CHECK(bad == 0,
                          "sphere set %d: %zu flags differ from brute force",
                          s,
                          bad);
        PARTICULATE_CHECK(outside_torus == 0,
                          "%zu points flagged outside the torus",
                          outside_torus);
        PARTICULATE_CHECK(inside > 1000,
                          "sphere set %d: only %zu inside",
                          s,
                          inside);
        std::printf("  set %d: %zu spheres, %zu of %zu points inside, %s\n",
                    s,
                    shapes[s].spheres.r.size(),
                    inside,
                    np,
                    bad == 0 ? "identical to brute force" : "DIFFERENT");
      }
  }

  /** Poisoned outputs are overwritten, for odd sizes and thread counts. */
  void
  test_poison_and_sizes()
  {
    std::printf("poisoned outputs, odd sizes, thread counts\n");
    std::mt19937              rng(3);
    std::vector<TestShape>    shapes;
    std::vector<BodyInstance> bodies;
    mixed_scene(rng, 20, 0.15, shapes, bodies);
    ContainmentEngine one(Backend::cpu, 1), many(Backend::cpu, 3);
    upload(one, shapes);
    upload(many, shapes);
    const std::uint32_t poison_bits
      = 0x7fbadbadu; // a NaN no computation yields
    float poison;
    std::memcpy(&poison, &poison_bits, 4);
    for (const std::size_t np : {std::size_t(0),
                                 std::size_t(1),
                                 std::size_t(255),
                                 std::size_t(257),
                                 std::size_t(4097),
                                 std::size_t(100003)})
      {
        std::vector<float> xyz = random_points(rng, np, -0.2, 1.2);
        std::vector<int>   f1(np, 0x5a5a5a5a), f2(np, 0x5a5a5a5a);
        std::vector<float> d1(np, poison), d2(np, poison);
        one.classify(xyz.data(),
                     np,
                     bodies.data(),
                     bodies.size(),
                     f1.data(),
                     d1.data());
        many.classify(xyz.data(),
                      np,
                      bodies.data(),
                      bodies.size(),
                      f2.data(),
                      d2.data());
        std::size_t left = 0, differ = 0;
        for (std::size_t p = 0; p < np; ++p)
          {
            left += !(f1[p] >= -1 && f1[p] < 20)
                    || std::memcmp(&d1[p], &poison_bits, 4) == 0;
            differ += f1[p] != f2[p] || std::memcmp(&d1[p], &d2[p], 4) != 0;
          }
        PARTICULATE_CHECK(
          left == 0 && differ == 0,
          "n = %zu: %zu outputs left poisoned, %zu differ between 1 and 3 threads",
          np,
          left,
          differ);
      }
    std::printf(
      "  n = 0, 1, 255, 257, 4097, 100003: all outputs written, 1 thread == 3 threads\n");
  }

  template <typename Exception, typename F>
  void
  expect_throw(const char *what, F f)
  {
    try
      {
        f();
        PARTICULATE_CHECK(false, "%s did not throw", what);
      }
    catch (const Exception &e)
      {
        std::printf("  %s -> %s\n", what, e.what());
      }
  }

  void
  test_bad_input()
  {
    std::printf("input validation\n");
    ContainmentEngine engine(Backend::cpu);
    DistanceMapData   m = sample_map(sphere_sdf(0.2), 0.3, 5);
    const int         h = engine.add_distance_map(m);
    expect_throw<std::invalid_argument>("values of the wrong length", [&] {
      DistanceMapData bad = m;
      bad.values.pop_back();
      engine.add_distance_map(bad);
    });
    expect_throw<std::invalid_argument>("zero spacing", [&] {
      DistanceMapData bad = m;
      bad.spacing[1]      = 0.f;
      engine.add_distance_map(bad);
    });
    expect_throw<std::invalid_argument>("a NaN sample", [&] {
      DistanceMapData bad = m;
      bad.values[3]       = std::numeric_limits<float>::quiet_NaN();
      engine.add_distance_map(bad);
    });
    expect_throw<std::invalid_argument>("a negative radius", [&] {
      InnerSphereData s;
      s.cx = s.cy = s.cz = {0.f};
      s.r                = {-1.f};
      engine.add_inner_spheres(s);
    });
    expect_throw<std::invalid_argument>("sphere arrays of unequal length", [&] {
      InnerSphereData s;
      s.cx = s.cy = {0.f};
      s.cz        = {0.f, 1.f};
      s.r         = {1.f};
      engine.add_inner_spheres(s);
    });
    float        p[3] = {0.f, 0.f, 0.f};
    int          f;
    float        d;
    BodyInstance b;
    b.shape = h + 5;
    expect_throw<std::invalid_argument>("an unknown shape handle", [&] {
      engine.classify(p, 1, &b, 1, &f, &d);
    });
    b.shape = h;
    b.R[0]  = 2.f;
    expect_throw<std::invalid_argument>("a scaled rotation", [&] {
      engine.classify(p, 1, &b, 1, &f, &d);
    });
    b.R[0] = 1.f;
    expect_throw<std::invalid_argument>("no output buffer", [&] {
      engine.classify(p, 1, &b, 1, nullptr, nullptr);
    });
    engine.classify(p, 1, &b, 1, &f, &d);
    PARTICULATE_CHECK(f == 0 && std::abs(d + 0.2f) < 1e-6f,
                      "centre of the sphere: %d %g",
                      f,
                      d);
    // No bodies: every point outside.
    engine.classify(p, 1, nullptr, 0, &f, &d);
    PARTICULATE_CHECK(f == -1 && d == inf, "empty scene: %d %g", f, d);

    if (!ContainmentEngine::cuda_device_available())
      {
        expect_throw<std::runtime_error>("Backend::cuda without a device", [&] {
          ContainmentEngine e(Backend::cuda);
        });
        ContainmentEngine a(Backend::automatic);
        PARTICULATE_CHECK(a.backend() == Backend::cpu,
                          "automatic without a device must be cpu");
      }
  }
} // namespace

int
main()
{
  try
    {
      std::printf("particulate containment, CPU path (CUDA compiled: %s)\n",
                  ContainmentEngine::cuda_compiled() ? "yes" : "no");
      test_analytic_maps();
      test_nodes_and_box_edges();
      test_culling_exact();
      test_spheres();
      test_poison_and_sizes();
      test_bad_input();
    }
  catch (const std::exception &e)
    {
      std::printf("FAILED with exception: %s\n", e.what());
      return 1;
    }
  std::printf(failures() == 0 ? "all CPU containment checks passed\n" :
                                "%d CPU containment checks FAILED\n",
              failures());
  return failures() == 0 ? 0 : 1;
}
