// Mesh-mesh narrow phase (issue 44): the cost of NarrowPhase::collide for
// one pair of mesh bodies (geometry::make_mesh_body: the vertices of each
// against the other's distance map, both ways, then the reduced contact set
// of at most 8 points; thesis §3.4.2) against the number of surface
// vertices, beside the same pair as analytic ellipsoids (GJK/EPA).
//
// The bodies: two ellipsoids with semi-axes (20, 14, 10) mm meshed as
// geodesic spheres of frequency 3, 6, 13, 25, 50 (92 to 25 002 vertices),
// each with its map at the automatic spacing (c / 8; the same map at every
// resolution). Five relative poses: end to end (along x), stacked (along z),
// crossed (stacked, B turned 90 degrees about z), and two random orientations
// and directions. B is moved along the pose's direction until the deepest
// vertex of either mesh lies delta = 0.01 c inside the other (bisection), so
// every pose is a touching, slightly overlapping contact; the contact margin
// is the World's default, 2 % of the bounding radius. The analytic pair is
// timed at the same poses.
//
// Times are thread CPU time, the median of 7 samples, each sample as many
// calls as fill 2 ms. Beside collide() itself, which skips the vertices
// farther than the margin from the partner's box: "beyond map", the share
// of the vertices outside the partner's map grid box (there the exact
// surface would answer); "every vertex", the two vertex passes querying
// every vertex's distance, without building and reducing contact points
// (what collide() would cost without its box test); "in-map", the same
// passes skipping the vertices beyond the map;
// "points before", the vertices within the margin (what reduction starts
// from). Asserts nothing about time.
// Usage: bench_rigid_mesh_contact [max_vertices]   (default: all five)
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/mesh_body.h>
#include <particulate/rigid/narrow_phase.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "../geodesic_ellipsoid.h"

using namespace particulate::rigid;
using namespace particulate::geometry;
using particulate::benchmarks::geodesic_ellipsoid;
using particulate::benchmarks::geodesic_vertices;

namespace {
  // CPU time of this thread in s: robust on a shared machine.
  double
  cpu_seconds()
  {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1.e-9 * t.tv_nsec;
  }

  volatile double sink = 0.;

  // Median over 7 samples of the CPU time of one call of @p f [us]; each
  // sample repeats f often enough to last 2 ms.
  template <typename F>
  double
  median_us(F &&f)
  {
    f(); // warm-up
    unsigned int calls = 1;
    for (;;)
      {
        const double t0 = cpu_seconds();
        for (unsigned int i = 0; i < calls; ++i)
          f();
        if (cpu_seconds() - t0 >= 2.e-3)
          break;
        calls *= 2;
      }
    std::vector<double> t(7);
    for (double &x : t)
      {
        const double t0 = cpu_seconds();
        for (unsigned int i = 0; i < calls; ++i)
          f();
        x = (cpu_seconds() - t0) / calls * 1.e6;
      }
    std::nth_element(t.begin(), t.begin() + 3, t.end());
    return t[3];
  }

  // What NarrowPhase::collide tests for a pair of mesh bodies, without the
  // contact points: the surface points of P against the signed distance of
  // Q (its map, or beyond the map's grid box its exact surface).
  struct Pass
  {
    double      deepest = std::numeric_limits<double>::infinity(); // [m]
    std::size_t within  = 0; // gaps <= margin
    std::size_t beyond  = 0; // points beyond Q's map
  };

  // With @p map_only, the points beyond Q's map @p q_map are skipped (they
  // lie outside Q's box enlarged by the map's margin, so further than the
  // contact margin from Q whenever that margin is smaller).
  void
  vertex_pass(const RigidBody   &P,
              const RigidBody   &Q,
              const DistanceMap &q_map,
              const double       margin,
              const bool         map_only,
              Pass              &pass)
  {
    for (const Eigen::Vector3d &pb : P.shape().surface_points())
      {
        const Eigen::Vector3d pq = Q.to_body(P.to_world(pb));
        if (!q_map.covers(pq))
          {
            ++pass.beyond;
            if (map_only)
              continue;
          }
        Eigen::Vector3d g;
        const double    gap = Q.shape().signed_distance(pq, &g);
        pass.deepest        = std::min(pass.deepest, gap);
        pass.within += gap <= margin;
      }
  }

