// Broad-phase scaling (issue 3): hierarchical hash grid against all-pairs
// and CGAL's box_intersection_d on identical scenes of n spheres, n = 1e3 ..
// 1e6, radii log-uniform over a factor 10, 10 % solid volume fraction.
// Reports: full build + query, incremental update (every sphere moved by
// 1 % of its radius) + query, all-pairs (n <= 3e4) and CGAL (boxes of the
// spheres, then the exact sphere test) in ms of thread CPU time, and the
// pairs found.
// Usage: bench_rigid_broad_phase [max_n]
#include <particulate/rigid/all_pairs_broad_phase.h>
#include <particulate/rigid/hierarchical_hash_grid.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <vector>

#ifdef PARTICULATE_BENCH_WITH_CGAL
#  include <CGAL/box_intersection_d.h>
#endif

using namespace particulate::rigid;
namespace {
  // CPU time of this thread in ms: robust on a shared machine, where wall
  // time also counts the other processes.
  struct Clock
  {
    static double
    now()
    {
      timespec t;
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
      return 1.e3 * t.tv_sec + 1.e-6 * t.tv_nsec;
    }
  };
  double
  ms_since(const double t0)
  {
    return Clock::now() - t0;
  }
} // namespace

int
main(int argc, char **argv)
{
  const unsigned long max_n = argc > 1 ? std::atol(argv[1]) : 1000000;
  std::printf(
    "| n | hash grid build+query (ms) | incremental update+query (ms) | ns per body | "
    "all-pairs (ms) | CGAL box_intersection_d (ms) | pairs |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (unsigned long n = 1000; n <= max_n; n *= 10)
    for (const unsigned long m : {n, 3 * n})
      {
        if (m > max_n || (m == 3 * n && n >= 1000000))
          continue;
        std::mt19937                           rng(1);
        std::uniform_real_distribution<double> u(0., 1.);
        const double                           rmin = 0.01, ratio = 10.;
        std::vector<BroadPhaseProxy>           p(m);
        double                                 vol = 0.;
        for (auto &x : p)
          {
            x.radius = rmin * std::pow(ratio, u(rng));
            vol += 4. / 3. * M_PI * std::pow(x.radius, 3);
          }
        const double L = std::cbrt(vol / 0.1);
        for (auto &x : p)
          x.center = L * Eigen::Vector3d(u(rng), u(rng), u(rng));

        HierarchicalHashGrid  grid;
        std::vector<BodyPair> pairs;
        auto                  t0 = Clock::now();
        grid.update(p);
        grid.find_pairs(pairs);
        const double t_build = ms_since(t0);
        for (auto &x : p)
          x.center += 0.01 * x.radius
                      * Eigen::Vector3d(2. * u(rng) - 1.,
                                        2. * u(rng) - 1.,
                                        2. * u(rng) - 1.);
        t0 = Clock::now();
        grid.update(p);
        grid.find_pairs(pairs);
        const double t_incr = ms_since(t0);

        double t_all = -1.;
        if (m <= 30000)
          {
            AllPairsBroadPhase    ref;
            std::vector<BodyPair> rp;
            t0 = Clock::now();
            ref.update(p);
            ref.find_pairs(rp);
            t_all = ms_since(t0);
            if (rp.size() != pairs.size())
              {
                std::printf("pair count mismatch: %zu vs %zu\n",
                            rp.size(),
                            pairs.size());
                return 1;
              }
          }
        double t_cgal = -1.;
#ifdef PARTICULATE_BENCH_WITH_CGAL
        {
          using Box = CGAL::Box_intersection_d::
            Box_with_handle_d<double, 3, const BroadPhaseProxy *>;
          t0 = Clock::now();
          std::vector<Box> boxes;
          boxes.reserve(m);
          for (const auto &x : p)
            {
              double lo[3], hi[3];
              for (int k = 0; k < 3; ++k)
                {
                  lo[k] = x.center[k] - x.radius;
                  hi[k] = x.center[k] + x.radius;
                }
              boxes.emplace_back(lo, hi, &x);
            }
          std::size_t found = 0;
          CGAL::box_self_intersection_d(boxes.begin(),
                                        boxes.end(),
                                        [&](const Box &a, const Box &b) {
                                          if (proxies_overlap(*a.handle(),
                                                              *b.handle()))
                                            ++found;
                                        });
          t_cgal = ms_since(t0);
          if (found != pairs.size())
            {
              std::printf("CGAL pair count mismatch: %zu vs %zu\n",
                          found,
                          pairs.size());
              return 1;
            }
        }
#endif
        auto cell = [](double t) {
          static char buf[4][32];
          static int  k = 0;
          k             = (k + 1) % 4;
          if (t < 0.)
            std::snprintf(buf[k], 32, "-");
          else
            std::snprintf(buf[k], 32, "%.2f", t);
          return buf[k];
        };
        std::printf("| %lu | %.2f | %.2f | %.0f | %s | %s | %zu |\n",
                    m,
                    t_build,
                    t_incr,
                    1.e6 * t_incr / m,
                    cell(t_all),
                    cell(t_cgal),
                    pairs.size());
        std::fflush(stdout);
      }
  return 0;
}
