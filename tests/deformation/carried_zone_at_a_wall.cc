// A body that moves about a cell per step towards a wall, with 'Moving
// bodies = carry neighbourhood' (MovingMesh::follow told where the step
// starts): a disk of radius 0.1 sinks towards the floor of [0, 1] x [0, 2]
// (h = 1/32), its zone (0.05) fading over 0.3, so that the floor lies
// within the fade and the cells between disk and floor are pressed flat,
// down to a gap of 1.3 h. A fresh start made where the step starts is
// carried over the step, which presses those cells by nearly the step.
// - Sinking by 0.9 h per step: the fresh start's zone is realigned to the
//   lattice translation nearest to where the step takes it, so that the
//   carry never presses a cell by more than the step and half a cell.
//   Checked: every fresh start is made where the step starts, no cell
//   inverts or falls below the quality bound, and the vertices inside the
//   disk keep their places relative to it throughout. (Realigned to the
//   translation nearest to where the step starts instead, the fresh start
//   carried over the step inverts the cell between disk and floor.)
// - Sinking by 1.2 h per step and turning by 0.05 rad per step: a turned
//   zone is not realigned, the fresh start is the undeformed mesh, and its
//   carry over the step would invert that cell. Checked: follow() makes
//   such a fresh start where the disk is now, and no cell inverts or falls
//   below the quality bound.

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
#include "disk_in_channel.h"

using namespace dealii;
using namespace particulate;
using namespace particulate::deformation;

namespace {
  using sinking_disk::disk_at;
  using sinking_disk::inside_relative;
  const double radius = sinking_disk::disk_radius,
               h      = sinking_disk::channel_cell;

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

  const core::MeshParameters mesh = sinking_disk::uniform_channel();

  DeformationParameters p;
  p.method             = DeformationParameters::Method::none;
  p.following          = DeformationParameters::Following::carry_neighbourhood;
  p.carried_zone_width = 0.05;
  p.carried_zone_fade  = 0.3;

  for (const bool turning : {false, true})
    {
      MovingMesh<2> moving(mesh, p);
      const double  step = (turning ? 1.2 : 0.9) * h;
      const double  turn = turning ? 0.05 : 0.;
      Point<2>      at(0.5 + 0.3 * h, radius + 8.5 * h);
      moving.adapt(disk_at(at));
      const auto start = inside_relative(moving.hierarchy().get_vertices(), at);

      unsigned int fresh_at_step_start = 0, fresh_where_now = 0, n = 0;
      double       worst_quality = 1., offset = 0.;
      while (at[1] - radius - step > 1.3 * h - 1e-12)
        {
          ++n;
          const Point<2> before = at;
          at[1] -= step;
          const auto was    = disk_at(before);
          const auto report = moving.follow(
            disk_at(at),
            [&](const Point<2> &x) {
              const Tensor<1, 2> r = x - before;
              return at - x
                     + Tensor<1, 2>(
                       {std::cos(turn) * r[0] - std::sin(turn) * r[1],
                        std::sin(turn) * r[0] + std::cos(turn) * r[1]});
            },
            &was);
          worst_quality
            = std::min(worst_quality, report.quality.min_scaled_jacobian);
          if (turning)
            {
              if (report.readapted)
                {
                  fresh_at_step_start += !moving.fresh_start_vertices().empty();
                  fresh_where_now += moving.fresh_start_vertices().empty();
                }
              continue;
            }
          offset
            = std::max(offset,
                       largest_offset(
                         inside_relative(moving.hierarchy().get_vertices(), at),
                         start));
          if (!report.readapted)
            continue;
          if (moving.fresh_start_vertices().empty())
            ++fresh_where_now;
          else
            {
              ++fresh_at_step_start;
              offset = std::max(
                offset,
                largest_offset(inside_relative(moving.fresh_start_vertices(),
                                               before),
                               start));
            }
        }
      const std::string name = turning ? "sinking and turning" : "sinking";
      std::cout << name << ": " << n << " steps to a gap of "
                << (at[1] - radius) / h
                << " h; fresh starts where the step starts: "
                << fresh_at_step_start
                << ", where the disk is now: " << fresh_where_now
                << "; worst scaled Jacobian " << worst_quality;
      if (!turning)
        std::cout << "; " << start.size()
                  << " vertices inside the disk, largest offset from their "
                     "start "
                  << offset << " h";
      std::cout << "\n";
      CHECK_MSG(worst_quality >= p.min_quality - 1e-12,
                name + ": no cell inverts or falls below the quality bound");
      if (turning)
        CHECK_MSG(fresh_where_now > 0,
                  name
                    + ": a fresh start that the step's carry would "
                      "invert is made where the disk is now");
      else
        {
          CHECK_MSG(fresh_at_step_start > 0 && fresh_where_now == 0,
                    name + ": every fresh start is made where the step starts");
          CHECK_MSG(offset < 1e-9,
                    name
                      + ": the disk keeps its vertices through every "
                        "fresh start");
        }
    }
  return test::finish("deformation_carried_zone_at_a_wall");
}
