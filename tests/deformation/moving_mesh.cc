// A mesh that follows a moving body (deformation::MovingMesh, thesis §6.3):
// the oscillating-cylinder set-up of prm/oscillating-cylinder (channel
// 2.2 x 0.41 on 11 x 2 coarse cells, disk D = 0.1 centred on a coarse edge)
// swept over a quarter of its path. For Laplace-kappa and Laplace-alpha:
// - no cell ever inverts or degenerates (scaled Jacobian above the bound,
//   bounded aspect ratio), also where the disk swallows a coarse edge whole;
// - Laplace-alpha keeps vertices on the circle all along the path;
// - with 'Moving bodies = carry surface vertices' no vertex crosses the
//   circle between two fresh adaptations, which are rare;
// - with 'carry neighbourhood' (on the plain mesh, 'Method = none') the
//   vertices near the disk keep their place relative to it (none crosses
//   the circle) while the channel's ends stay put, without a fresh
//   adaptation on this path;
// - copied into a distributed mesh, every cell has the serial positions.

#include <particulate/core/mesh.h>
#include <particulate/deformation/distance_field.h>
#include <particulate/deformation/moving_mesh.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "../geometry/check.h"

using namespace dealii;
using namespace particulate;
using namespace particulate::deformation;

namespace {
  FunctionDistanceField<2>
  disk_at(const double x_centre)
  {
    return FunctionDistanceField<2>([x_centre](const Point<2> &x) {
      return x.distance(Point<2>(x_centre, 0.2)) - 0.05;
    });
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  core::MeshParameters mesh;
  mesh.type         = core::MeshParameters::Type::hyper_rectangle;
  mesh.lower_corner = {0., 0.};
  mesh.upper_corner = {2.2, 0.41};
  mesh.subdivisions = {11, 2};
  mesh.refinements  = 4;

  for (const auto following : {0, 1, 2, 3})
    {
      const bool neighbourhood = following == 3;
      const auto method
        = following == 0 ? DeformationParameters::Method::laplace_kappa :
          neighbourhood  ? DeformationParameters::Method::none :
                           DeformationParameters::Method::laplace_alpha;
      const bool            carry = following >= 2;
      DeformationParameters p;
      p.method = method;
      p.width  = 0.1;
      if (following == 2)
        p.following = DeformationParameters::Following::carry_surface;
      if (neighbourhood)
        {
          p.following = DeformationParameters::Following::carry_neighbourhood;
          p.carried_zone_width = 0.03;
          p.carried_zone_fade  = 0.3;
        }
      MovingMesh<2>     moving(mesh, p);
      const std::string name = moving.method_name()
                               + (neighbourhood ? " (neighbourhood carried)" :
                                  carry         ? " (carried)" :
                                                  "");
      // carry neighbourhood: the vertices within the carried zone at the
      // start, and where they are relative to the disk
      // (and the vertices on the channel's ends)
      std::vector<std::pair<unsigned int, Tensor<1, 2>>> near_disk;
      std::vector<std::pair<unsigned int, Point<2>>>     channel_ends;
      for (unsigned int v = 0; v < moving.hierarchy().n_vertices(); ++v)
        {
          const Point<2> &x = moving.hierarchy().get_vertices()[v];
          if (neighbourhood && x.distance(Point<2>(1.1, 0.2)) < 0.05 + 0.03)
            near_disk.emplace_back(v, x - Point<2>(1.1, 0.2));
          if (std::abs(x[0]) < 1e-9 || std::abs(x[0] - 2.2) < 1e-9)
            channel_ends.emplace_back(v, x);
        }
      unsigned int readaptations = 0, crossings = 0;
      long         inside_before = -1;
      double       x_previous    = 1.1;

      // quarter period of x_c = 1.1 + 0.25 sin(2 pi t / 4) in 25 steps
      double       worst_quality = 1., worst_aspect = 1.;
      unsigned int fewest_projected = std::numeric_limits<unsigned int>::max();
      for (unsigned int step = 0; step <= 25; ++step)
        {
          const double x_c
            = 1.1 + 0.25 * std::sin(2. * M_PI * 0.25 * (step * 0.04));
          const auto report
            = moving.follow(disk_at(x_c), [&](const Point<2> &) {
                return Tensor<1, 2>({x_c - x_previous, 0.});
              });
          x_previous = x_c;
          // vertices strictly inside the disk: a carried mesh moves none
          // across the circle
          long inside = 0;
          for (const auto &x : moving.hierarchy().get_vertices())
            inside += x.distance(Point<2>(x_c, 0.2)) < 0.05 - 1e-6;
          if (report.readapted)
            ++readaptations;
          else if (inside != inside_before)
            ++crossings;
          inside_before = inside;
          worst_quality
            = std::min(worst_quality, report.quality.min_scaled_jacobian);
          worst_aspect
            = std::max(worst_aspect, report.quality.max_aspect_ratio);
          fewest_projected
            = std::min(fewest_projected, report.projected_vertices);
        }
      std::cout << name << ": worst min scaled Jacobian " << worst_quality
                << ", worst aspect ratio " << worst_aspect
                << ", fewest vertices on the circle " << fewest_projected
                << "; adapted afresh in " << readaptations
                << " of 26 steps, vertices crossed the circle in " << crossings
                << " carried steps\n";
      CHECK_MSG(worst_quality >= p.min_quality - 1e-12,
                name + ": no cell below the quality bound on the whole path");
      CHECK_MSG(worst_aspect < 20.,
                name + ": no degenerate cell (aspect ratio below 20)");
      // the circumference is 25 cells of h = 0.0125 long
      if (neighbourhood)
        {
          const Point<2> centre(x_previous, 0.2);
          double         moved_off = 0.;
          for (const auto &[v, offset] : near_disk)
            moved_off = std::max(
              moved_off,
              (moving.hierarchy().get_vertices()[v] - centre - offset).norm());
          double ends_moved = 0.;
          for (const auto &[v, x] : channel_ends)
            ends_moved
              = std::max(ends_moved,
                         moving.hierarchy().get_vertices()[v].distance(x));
          std::cout << name << ": " << near_disk.size()
                    << " vertices near the disk off their place relative to "
                       "it by "
                    << moved_off << ", channel ends off by " << ends_moved
                    << '\n';
          CHECK_MSG(readaptations == 1,
                    name
                      + ": adapted only at the start (a fade of 0.3 takes "
                        "the quarter period's 0.25)");
          CHECK_MSG(moved_off < 1e-12,
                    name
                      + ": the vertices within the carried zone move "
                        "rigidly with the disk");
          CHECK_MSG(ends_moved < 1e-12, name + ": the channel's ends stay put");
        }
      if (method == DeformationParameters::Method::laplace_alpha)
        CHECK_MSG(fewest_projected >= 16,
                  name
                    + ": at least 16 vertices on the circle at every "
                      "position");
      if (carry)
        {
          CHECK_MSG(crossings == 0,
                    name + ": no vertex crosses the circle while carried");
          CHECK_MSG(readaptations < 26 / 2,
                    name + ": adapted afresh in fewer than half the steps");
        }
      else
        CHECK_MSG(readaptations == 26,
                  name + ": 'Moving bodies = re-adapt' adapts every step");

      // the distributed copy
      parallel::fullydistributed::Triangulation<2> tria(MPI_COMM_WORLD);
      core::create_mesh(mesh, tria);
      moving.copy_vertices_to(tria);
      double mismatch = 0.;
      for (const auto &cell : tria.active_cell_iterators())
        if (!cell->is_artificial())
          {
            const auto twin
              = moving.hierarchy().create_cell_iterator(cell->id());
            for (const auto v : cell->vertex_indices())
              mismatch
                = std::max(mismatch, cell->vertex(v).distance(twin->vertex(v)));
          }
      mismatch = Utilities::MPI::max(mismatch, MPI_COMM_WORLD);
      CHECK_MSG(mismatch == 0.,
                name + ": the distributed mesh has the serial positions");
    }
  return test::finish("deformation_moving_mesh");
}
