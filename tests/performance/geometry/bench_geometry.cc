// Geometry benchmark (issue 4): distance-map lookup against CGAL's direct
// queries, map build time against mesh size, and hash-grid point
// containment on 33^3 / 65^3 / 129^3 vertex lattices against 1 and 100
// bodies; and (issue 44) the containment of 1 to 1 000 mesh bodies
// (MappedSurface) on 65^3 / 129^3 lattices, per call, node and body.
// Prints tables; asserts nothing about time.
// Usage: bench_geometry [quick] [lookups|mesh-bodies]   ("quick": smaller
// sizes, for smoke runs; "lookups": only the lookup table; "mesh-bodies":
// only the mesh-body containment table)
#include <particulate/geometry/box.h>
#include <particulate/geometry/distance_map.h>
#include <particulate/geometry/distance_map_shape.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/mesh_body.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/mesh_io.h>
#include <particulate/geometry/point_containment.h>
#include <particulate/geometry/sphere.h>
#include <particulate/geometry/triangulated_surface.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <random>
#include <string>

#include "../geodesic_ellipsoid.h"

using namespace particulate::geometry;
using Eigen::Vector3d;
using Clock = std::chrono::steady_clock;

namespace {
  double
  seconds_since(const Clock::time_point t0)
  {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  }

  // The n^3 vertices of a uniform lattice of the unit cube.
  std::vector<Vector3d>
  unit_cube_lattice(const int n)
  {
    std::vector<Vector3d> pts;
    pts.reserve(std::size_t(n) * n * n);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          pts.emplace_back(i / double(n - 1),
                           j / double(n - 1),
                           k / double(n - 1));
    return pts;
  }

  // Keeps results alive so the compiler cannot drop the timed loops.
  volatile double sink = 0.;

  // Median of @p repeats timings of @p f [s]: one pass can be inflated by
  // another process on the shared cores.
  template <typename F>
  double
  median_seconds(const int repeats, F &&f)
  {
    std::vector<double> t(repeats);
    for (double &x : t)
      {
        const auto t0 = Clock::now();
        f();
        x = seconds_since(t0);
      }
    std::nth_element(t.begin(), t.begin() + repeats / 2, t.end());
    return t[repeats / 2];
  }

