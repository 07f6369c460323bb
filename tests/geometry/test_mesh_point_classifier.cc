// The deal.II adapter, serial: hash-grid containment of mesh vertices and Q2
// support points equals brute force, and the inside set of a sphere equals
// the exact set of lattice points computed in integers.
#include <particulate/geometry/box.h>
#include <particulate/geometry/dealii/mesh_point_classifier.h>
#include <particulate/geometry/mesh_io.h>
#include <particulate/geometry/sphere.h>
#include <particulate/geometry/triangulated_surface.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "check.h"

using namespace particulate::geometry;
using Eigen::Vector3d;

namespace {
  // Lattice points (i, j, k) / n, 0 <= i, j, k <= n, inside the closed ball of
  // radius m / n around (c, c, c) / n: counted in exact integer arithmetic.
  long
  lattice_points_in_ball(const int n, const int c, const int m)
  {
    long count = 0;
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
          count += (i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c)
                   <= m * m;
    return count;
  }
} // namespace

int
main()
{
  dealii::Triangulation<3> tria;
  dealii::GridGenerator::subdivided_hyper_cube(tria, 16, 0., 1.);

  // A ball of radius 1/4 at the centre: lattice points lie exactly on its
  // surface (e.g. (3/4, 1/2, 1/2)) and must count as inside.
  Sphere     ball(0.25);
  const Pose centre(Eigen::Matrix3d::Identity(), Vector3d(0.5, 0.5, 0.5));
  std::vector<PlacedShape> one = {{&ball, centre}};

  // Vertices: 17^3, spacing 1/16, ball radius 4 spacings.
  {
    const MeshPointClassifier c(tria);
    CHECK(c.points().size() == 17u * 17u * 17u);
    ContainmentStatistics stats;
    const auto            in   = c.classify(one, nullptr, &stats);
    long                  n_in = 0;
    for (const int b : in)
      n_in += b == 0;
    const long exact = lattice_points_in_ball(16, 8, 4);
    std::cout << "vertices in ball: " << n_in << " (exact " << exact << "), "
              << stats.n_points_touched << " of " << stats.n_points
              << " touched" << std::endl;
    CHECK(n_in == exact);
    CHECK(stats.n_points_touched == 9u * 9u * 9u); // the ball's box
    // Each id is a vertex index and the point is that vertex.
    bool ids_ok = true;
    for (std::size_t i = 0; i < c.points().size(); ++i)
      {
        const auto &v = tria.get_vertices()[c.point_ids()[i]];
        ids_ok        = ids_ok
                 && v.distance(dealii::Point<3>(c.points()[i][0],
                                                c.points()[i][1],
                                                c.points()[i][2]))
                      == 0.;
      }
    CHECK(ids_ok);
  }

  // Q2 velocity nodes (component 0 of FE_Q(2)^3): 33^3 points, spacing
  // 1/32, the ball's radius is 8 spacings.
  {
    dealii::FESystem<3>   fe(dealii::FE_Q<3>(2), 3);
    dealii::DoFHandler<3> dh(tria);
    dh.distribute_dofs(fe);
    const MeshPointClassifier c(dealii::MappingQ1<3>(), dh, 0);
    CHECK(c.points().size() == 33u * 33u * 33u);
    const auto in   = c.classify(one);
    long       n_in = 0;
    for (const int b : in)
      n_in += b == 0;
    std::cout << "Q2 nodes in ball: " << n_in << " (exact "
              << lattice_points_in_ball(32, 16, 8) << ")" << std::endl;
    CHECK(n_in == lattice_points_in_ball(32, 16, 8));

    // Many bodies of several kinds: exactly the brute-force answer.
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(0.11));
    shapes.push_back(std::make_unique<Box>(Vector3d(0.1, 0.05, 0.15)));
    const char       *env = std::getenv("PARTICULATE_CGAL_DATA_DIR");
    const std::string elephant
      = std::string(env ? env : "cgal-data") + "/data/meshes/elephant.off";
    if (std::filesystem::exists(elephant))
      shapes.push_back(std::make_unique<TriangulatedSurface>(
        read_surface_mesh(elephant).scaled(0.3)));
    std::vector<PlacedShape> bodies;
    for (int b = 0; b < 30; ++b)
      {
        const double t = 0.37 * b;
        bodies.push_back(
          {shapes[b % shapes.size()].get(),
           Pose(Eigen::Quaterniond(std::cos(t), std::sin(t), 0.3, -0.2),
                Vector3d(0.5 + 0.4 * std::sin(1.3 * t),
                         0.5 + 0.4 * std::cos(0.7 * t),
                         0.5 + 0.4 * std::sin(2.1 * t)))});
      }
    ContainmentStatistics stats;
    const auto            fast = c.classify(bodies, nullptr, &stats);
    const auto slow = classify_points_brute_force(c.points(), bodies);
    long       diff = 0, n_inside = 0;
    for (std::size_t i = 0; i < fast.size(); ++i)
      {
        diff += fast[i] != slow[i];
        n_inside += fast[i] >= 0;
      }
    std::cout << bodies.size() << " bodies: " << n_inside << " nodes inside, "
              << stats.n_tests << " tests (brute force "
              << fast.size() * bodies.size() << "), " << diff << " differences"
              << std::endl;
    CHECK(diff == 0 && n_inside > 0);
  }
  return test::finish("geometry_mesh_point_classifier");
}