  struct RelativePose
  {
    std::string        name;
    Eigen::Quaterniond qa, qb;
    Eigen::Vector3d    direction; // of B's centre from A's (world, unit)
  };

  std::vector<RelativePose>
  relative_poses()
  {
    using Q                       = Eigen::Quaterniond;
    const Q                   one = Q::Identity();
    const double              pi  = std::acos(-1.);
    std::vector<RelativePose> poses
      = {{"end to end", one, one, Eigen::Vector3d::UnitX()},
         {"stacked", one, one, Eigen::Vector3d::UnitZ()},
         {"crossed",
          one,
          Q(Eigen::AngleAxisd(0.5 * pi, Eigen::Vector3d::UnitZ())),
          Eigen::Vector3d::UnitZ()}};
    std::mt19937                           rng(44);
    std::normal_distribution<double>       g;
    std::uniform_real_distribution<double> u(-1., 1.);
    for (const char *name : {"random 1", "random 2"})
      {
        const Q qa = Q(u(rng), u(rng), u(rng), u(rng)).normalized();
        const Q qb = Q(u(rng), u(rng), u(rng), u(rng)).normalized();
        const Eigen::Vector3d d(g(rng), g(rng), g(rng));
        poses.push_back({name, qa, qb, d.normalized()});
      }
    return poses;
  }

  // Places B along the pose's direction so that the deepest vertex of either
  // mesh lies @p depth inside the other; the analytic pair gets the same
  // pose.
  void
  place(const RelativePose &pose,
        const double        depth,
        const DistanceMap  &map,
        RigidBody          &A,
        RigidBody          &B,
        RigidBody          &A_exact,
        RigidBody          &B_exact)
  {
    A.orientation = A_exact.orientation = pose.qa;
    B.orientation = B_exact.orientation = pose.qb;
    A.position = A_exact.position = Eigen::Vector3d::Zero();
    double lo = 0., hi = A.bounding_radius() + B.bounding_radius() + depth;
    for (int it = 0; it < 60; ++it)
      {
        const double s = 0.5 * (lo + hi);
        B.position     = s * pose.direction;
        Pass pass; // the deepest point is never beyond the partner's map
        vertex_pass(A, B, map, 0., true, pass);
        vertex_pass(B, A, map, 0., true, pass);
        (pass.deepest < -depth ? lo : hi) = s;
      }
    B.position = B_exact.position = hi * pose.direction;
  }
} // namespace