  void
  lookups(const std::string &name, const TriangleMesh &mesh, const int n)
  {
    const TriangulatedSurface surface(mesh);
    const double              h = mesh.bounding_box().extent().maxCoeff() / 64.;
    const DistanceMap         map = DistanceMap::build(surface, {h, 4 * h, 1});
    std::mt19937              rng(3);
    std::uniform_real_distribution<double> u(0., 1.);
    const BoundingBox                      box = map.grid_box();
    std::vector<Vector3d>                  pts(n);
    for (auto &p : pts)
      p = box.lower
          + box.extent().cwiseProduct(Vector3d(u(rng), u(rng), u(rng)));

    // ns per query, one call per point in the order of pts (first @p count).
    auto time_per_query = [&](auto &&f, int count, int repeats) {
      return median_seconds(repeats,
                            [&] {
                              double acc = 0.;
                              for (int i = 0; i < count; ++i)
                                acc += f(pts[i]);
                              sink = sink + acc;
                            })
             / count * 1e9;
    };
    // ns per query, all of pts in one batched call.
    std::vector<double>   out(n);
    std::vector<Vector3d> nrm_out(n);
    auto                  time_batch = [&](bool with_normals) {
      return median_seconds(5,
                            [&] {
                              map.distances(pts.data(),
                                            pts.size(),
                                            out.data(),
                                            with_normals ? nrm_out.data() :
                                                                            nullptr);
                              sink = sink + out[n / 2] + nrm_out[n / 3][0];
                            })
             / n * 1e9;
    };
    auto d   = [&](const Vector3d &p) { return map.distance(p); };
    auto d_n = [&](const Vector3d &p) {
      Vector3d nrm;
      return map.distance(p, &nrm) + nrm[0];
    };
    // Random order (cache-miss bound for large grids); the first pass of each
    // median is the warm-up ...
    const double t_map     = time_per_query(d, n, 5);
    const double t_map_n   = time_per_query(d_n, n, 5);
    const double t_batch   = time_batch(false);
    const double t_batch_n = time_batch(true);
    // ... and in a coherent order (sorted by grid cell, as mesh vertices
    // numbered cell by cell come).
    std::vector<Vector3d> sorted  = pts;
    auto                  cell_of = [&](const Vector3d &p) {
      const Vector3d s = (p - box.lower) / h;
      return (long(s[2]) * 4096 + long(s[1])) * 4096 + long(s[0]);
    };
    std::sort(sorted.begin(),
              sorted.end(),
              [&](const Vector3d &a, const Vector3d &b) {
                return cell_of(a) < cell_of(b);
              });
    std::swap(pts, sorted);
    const double t_sorted       = time_per_query(d, n, 5);
    const double t_batch_sorted = time_batch(false);
    std::swap(pts, sorted);
    // CGAL in random order: its cost does not depend on the order (each
    // query descends the tree from the root).
    const int    m      = std::max(1000, n / 10);
    const double t_cgal = time_per_query(
      [&](const Vector3d &p) { return surface.unsigned_distance(p); },
      m,
      3);
    const double t_signed = time_per_query(
      [&](const Vector3d &p) { return surface.signed_distance(p); },
      m,
      3);
    const double t_side = time_per_query(
      [&](const Vector3d &p) { return double(surface.contains(p)); },
      m,
      3);
    std::printf(
      "| %-14s | %9zu | %3d x %3d x %3d | %6.1f | %6.1f | %6.1f | %6.1f | %6.1f | %6.1f | %9.0f | %9.0f | %9.0f | %5.0f | %5.0f | %5.0f | %5.0f |\n",
      name.c_str(),
      mesh.n_triangles(),
      map.n_points()[0],
      map.n_points()[1],
      map.n_points()[2],
      t_map,
      t_sorted,
      t_batch,
      t_batch_sorted,
      t_map_n,
      t_batch_n,
      t_cgal,
      t_signed,
      t_side,
      t_cgal / t_map,
      t_cgal / t_sorted,
      t_cgal / t_batch,
      t_cgal / t_batch_sorted);
  }

  void
  build_time(const std::string &name, const TriangleMesh &mesh, const int cells)
  {
    const double h  = mesh.bounding_box().extent().maxCoeff() / cells;
    const auto   t0 = Clock::now();
    const TriangulatedSurface surface(mesh);
    const double              t_tree = seconds_since(t0);
    const auto                t1     = Clock::now();
    const DistanceMap         map = DistanceMap::build(surface, {h, 4 * h, 1});
    const double              t_map = seconds_since(t1);
    const double              np
      = double(map.n_points()[0]) * map.n_points()[1] * map.n_points()[2];
    std::printf("| %-14s | %9zu | %9.0f | %8.3f | %8.2f | %9.2f |\n",
                name.c_str(),
                mesh.n_triangles(),
                np,
                t_tree,
                t_map,
                t_map / np * 1e6);
  }

  // A distance-map shape that answers many points one contains() call at a
  // time (Shape's default contains_points): the containment before the
  // batched path, to compare with.
  class OneByOne : public Shape
  {
  public:
    explicit OneByOne(const Shape &s)
      : s(s)
    {}
    std::string
    name() const override
    {
      return s.name();
    }
    double
    signed_distance(const Vector3d &p, Vector3d *normal) const override
    {
      return s.signed_distance(p, normal);
    }
    bool
    contains(const Vector3d &p) const override
    {
      return s.contains(p);
    }
    BoundingBox
    bounding_box() const override
    {
      return s.bounding_box();
    }
    double
    volume() const override
    {
      return s.volume();
    }

  private:
    const Shape &s;
  };

