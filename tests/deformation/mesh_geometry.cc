// Unit tests of the deformation module's mesh geometry: the scaled Jacobian
// and aspect ratio against closed forms, the equidistribution error of
// meshes whose cells have exactly the target sizes, the coordinate
// prolongation (exact for affine maps), boundary sliding, the back-off that
// refuses to invert a cell, and the ray-tracing point location against a
// brute-force search.

#include <particulate/deformation/mesh_quality.h>
#include <particulate/deformation/point_locator.h>
#include <particulate/deformation/vertex_hierarchy.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <iostream>
#include <random>

#include "../geometry/check.h"

using namespace dealii;
using namespace particulate::deformation;

namespace {
  bool
  close(const double a, const double b, const double tol = 1e-12)
  {
    return std::abs(a - b) <= tol * (1. + std::abs(b));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // Closed forms: a rectangle is perfect; a parallelogram with angle theta
  // has sin(theta) at every corner; swapping two vertices inverts the cell.
  {
    const std::array<Point<2>, 4> rectangle
      = {{Point<2>(0, 0), Point<2>(3, 0), Point<2>(0, 1), Point<2>(3, 1)}};
    CHECK_MSG(close(scaled_jacobian<2>(rectangle), 1.), "rectangle: SJ = 1");
    CHECK_MSG(close(aspect_ratio<2>(rectangle), 3.), "rectangle 3x1: AR = 3");
    const double                  theta = 0.4;
    const Point<2>                e(std::cos(theta), std::sin(theta));
    const std::array<Point<2>, 4> rhombus
      = {{Point<2>(0, 0), Point<2>(1, 0), e, Point<2>(1, 0) + e}};
    CHECK_MSG(close(scaled_jacobian<2>(rhombus), std::sin(theta)),
              "parallelogram: SJ = sin(theta)");
    const std::array<Point<2>, 4> inverted
      = {{Point<2>(1, 0), Point<2>(0, 0), Point<2>(0, 1), Point<2>(1, 1)}};
    CHECK_MSG(scaled_jacobian<2>(inverted) < 0.,
              "inverted quadrilateral: SJ < 0");
    std::array<Point<3>, 8> brick, sheared;
    for (unsigned int v = 0; v < 8; ++v)
      {
        brick[v] = Point<3>(2. * (v & 1), 1. * ((v >> 1) & 1), 0.5 * (v >> 2));
        sheared[v] = brick[v] + Point<3>(0.5 * brick[v][2] / 0.5, 0, 0);
      }
    CHECK_MSG(close(scaled_jacobian<3>(brick), 1.), "brick: SJ = 1");
    // shearing x by z: the z edge (0, 0, 0.5) becomes (0.5, 0, 0.5), at
    // 45 degrees to the x edge: SJ = sin(45°)
    CHECK_MSG(close(scaled_jacobian<3>(sheared), 1. / std::sqrt(2.)),
              "sheared hexahedron: SJ = 1/sqrt(2)");
  }

  // Equidistribution: zero for a uniform mesh under a constant monitor and
  // for a graded mesh whose cells are exactly the monitor's sizes.
  {
    Triangulation<2> uniform;
    GridGenerator::hyper_cube(uniform);
    uniform.refine_global(3);
    const auto e0
      = equidistribution_error<2>(uniform, [](const Point<2> &) { return 2.; });
    CHECK_MSG(e0.l2 < 1e-14 && e0.max < 1e-14,
              "uniform mesh, constant monitor");
    Triangulation<2>                       graded;
    const std::vector<std::vector<double>> steps = {{0.1, 0.2, 0.3, 0.4}, {1.}};
    GridGenerator::subdivided_hyper_rectangle(graded,
                                              steps,
                                              Point<2>(0, 0),
                                              Point<2>(1, 1));
    const auto e1 = equidistribution_error<2>(graded, [](const Point<2> &x) {
      return 0.1
             + 0.2
                 * (x[0] < 0.1 ? 0. :
                    x[0] < 0.3 ? 0.5 :
                    x[0] < 0.6 ? 1. :
                                 1.5);
    });
    CHECK_MSG(e1.max < 1e-12, "graded mesh, monitor = its cell sizes");
    const auto e2
      = equidistribution_error<2>(graded, [](const Point<2> &) { return 1.; });
    // cells 0.1 ... 0.4 against the mean 0.25: |e| at most 0.6
    CHECK_MSG(close(e2.max, 0.6),
              "graded mesh, constant monitor: max |e| = 0.6");
  }

  // Coordinate prolongation reproduces any affine image of the hierarchy,
  // and boundary vertices only slide along their side.
  {
    Triangulation<3> tria;
    GridGenerator::hyper_cube(tria);
    tria.refine_global(3);
    const VertexHierarchy<3> hierarchy(tria);
    Tensor<2, 3>             A;
    A[0][0] = 1.2, A[0][1] = 0.3, A[1][1] = 0.9, A[2][0] = -0.2, A[2][2] = 1.1;
    const Tensor<1, 3>    b({0.1, -0.4, 2.});
    std::vector<Point<3>> exact = tria.get_vertices(), positions;
    for (auto &x : exact)
      x = Point<3>(A * x + b);
    positions = tria.get_vertices();
    for (const unsigned int v : hierarchy.vertices_on_level(0))
      positions[v] = exact[v];
    for (unsigned int l = 0; l + 1 < hierarchy.n_levels(); ++l)
      hierarchy.prolongate(l, positions);
    double error = 0.;
    for (unsigned int v = 0; v < positions.size(); ++v)
      error = std::max(error, positions[v].distance(exact[v]));
    CHECK_MSG(error < 1e-14, "prolongation is exact for affine maps");

    const Tensor<1, 3> push({0.3, -0.2, 0.7});
    bool               stays = true;
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      {
        const Point<3> x = tria.get_vertices()[v];
        const Point<3> y = x + hierarchy.admissible_displacement(v, push);
        for (unsigned int d = 0; d < 3; ++d)
          if ((x[d] == 0. || x[d] == 1.) && y[d] != x[d])
            stays = false;
      }
    CHECK_MSG(stays, "boundary vertices slide only within their faces");
    bool roles = true;
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      {
        const Point<3> x         = tria.get_vertices()[v];
        unsigned int   on_planes = 0;
        for (unsigned int d = 0; d < 3; ++d)
          on_planes += (x[d] == 0. || x[d] == 1.);
        // vertices on an edge of the cube slide along it; only the
        // corners are fixed
        roles = roles && hierarchy.is_fixed(v) == (on_planes == 3)
                && hierarchy.at_boundary(v) == (on_planes > 0);
      }
    CHECK_MSG(roles, "corners fixed, other boundary vertices sliding");
  }

  // Back-off: pushing a vertex across its neighbours is cut back so that no
  // cell inverts.
  {
    Triangulation<2> tria;
    GridGenerator::hyper_cube(tria);
    tria.refine_global(2);
    const VertexHierarchy<2> hierarchy(tria);
    const auto               old_positions = tria.get_vertices();
    auto                     moved         = old_positions;
    unsigned int             centre        = 0;
    for (unsigned int v = 0; v < moved.size(); ++v)
      if (old_positions[v].distance(Point<2>(0.5, 0.5)) < 1e-12)
        centre = v;
    moved[centre] += Tensor<1, 2>({0.6, 0.});
    const unsigned int held  = hierarchy.back_off(2, old_positions, moved, 0.2);
    double             worst = 1.;
    for (unsigned int c = 0; c < hierarchy.cells_on_level(2).size(); ++c)
      worst = std::min(worst, hierarchy.cell_quality(2, c, moved));
    CHECK_MSG(held == 1 && worst >= 0.2 && moved[centre][0] > 0.5,
              "an inverting move is cut back to a valid one");
  }

  // Ray-tracing point location finds the same cell as a brute-force search
  // on a randomly distorted mesh, from a hint far away.
  {
    Triangulation<2> tria;
    GridGenerator::hyper_cube(tria);
    tria.refine_global(5);
    GridTools::distort_random(0.25, tria, /*keep_boundary=*/true);
    const PointLocator<2>            locator(tria);
    std::mt19937                     random(7);
    std::uniform_real_distribution<> u(0., 1.);
    unsigned int                     agree = 0;
    const unsigned int               n     = 500;
    auto                             hint  = tria.begin_active();
    for (unsigned int k = 0; k < n; ++k)
      {
        const Point<2> p(u(random), u(random));
        const auto     found = locator.locate(p, hint);
        const auto     brute
          = GridTools::find_active_cell_around_point(locator.get_mapping(),
                                                     tria,
                                                     p);
        // on a shared face either neighbour is right
        agree += found.inside
                 && (found.cell == brute.first || found.cell->point_inside(p));
        hint = found.cell;
      }
    CHECK_MSG(agree == n, "ray tracing agrees with brute force on 500 points");
    CHECK_MSG(locator.n_fallbacks() == 0, "no brute-force fallback was needed");
  }

  return test::finish("deformation_mesh_geometry");
}
