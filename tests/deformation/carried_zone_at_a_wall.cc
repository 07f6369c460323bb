// A body that moves about a cell per step towards a wall, with 'Moving
// bodies = carry neighbourhood' (MovingMesh::follow told where the step
// starts): a disk of radius 0.1 sinks by 0.9 cells per step (h = 1/32 on
// [0, 1] x [0, 2]) from a gap of 8.5 h to one of 1.3 h above the floor,
// its zone (0.05) fading over 0.3, so that the floor lies within the fade
// and the cells between disk and floor are pressed flat. A fresh start
// made where the step starts and then carried over the step moves those
// cells by up to half a cell of realignment plus the step, more than their
// height: then follow() makes the fresh start where the disk is now.
// Checked at every step:
// - no cell inverts or falls below the quality bound;
// - that fall-back was needed (some fresh start is made where the disk is
//   now) and was not taken where the step's carry leaves the fresh mesh
//   valid (the first fresh starts, far from the floor, are made where the
//   step starts);
// - the vertices inside the disk keep their places relative to it through
//   every fresh start of either kind.

#include <particulate/core/mesh.h>
#include <particulate/deformation/distance_field.h>
#include <particulate/deformation/moving_mesh.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include "../geometry/check.h"

using namespace dealii;
using namespace particulate;
using namespace particulate::deformation;

namespace {
  const double radius = 0.1, h = 1. / 32.;

  FunctionDistanceField<2>
  disk_at(const Point<2> &centre)
  {
    return FunctionDistanceField<2>(
      [centre](const Point<2> &x) { return x.distance(centre) - radius; });
  }

  /** The vertices inside the disk at @p centre, relative to it, sorted
   *  (a realigned zone holds other vertices at the same places). */
  std::vector<Tensor<1, 2>>
  inside_relative(const std::vector<Point<2>> &vertices, const Point<2> &centre)
  {
    std::vector<Tensor<1, 2>> inside;
    for (const auto &x : vertices)
      if (x.distance(centre) < radius)
        inside.push_back(x - centre);
    std::sort(inside.begin(),
              inside.end(),
              [](const Tensor<1, 2> &a, const Tensor<1, 2> &b) {
                return a[1] < b[1] - 1e-12
                       || (std::abs(a[1] - b[1]) <= 1e-12 && a[0] < b[0]);
              });
    return inside;
  }

  /** The largest distance, in cells, between two sets of relative places
   *  of equal size (infinite when the sizes differ). */
  double
  largest_offset(const std::vector<Tensor<1, 2>> &a,
                 const std::vector<Tensor<1, 2>> &b)
  {
    if (a.size() != b.size())
      return std::numeric_limits<double>::infinity();
    double largest = 0.;
    for (unsigned int i = 0; i < a.size(); ++i)
      largest = std::max(largest, (a[i] - b[i]).norm() / h);
    return largest;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  core::MeshParameters mesh;
  mesh.type         = core::MeshParameters::Type::hyper_rectangle;
  mesh.lower_corner = {0., 0.};
  mesh.upper_corner = {1., 2.};
  mesh.subdivisions = {4, 8};
  mesh.refinements  = 3;

  DeformationParameters p;
  p.method             = DeformationParameters::Method::none;
  p.following          = DeformationParameters::Following::carry_neighbourhood;
  p.carried_zone_width = 0.05;
  p.carried_zone_fade  = 0.3;
  MovingMesh<2> moving(mesh, p);

  const double step = 0.9 * h;
  Point<2>     at(0.5 + 0.3 * h, radius + 8.5 * h);
  moving.adapt(disk_at(at));
  const auto start = inside_relative(moving.hierarchy().get_vertices(), at);

  unsigned int fresh_at_step_start = 0, fresh_where_now = 0;
  unsigned int first_fresh_step = 0, first_fallback_step = 0;
  double       worst_quality = 1., offset = 0.;
  unsigned int n = 0;
  while (at[1] - radius - step > 1.3 * h - 1e-12)
    {
      ++n;
      const Point<2> before = at;
      at[1] -= step;
      const auto was    = disk_at(before);
      const auto report = moving.follow(
        disk_at(at),
        [&](const Point<2> &) {
          return Tensor<1, 2>({0., -step});
        },
        &was);
      worst_quality
        = std::min(worst_quality, report.quality.min_scaled_jacobian);
      offset = std::max(
        offset,
        largest_offset(inside_relative(moving.hierarchy().get_vertices(), at),
                       start));
      if (!report.readapted)
        continue;
      if (first_fresh_step == 0)
        first_fresh_step = n;
      if (moving.fresh_start_vertices().empty())
        {
          ++fresh_where_now;
          if (first_fallback_step == 0)
            first_fallback_step = n;
        }
      else
        {
          ++fresh_at_step_start;
          offset
            = std::max(offset,
                       largest_offset(
                         inside_relative(moving.fresh_start_vertices(), before),
                         start));
        }
    }
  std::cout << n << " steps to a gap of " << (at[1] - radius) / h
            << " h; fresh starts where the step starts: " << fresh_at_step_start
            << ", where the disk is now: " << fresh_where_now
            << " (first fresh start in step " << first_fresh_step
            << ", first where the disk is now in step " << first_fallback_step
            << "); worst scaled Jacobian " << worst_quality << "; "
            << start.size()
            << " vertices inside the disk, largest offset from their start "
            << offset << " h\n";
  CHECK_MSG(worst_quality >= p.min_quality - 1e-12,
            "no cell inverts or falls below the quality bound");
  CHECK_MSG(fresh_where_now > 0,
            "near the floor a fresh start is made where the disk is now");
  CHECK_MSG(fresh_at_step_start > 0 && first_fresh_step < first_fallback_step,
            "where the step's carry leaves the fresh mesh valid, the fresh "
            "start is made where the step starts");
  CHECK_MSG(offset < 1e-9,
            "the disk keeps its vertices through every fresh start");
  return test::finish("deformation_carried_zone_at_a_wall");
}