  void
  containment(const int                       n,
              const char                     *label,
              const std::vector<PlacedShape> &bodies,
              const bool                      brute)
  {
    const std::vector<Vector3d> pts = unit_cube_lattice(n);
    const auto                  t0  = Clock::now();
    const PointHashGrid         grid(pts);
    const double                t_grid = seconds_since(t0);
    ContainmentStatistics       stats;
    std::vector<int>            fast;
    const double                t_fast = median_seconds(5, [&] {
      fast = classify_points(grid, bodies, nullptr, &stats);
    });
    double                      t_slow = 0.;
    bool                        same   = true;
    if (brute)
      {
        const auto t2   = Clock::now();
        const auto slow = classify_points_brute_force(pts, bodies);
        t_slow          = seconds_since(t2);
        same            = slow == fast;
      }
    std::size_t inside = 0;
    for (const int b : fast)
      inside += b >= 0;
    char brute_s[32] = "-", speedup[32] = "-";
    if (brute)
      {
        std::snprintf(brute_s, sizeof(brute_s), "%.4f", t_slow);
        std::snprintf(speedup, sizeof(speedup), "%.0f", t_slow / t_fast);
      }
    std::printf(
      "| %4d^3 | %-28s | %8zu | %8.4f | %8.5f | %9s | %7s | %8.5f | %8.5f | %5s |\n",
      n,
      label,
      inside,
      t_grid,
      t_fast,
      brute_s,
      speedup,
      double(stats.n_points_touched) / pts.size(),
      double(stats.n_tests) / (double(pts.size()) * bodies.size()),
      brute ? (same ? "yes" : "NO") : "-");
  }

  // Median of 5 samples of the CPU time of this thread for one call of
  // @p f [s], each sample repeating f often enough to last 2 ms: robust
  // against other processes on the shared cores, and resolving calls of a
  // few microseconds.
  template <typename F>
  double
  median_cpu_seconds(F &&f)
  {
    auto cpu = [] {
      timespec t;
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
      return t.tv_sec + 1.e-9 * t.tv_nsec;
    };
    f(); // warm-up
    unsigned int calls = 1;
    for (;;)
      {
        const double t0 = cpu();
        for (unsigned int i = 0; i < calls; ++i)
          f();
        if (cpu() - t0 >= 2.e-3)
          break;
        calls *= 2;
      }
    std::vector<double> t(5);
    for (double &x : t)
      {
        const double t0 = cpu();
        for (unsigned int i = 0; i < calls; ++i)
          f();
        x = (cpu() - t0) / calls;
      }
    std::nth_element(t.begin(), t.begin() + 2, t.end());
    return t[2];
  }

