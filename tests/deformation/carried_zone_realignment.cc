// A fresh start of 'Moving bodies = carry neighbourhood' keeps the body's
// place among the vertices where the mesh repeats itself along its path
// (deformation::realigned_zones, used by MovingMesh::follow): a disk of
// radius 0.1 sinks by 0.37 cells per step, 24 steps, through a uniform
// mesh of cells h = 1/32 on [0, 1] x [0, 2], carried with a zone of 0.05
// fading over 0.2, with 'Re-adaptation aspect ratio' so tight that most
// steps start afresh. Checked at every step:
// - the vertices inside the disk are those of the start, at the same
//   places relative to its centre (to 1e-9 h), so the fictitious boundary
//   sees the same body all along; so are those of a fresh start made where
//   the step starts (follow() told where the disk was), which is then
//   carried over the step;
// - no cell falls below the quality bound.
// And a zone that turned with its body (every vertex moved by its own
// displacement) is not realigned: realigned_zones() leaves the fresh start
// to the undeformed mesh (no zones).
// A plain fresh start from the undeformed mesh (what the realignment
// replaces) would put the disk 0.37 h further among the vertices each
// step: the count of vertices inside changes (printed for comparison, from
// the undeformed mesh around the moved disk).

#include <particulate/core/mesh.h>
#include <particulate/deformation/carried_zone_realignment.h>
#include <particulate/deformation/distance_field.h>
#include <particulate/deformation/moving_mesh.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "../geometry/check.h"
#include "disk_in_channel.h"

using namespace dealii;
using namespace particulate;
using namespace particulate::deformation;

namespace {
  using sinking_disk::disk_at;
  using sinking_disk::inside_relative;
  const double radius = sinking_disk::disk_radius,
               h      = sinking_disk::channel_cell;
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const core::MeshParameters mesh = sinking_disk::uniform_channel();

  DeformationParameters p;
  p.method             = DeformationParameters::Method::none;
  p.following          = DeformationParameters::Following::carry_neighbourhood;
  p.carried_zone_width = 0.05;
  p.carried_zone_fade  = 0.2;
  p.readaptation_aspect_ratio = 1.001;
  MovingMesh<2> moving(mesh, p);

  Point<2>     centre(0.5 + 0.3 * h, 1.5 + 0.2 * h);
  const double step = 0.37 * h;
  // from_step_start: follow() also gets where the disk was before the step
  // and starts afresh there, then carries the fresh mesh over the step
  const auto follow_the_disk = [&](const bool from_step_start) {
    MovingMesh<2> moving(mesh, p);
    Point<2>      at = centre;
    moving.adapt(disk_at(at));
    const auto   start = inside_relative(moving.hierarchy().get_vertices(), at);
    const auto   undeformed   = moving.hierarchy().get_vertices();
    unsigned int fresh_starts = 0, changed_sets = 0, plain_changes = 0;
    unsigned int fresh_at_step_start = 0;
    double       worst_quality = 1., largest_offset = 0.;
    const auto   offset_from_start
      = [&](const std::vector<Point<2>> &x, const Point<2> &c) {
          const auto now = inside_relative(x, c);
          if (now.size() != start.size())
            {
              ++changed_sets;
              return;
            }
          for (unsigned int i = 0; i < now.size(); ++i)
            largest_offset
              = std::max(largest_offset, (now[i] - start[i]).norm() / h);
        };
    for (unsigned int n = 1; n <= 24; ++n)
      {
        const Point<2> before = at;
        at[1] -= step;
        const auto was    = disk_at(before);
        const auto report = moving.follow(
          disk_at(at),
          [&](const Point<2> &) {
            return Tensor<1, 2>({0., -step});
          },
          from_step_start ? &was : nullptr);
        fresh_starts += report.readapted;
        if (!moving.fresh_start_vertices().empty())
          {
            ++fresh_at_step_start;
            offset_from_start(moving.fresh_start_vertices(), before);
          }
        worst_quality
          = std::min(worst_quality, report.quality.min_scaled_jacobian);
        offset_from_start(moving.hierarchy().get_vertices(), at);
        plain_changes += inside_relative(undeformed, at).size() != start.size();
      }
    std::cout << (from_step_start ? "from the step's start: " : "")
              << "fresh starts in " << fresh_starts << " of 24 steps ("
              << fresh_at_step_start << " where the step starts); "
              << start.size()
              << " vertices inside the disk; the set changed in "
              << changed_sets << " steps, largest offset " << largest_offset
              << " h; from the undeformed mesh the count would change in "
              << plain_changes << " steps; worst scaled Jacobian "
              << worst_quality << "\n";
    CHECK_MSG(fresh_starts >= 12, "most steps start afresh");
    CHECK_MSG(fresh_at_step_start == (from_step_start ? fresh_starts : 0),
              "each fresh start is made where the step starts if, and only "
              "if, follow() is told where that is");
    CHECK_MSG(plain_changes > 0,
              "the path puts the disk elsewhere among the undeformed "
              "vertices");
    CHECK_MSG(changed_sets == 0 && largest_offset < 1e-9,
              "the disk keeps its vertices through every fresh start");
    CHECK_MSG(worst_quality >= p.min_quality - 1e-12,
              "no cell below the quality bound");
  };
  follow_the_disk(false);
  follow_the_disk(true);
  centre[1] -= 24 * step;

  // the mesh turned by 0.2 rad about the disk's centre
  std::vector<Point<2>> turned
    = MovingMesh<2>(mesh, p).hierarchy().get_vertices();
  for (auto &x : turned)
    {
      const Tensor<1, 2> r = x - centre;
      x                    = centre
          + Tensor<1, 2>({std::cos(0.2) * r[0] - std::sin(0.2) * r[1],
                          std::sin(0.2) * r[0] + std::cos(0.2) * r[1]});
    }
  CHECK_MSG(realigned_zones(turned,
                            MovingMesh<2>(mesh, p).hierarchy().get_vertices(),
                            disk_at(centre),
                            0.05)
              .empty(),
            "a zone that turned with its body is not realigned");
  return test::finish("deformation_carried_zone_realignment");
}