int
main(int argc, char **argv)
{
  const unsigned long max_vertices
    = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 30000;
  const Eigen::Vector3d semi_axes(0.02, 0.014, 0.01);
  const double          c     = semi_axes[2];
  const double          depth = 0.01 * c;
  const auto            exact = std::make_shared<Ellipsoid>(semi_axes);
  const auto            poses = relative_poses();

  struct Summary
  {
    unsigned int vertices, triangles;
    double       map_seconds;
    double       mesh_us = 0., tests_us = 0., in_map_us = 0., exact_us = 0.;
    double       beyond = 0., before = 0., after = 0.;
  };
  std::vector<Summary> summary;
  double               margin = 0., spacing = 0.;
  std::array<int, 3>   grid{{0, 0, 0}};

  std::printf(
    "\n## Mesh-mesh narrow phase per pair against surface vertices (ellipsoids 20 x 14 x 10 mm, overlap %.2g mm)\n\n",
    depth * 1e3);
  const char *header
    = "| vertices | triangles | %-10s | mesh [us/pair] | ns/vertex | beyond map | every vertex [us] | in-map [us] | points before | after | analytic [us/pair] | mesh / analytic |\n"
      "|----------|-----------|------------|----------------|-----------|------------|----------------|-------------------|---------------|-------|--------------------|-----------------|\n";
  std::printf(header, "pose");
  const char *row
    = "| %8u | %9u | %-10s | %14.1f | %9.1f | %9.0f%% | %14.1f | %17.1f | %13.4g | %5.4g | %18.2f | %15.2g |\n";
  for (const unsigned int n : {3u, 6u, 13u, 25u, 50u})
    {
      if (geodesic_vertices(n) > max_vertices)
        break;
      const double   t0   = cpu_seconds();
      const MeshBody mesh = make_mesh_body(geodesic_ellipsoid(semi_axes, n),
                                           MeshBodyOptions(),
                                           "the geodesic ellipsoid");
      Summary        s;
      s.map_seconds     = cpu_seconds() - t0;
      s.vertices        = mesh.shape->surface_mesh().n_vertices();
      s.triangles       = mesh.shape->surface_mesh().n_triangles();
      const auto &map   = mesh.shape->map();
      grid              = map.n_points();
      spacing           = map.spacing();
      const double n_pt = 2. * s.vertices; // points tested per pair

      RigidBody A(mesh.shape, 0, 1000., false), B(mesh.shape, 0, 1000., false);
      RigidBody A_exact(exact, 0, 1000., false),
        B_exact(exact, 0, 1000., false);
      // The World's automatic margin.
      margin = 0.02 * std::min(A.bounding_radius(), B.bounding_radius());
      for (const RelativePose &pose : poses)
        {
          place(pose, depth, map, A, B, A_exact, B_exact);
          ContactEdge  edge;
          const double t_mesh = median_us([&] {
            NarrowPhase::collide(A, B, margin, edge);
            sink = sink + edge.manifold.points.size();
          });
          const double after  = edge.manifold.points.size();
          Pass         all;
          vertex_pass(A, B, map, margin, false, all);
          vertex_pass(B, A, map, margin, false, all);
          auto passes = [&](const bool map_only) {
            return median_us([&] {
              Pass pass;
              vertex_pass(A, B, map, margin, map_only, pass);
              vertex_pass(B, A, map, margin, map_only, pass);
              sink = sink + pass.deepest;
            });
          };
          const double t_tests  = passes(false);
          const double t_in_map = passes(true);
          ContactEdge  edge_exact;
          const double t_exact = median_us([&] {
            NarrowPhase::collide(A_exact, B_exact, margin, edge_exact);
            sink = sink + edge_exact.manifold.points.size();
          });
          std::printf(row,
                      s.vertices,
                      s.triangles,
                      pose.name.c_str(),
                      t_mesh,
                      t_mesh * 1e3 / n_pt,
                      100. * all.beyond / n_pt,
                      t_tests,
                      t_in_map,
                      double(all.within),
                      after,
                      t_exact,
                      t_mesh / t_exact);
          const double w = 1. / poses.size();
          s.mesh_us += w * t_mesh;
          s.tests_us += w * t_tests;
          s.in_map_us += w * t_in_map;
          s.exact_us += w * t_exact;
          s.beyond += w * all.beyond;
          s.before += w * all.within;
          s.after += w * after;
        }
      std::fflush(stdout);
      summary.push_back(s);
    }

  std::printf("\n## Mean over the %zu poses\n\n", poses.size());
  std::printf(header, "map build");
  for (const Summary &s : summary)
    {
      char build[32];
      std::snprintf(build, sizeof(build), "%.3f s", s.map_seconds);
      std::printf(row,
                  s.vertices,
                  s.triangles,
                  build,
                  s.mesh_us,
                  s.mesh_us * 1e3 / (2. * s.vertices),
                  100. * s.beyond / (2. * s.vertices),
                  s.tests_us,
                  s.in_map_us,
                  s.before,
                  s.after,
                  s.exact_us,
                  s.mesh_us / s.exact_us);
    }
  std::printf(
    "\nmesh: NarrowPhase::collide for the pair; ns/vertex: that over the "
    "2 x vertices it tests (each body's against the other's distance); "
    "beyond map: share of those outside the partner's map grid box "
    "(%d x %d x %d points at the largest mesh, spacing %.3g mm, margin 4 cells), which the "
    "exact surface would answer (CGAL closest point and inside test), "
    "and which collide() skips by a box test; every vertex: the two passes "
    "querying every vertex, without building and reducing contact points; "
    "in-map: the same skipping the points beyond the map; "
    "points before: vertices within the margin (%.2g mm, 2 %% of the "
    "bounding radius), after: the reduced set collide() returns; analytic: "
    "the same poses with geometry::Ellipsoid (GJK/EPA). Thread CPU time, "
    "median of 7 samples of >= 2 ms.\n",
    grid[0],
    grid[1],
    grid[2],
    spacing * 1e3,
    margin * 1e3);
  return 0;
}