  // One step's containment of mesh bodies against a lattice of nodes, by
  // body count (issue 44). The bodies: one MappedSurface (make_mesh_body:
  // the exact polyhedron and its distance map at the automatic spacing) of a
  // geodesic ellipsoid mesh with semi-axes (35, 24.5, 17.5) mm, 2 000
  // triangles, at 1 000 random poses (random orientations, centres at least
  // 2 a = 70 mm apart, so that their circumscribed spheres do not overlap)
  // in the unit cube; the first 1, 10, 100, 1 000 of them. Two ways of
  // marking the nodes:
  // - classify_points (point_containment.h): the hash grid's candidates per
  //   body box, answered in groups by MappedSurface::contains_points;
  // - "FBM loop": what fbm::FictitiousBoundary::classify does on the CPU
  //   (the application's cpu containment backend, 'inside' marking): the
  //   same hash-grid candidates, those in the body's own box asked for
  //   their signed distance, a node inside when its distance is <= 1e-10
  //   of its half spacing.
  // The hash grid over the nodes is built once per mesh (column "grid").
  void
  mesh_body_containment(const bool quick)
  {
    const Eigen::Vector3d semi_axes(0.035, 0.0245, 0.0175);
    const MeshBody        body
      = make_mesh_body(particulate::benchmarks::geodesic_ellipsoid(semi_axes,
                                                                   10),
                       MeshBodyOptions(),
                       "the geodesic ellipsoid");
    // called through Shape, as the FBM calls RigidBody::shape()
    const Shape       &shape = *body.shape;
    const DistanceMap &map   = body.shape->map();

    std::vector<Pose>                      poses;
    std::mt19937                           rng(44);
    std::uniform_real_distribution<double> u(0., 1.), q(-1., 1.);
    const double                           a     = semi_axes.maxCoeff();
    unsigned long                          tries = 0;
    while (poses.size() < 1000)
      {
        ++tries;
        const Vector3d x = Vector3d::Constant(a)
                           + (1. - 2. * a) * Vector3d(u(rng), u(rng), u(rng));
        bool free = true;
        for (const Pose &p : poses)
          free = free && (p.translation() - x).norm() >= 2. * a;
        if (free)
          poses.emplace_back(
            Eigen::Quaterniond(q(rng), q(rng), q(rng), q(rng)).normalized(),
            x);
      }

    std::printf(
      "\n## Mesh-body containment per step against body count (MappedSurface, %zu triangles, map %d x %d x %d)\n\n",
      body.shape->surface_mesh().n_triangles(),
      map.n_points()[0],
      map.n_points()[1],
      map.n_points()[2]);
    std::printf(
      "| nodes  | bodies | inside  | tests/body | beyond map | grid [ms] | classify_points [ms] | ns/node | us/body | ns/test | FBM loop [ms] | ns/node | us/body | ns/test | equal |\n");
    std::printf(
      "|--------|--------|---------|------------|------------|-----------|----------------------|---------|---------|---------|---------------|---------|---------|---------|-------|\n");
    for (const int n : {33, 65, 129})
      {
        if ((quick && n > 65) || (!quick && n < 65))
          continue;
        const std::vector<Vector3d> pts   = unit_cube_lattice(n);
        const double                nodes = double(pts.size());
        // the FBM's tolerance: 1e-10 of half the node spacing
        const double        tolerance = 1e-10 * 0.5 / (n - 1);
        const auto          t0        = Clock::now();
        const PointHashGrid grid(pts);
        const double        t_grid = seconds_since(t0);
        for (const std::size_t count : {1, 10, 100, 1000})
          {
            std::vector<PlacedShape> bodies;
            for (std::size_t b = 0; b < count; ++b)
              bodies.push_back({&shape, poses[b]});
            // counters from an untimed call (they cost a pass over all
            // points)
            ContainmentStatistics stats;
            classify_points(grid, bodies, nullptr, &stats);
            std::vector<int> marked;
            const double     t_classify = median_cpu_seconds(
              [&] { marked = classify_points(grid, bodies); });
            std::vector<int> node_body(pts.size(), -1);
            std::size_t      tests  = 0;
            const double     t_loop = median_cpu_seconds([&] {
              std::fill(node_body.begin(), node_body.end(), -1);
              tests = 0;
              for (std::size_t b = 0; b < count; ++b)
                {
                  const Pose       &pose  = bodies[b].pose;
                  const BoundingBox local = shape.bounding_box().enlarged(
                    1e-9 * shape.bounding_radius() + 1e-14);
                  grid.for_each_in_box(pose.to_world(local),
                                       [&](const std::size_t i) {
                                         ++tests;
                                         if (node_body[i] >= 0)
                                           return;
                                         const Vector3d x
                                           = pose.to_body(pts[i]);
                                         if (local.contains(x)
                                             && shape.signed_distance(x)
                                                  <= tolerance)
                                           node_body[i] = int(b);
                                       });
                }
            });
            std::size_t inside = 0, beyond = 0;
            for (const int b : marked)
              inside += b >= 0;
            // candidates beyond the map's grid box: there
            // MappedSurface::signed_distance asks the exact surface
            for (const PlacedShape &b : bodies)
              grid.for_each_in_box(world_bounding_box(b),
                                   [&](const std::size_t i) {
                                     beyond
                                       += !map.covers(b.pose.to_body(pts[i]));
                                   });
            const double tests_c = double(stats.n_tests);
            std::printf(
              "| %4d^3 | %6zu | %7zu | %10.0f | %9.0f%% | %9.1f | %20.3f | %7.2f | %7.2f | %7.1f | %13.3f | %7.2f | %7.2f | %7.1f | %5s |\n",
              n,
              count,
              inside,
              tests_c / count,
              100. * beyond / tests_c,
              t_grid * 1e3,
              t_classify * 1e3,
              t_classify / nodes * 1e9,
              t_classify / count * 1e6,
              t_classify / tests_c * 1e9,
              t_loop * 1e3,
              t_loop / nodes * 1e9,
              t_loop / count * 1e6,
              t_loop / double(tests) * 1e9,
              marked == node_body ? "yes" : "NO");
            std::fflush(stdout);
          }
      }
    std::printf(
      "\nbodies: the first of 1 000 ellipsoids at random non-overlapping "
      "poses in the unit cube (%lu draws to place them); nodes: the lattice "
      "of the unit cube; inside: nodes marked; tests/body: nodes in a body's "
      "box; beyond map: share of those outside the map's grid box (the body "
      "box with 4 map cells of margin, in the body frame), where "
      "MappedSurface::signed_distance asks the exact surface (CGAL closest "
      "point and inside test) while contains_points answers outside; grid: building the hash grid over the nodes (once per mesh, wall "
      "time); classify_points: geometry::classify_points (batched "
      "MappedSurface::contains_points); FBM loop: the application's cpu "
      "backend (fbm::FictitiousBoundary::classify, 'inside' marking: one "
      "signed_distance per candidate node inside the body's own box); ns/node: over all nodes; "
      "us/body, ns/test: per body, per candidate node; equal: both mark the "
      "same nodes. Thread CPU time, median of 5 samples of >= 2 ms.\n",
      tries);
  }
} // namespace

