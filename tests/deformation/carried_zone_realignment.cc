// A fresh start of 'Moving bodies = carry neighbourhood' keeps the body's
// place among the vertices where the mesh repeats itself along its path
// (deformation::realigned_zones, used by MovingMesh::follow): a disk of
// radius 0.1 sinks by 0.37 cells per step, 24 steps, through a uniform
// mesh of cells h = 1/32 on [0, 1] x [0, 2], carried with a zone of 0.05
// fading over 0.2, with 'Re-adaptation aspect ratio' so tight that most
// steps start afresh. Checked at every step:
// - the vertices inside the disk are those of the start, at the same
//   places relative to its centre (to 1e-9 h), so the fictitious boundary
//   sees the same body all along;
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

  /** The vertices inside the disk at @p centre, relative to it, sorted. */
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
  p.carried_zone_fade  = 0.2;
  p.readaptation_aspect_ratio = 1.001;
  MovingMesh<2> moving(mesh, p);

  Point<2> centre(0.5 + 0.3 * h, 1.5 + 0.2 * h);
  moving.adapt(disk_at(centre));
  const auto start = inside_relative(moving.hierarchy().get_vertices(), centre);
  const auto undeformed     = moving.hierarchy().get_vertices();
  const double step         = 0.37 * h;
  unsigned int fresh_starts = 0, changed_sets = 0, plain_changes = 0;
  double       worst_quality = 1., largest_offset = 0.;
  for (unsigned int n = 1; n <= 24; ++n)
    {
      centre[1] -= step;
      const auto report = moving.follow(disk_at(centre), [&](const Point<2> &) {
        return Tensor<1, 2>({0., -step});
      });
      fresh_starts += report.readapted;
      worst_quality
        = std::min(worst_quality, report.quality.min_scaled_jacobian);
      const auto now
        = inside_relative(moving.hierarchy().get_vertices(), centre);
      if (now.size() != start.size())
        ++changed_sets;
      else
        for (unsigned int i = 0; i < now.size(); ++i)
          largest_offset
            = std::max(largest_offset, (now[i] - start[i]).norm() / h);
      plain_changes
        += inside_relative(undeformed, centre).size() != start.size();
    }
  std::cout << "fresh starts in " << fresh_starts << " of 24 steps; "
            << start.size() << " vertices inside the disk; the set changed in "
            << changed_sets << " steps, largest offset " << largest_offset
            << " h; from the undeformed mesh the count would change in "
            << plain_changes << " steps; worst scaled Jacobian "
            << worst_quality << "\n";
  CHECK_MSG(fresh_starts >= 12, "most steps start afresh");
  CHECK_MSG(plain_changes > 0,
            "the path puts the disk elsewhere among the undeformed vertices");
  CHECK_MSG(changed_sets == 0 && largest_offset < 1e-9,
            "the disk keeps its vertices through every fresh start");
  CHECK_MSG(worst_quality >= p.min_quality - 1e-12,
            "no cell below the quality bound");

  // the mesh turned by 0.2 rad about the disk's centre
  std::vector<Point<2>> turned = undeformed;
  for (auto &x : turned)
    {
      const Tensor<1, 2> r = x - centre;
      x                    = centre
          + Tensor<1, 2>({std::cos(0.2) * r[0] - std::sin(0.2) * r[1],
                          std::sin(0.2) * r[0] + std::cos(0.2) * r[1]});
    }
  CHECK_MSG(realigned_zones(turned, undeformed, disk_at(centre), 0.05).empty(),
            "a zone that turned with its body is not realigned");
  return test::finish("deformation_carried_zone_realignment");
}
