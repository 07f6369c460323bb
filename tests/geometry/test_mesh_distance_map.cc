// Distance maps of real surface meshes (CGAL's bunny and elephant): the sign
// of the interpolated distance must agree with CGAL's exact side-of-mesh
// test at every random point farther than one map cell from the surface
// (issue 4). Usage: geometry_mesh_distance_map [points per mesh]
// (default 100000; the validation run uses 10^6).
#include <particulate/geometry/distance_map.h>
#include <particulate/geometry/mesh_io.h>
#include <particulate/geometry/triangulated_surface.h>

#include <chrono>
#include <cmath>
#include <random>
#include <sstream>

#include "check.h"

using namespace particulate::geometry;
using Eigen::Vector3d;

int
main(int argc, char **argv)
{
  const std::string dir      = test::cgal_meshes_or_skip();
  const long        n_points = argc > 1 ? std::atol(argv[1]) : 100000;

  for (const char *name : {"bunny00.off", "elephant.off"})
    {
      const TriangleMesh        mesh = read_surface_mesh(dir + "/" + name);
      const TriangulatedSurface surface(mesh);
      const BoundingBox         box = mesh.bounding_box();
      // 96 cells along the longest side, margin 5 cells.
      const double      h   = box.extent().maxCoeff() / 96.;
      const auto        t0  = std::chrono::steady_clock::now();
      const DistanceMap map = DistanceMap::build(surface, {h, 5 * h, 2});
      const double      build_s
        = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
            .count();

      // At the grid points themselves the pseudo-normal sign must match the
      // exact side test everywhere (not only far from the surface).
      long grid_mismatch = 0, grid_checked = 0;
      for (int k = 0; k < map.n_points()[2]; ++k)
        for (int j = 0; j < map.n_points()[1]; ++j)
          for (int i = 0; i < map.n_points()[0]; ++i)
            {
              const Vector3d p = map.point(i, j, k);
              if (map.value(i, j, k) == 0.)
                continue;
              ++grid_checked;
              grid_mismatch
                += ((map.value(i, j, k) < 0.) != surface.contains(p));
            }

      std::mt19937                           rng(2024);
      std::uniform_real_distribution<double> u(0., 1.);
      const BoundingBox                      gb = map.grid_box();
      long   compared = 0, mismatched = 0, inside = 0;
      double max_err = 0., sum_err2 = 0.;
      for (long s = 0; s < n_points; ++s)
        {
          const Vector3d p
            = gb.lower
              + gb.extent().cwiseProduct(Vector3d(u(rng), u(rng), u(rng)));
          const double exact_unsigned = surface.unsigned_distance(p);
          if (exact_unsigned <= h)
            continue;
          const bool   exact_inside = surface.contains(p);
          const double d            = map.distance(p);
          ++compared;
          inside += exact_inside;
          if ((d <= 0.) != exact_inside)
            {
              ++mismatched;
              if (mismatched <= 5)
                std::cerr << "  mismatch at " << p.transpose() << ": map " << d
                          << ", exact inside " << exact_inside
                          << ", exact distance " << exact_unsigned << "\n";
            }
          const double err = std::abs(std::abs(d) - exact_unsigned);
          max_err          = std::max(max_err, err);
          sum_err2 += err * err;
        }
      std::cout << name << ": " << mesh.n_triangles() << " triangles, grid "
                << map.n_points()[0] << " x " << map.n_points()[1] << " x "
                << map.n_points()[2] << ", h = " << h << ", built in "
                << build_s << " s\n  " << grid_checked
                << " grid points vs side-of-mesh: " << grid_mismatch
                << " mismatches\n  " << compared << " of " << n_points
                << " random points farther than h from the surface (" << inside
                << " inside): " << mismatched
                << " sign mismatches; distance error rms "
                << std::sqrt(sum_err2 / compared) << " = "
                << std::sqrt(sum_err2 / compared) / h << " h, max " << max_err
                << " = " << max_err / h << " h" << std::endl;
      CHECK_MSG(grid_mismatch == 0,
                std::string(name) + ": grid-point signs agree with CGAL");
      CHECK_MSG(mismatched == 0,
                std::string(name)
                  + ": map sign agrees with CGAL side-of-mesh "
                    "farther than one cell from the surface");
      CHECK_MSG(compared > n_points / 2 && inside > 0,
                std::string(name) + ": enough points compared");
      // Trilinear interpolation of a distance function: the error is bounded
      // by the cell's half diagonal (a Lipschitz-1 function).
      CHECK(max_err < 0.87 * h);
    }
  return test::finish("geometry_mesh_distance_map");
}