int
main(int argc, char **argv)
{
  bool quick = false, lookups_only = false, mesh_bodies_only = false;
  for (int a = 1; a < argc; ++a)
    {
      const std::string flag = argv[a];
      quick |= flag == "quick";
      lookups_only |= flag == "lookups";
      mesh_bodies_only |= flag == "mesh-bodies";
    }
  if (mesh_bodies_only)
    {
      mesh_body_containment(quick);
      return 0;
    }
  const char       *env = std::getenv("PARTICULATE_CGAL_DATA_DIR");
  const std::string dir = std::string(env ? env : "cgal-data") + "/data/meshes";
  std::vector<std::pair<std::string, TriangleMesh>> meshes;
  for (const char *name : {"elephant.off", "bunny00.off"})
    if (std::filesystem::exists(dir + "/" + name))
      meshes.emplace_back(name, read_surface_mesh(dir + "/" + name));
  if (meshes.empty())
    std::printf("(CGAL sample meshes not found in %s; mesh rows skipped)\n",
                dir.c_str());

  std::printf("\n## Distance-map lookup vs CGAL queries [ns per query]\n\n");
  std::printf(
    "| mesh           | triangles | grid            | d      | d srt  | d bat  | d b srt| d+n    | d+n bat| CGAL dist | CGAL sdist| CGAL side | ratio | r srt | r bat | r b s |\n");
  std::printf(
    "|----------------|-----------|-----------------|--------|--------|--------|--------|--------|--------|-----------|-----------|-----------|-------|-------|-------|-------|\n");
  const int n_queries = quick ? 20000 : 200000;
  lookups("icosphere L5", mesh_generators::icosphere(1., 5), n_queries);
  for (const auto &[name, mesh] : meshes)
    lookups(name, mesh, n_queries);
  if (lookups_only)
    return 0;

  std::printf(
    "\n## Distance-map build time vs mesh size (64 cells along the longest side, margin 4 cells, 1 thread)\n\n");
  std::printf(
    "| mesh           | triangles | grid pts  | tree [s] | map [s]  | us/point  |\n");
  std::printf(
    "|----------------|-----------|-----------|----------|----------|-----------|\n");
  for (unsigned int level = 2; level <= (quick ? 4u : 7u); ++level)
    build_time("icosphere L" + std::to_string(level),
               mesh_generators::icosphere(1., level),
               64);
  for (const auto &[name, mesh] : meshes)
    build_time(name, mesh, 64);

  // Bodies in the unit cube: one ball, or 100 mixed bodies of size ~0.05.
  Sphere                         big(0.2);
  Sphere                         ball(0.05);
  Box                            brick(Vector3d(0.05, 0.03, 0.04));
  Ellipsoid                      egg(Vector3d(0.06, 0.04, 0.03));
  const std::vector<PlacedShape> one
    = {{&big, Pose(Eigen::Matrix3d::Identity(), Vector3d(0.5, 0.5, 0.5))}};
  std::vector<PlacedShape>               hundred;
  std::mt19937                           rng(9);
  std::uniform_real_distribution<double> u(0.08, 0.92), a(-1., 1.);
  const Shape                           *kinds[] = {&ball, &brick, &egg};
  for (int b = 0; b < 100; ++b)
    hundred.push_back({kinds[b % 3],
                       Pose(Eigen::Quaterniond(a(rng), a(rng), a(rng), a(rng)),
                            Vector3d(u(rng), u(rng), u(rng)))});

  // Mesh bodies: the elephant's distance map (64 cells along its longest
  // side), scaled to 0.4 (one body, centred) and to 0.1 (100 bodies at the
  // poses above), answered in groups (the batched path) or one contains()
  // call per point.
  std::vector<std::unique_ptr<Shape>> mesh_shapes;
  std::vector<PlacedShape>            one_map, one_map_1b1, maps, maps_1b1;
  for (const auto &[name, mesh] : meshes)
    if (name == "elephant.off")
      for (const double size : {0.4, 0.1})
        {
          TriangleMesh   scaled = mesh;
          const Vector3d c      = mesh.bounding_box().center();
          const double   s = size / mesh.bounding_box().extent().maxCoeff();
          for (Vector3d &v : scaled.vertices)
            v = s * (v - c);
          const TriangulatedSurface surface(scaled);
          auto                      map = std::make_shared<const DistanceMap>(
            DistanceMap::build(surface, {size / 64., 4 * size / 64., 1}));
          mesh_shapes.push_back(std::make_unique<DistanceMapShape>(map));
          mesh_shapes.push_back(
            std::make_unique<OneByOne>(*mesh_shapes.back()));
          const Shape *batched = mesh_shapes[mesh_shapes.size() - 2].get();
          const Shape *single  = mesh_shapes.back().get();
          if (size == 0.4)
            {
              one_map.push_back({batched, one[0].pose});
              one_map_1b1.push_back({single, one[0].pose});
            }
          else
            for (const PlacedShape &b : hundred)
              {
                maps.push_back({batched, b.pose});
                maps_1b1.push_back({single, b.pose});
              }
        }

  std::printf(
    "\n## Point containment of lattice vertices (hash grid vs brute force)\n\n");
  std::printf(
    "| points | bodies                       | inside   | grid [s] | hash [s] | brute [s] | speedup | touched  | tests/NM | equal |\n");
  std::printf(
    "|--------|------------------------------|----------|----------|----------|-----------|---------|----------|----------|-------|\n");
  for (const int n : {33, 65, 129})
    {
      if (quick && n > 65)
        break;
      containment(n, "1 ball", one, true);
      containment(n, "100 balls, boxes, ellipsoids", hundred, true);
      if (!maps.empty())
        {
          containment(n, "1 elephant map", one_map, true);
          containment(n, "1 elephant map, 1 by 1", one_map_1b1, false);
          containment(n, "100 elephant maps", maps, true);
          containment(n, "100 elephant maps, 1 by 1", maps_1b1, false);
        }
    }
  std::printf(
    "\nd / d+n: map distance (and normal), one DistanceMap::distance call per "
    "point; bat: one DistanceMap::distances call for all points; srt: "
    "queries ordered by grid cell; CGAL dist: AABB-tree closest point; "
    "sdist: + pseudo-normal sign; side: Side_of_triangle_mesh; ratio = CGAL "
    "dist / map d (r srt, r bat, r b s: against d srt, d bat, d b srt); "
    "medians of 5 map and 3 CGAL passes.\ntouched: fraction of vertices tested at least once; "
    "tests/NM: point-in-body tests over points x bodies; hash: median of 5 "
    "passes; elephant map: "
    "DistanceMapShape of the elephant (size 0.4 alone, 0.1 for 100), "
    "\"1 by 1\": one contains() call per point instead of the batched "
    "Shape::contains_points.\n");
  mesh_body_containment(quick);
  return 0;
}
