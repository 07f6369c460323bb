// How well a box mesh sees a real surface (thesis §6.6): a closed surface
// mesh from CGAL's sample data in a box of hexahedra, the mesh adapted to it
// with Laplace-kappa or not, at the same vertex count. The discrete body is
// the set of solid cells (centre inside the surface); its boundary faces are
// compared with the true surface by the Hausdorff distance
//   max( max over face points of |d|, max over surface points of the
//        distance to the nearest face point ),
// with face points = face vertices and centres, surface points = the
// triangle vertices and centroids, and by the error of the enclosed volume
// (deformation::measure_surface_resolution, which a 3D particulate-flow run
// also reports for its surface-mesh bodies).
// A slice through the middle of the body is written for the figure.
//
// Usage: deformation_geometry_resolution SURFACE.off OUTPUT_DIR [LEVELS]
// (CGAL's pig.off and plane.off are open surfaces, which the reader
// rejects; the test uses the closed elephant.off.)
// Checks (exit 1 if violated): on every level Laplace-kappa leaves no cell
// below its quality bound and brings the faces of the discrete body closer
// to the surface (mean distance). The Hausdorff distance is reported; on
// coarse levels it is set by features thinner than a cell (the trunk and
// tail of the elephant), which no vertex motion resolves.

#include <particulate/deformation/distance_field.h>
#include <particulate/deformation/laplace_smoothing.h>
#include <particulate/deformation/mesh_quality.h>
#include <particulate/deformation/surface_resolution.h>
#include <particulate/geometry/mesh_io.h>
#include <particulate/geometry/triangulated_surface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace particulate;
using namespace particulate::deformation;

namespace {
  /** The cells cut by the plane z = @p z, as polygons, for the figure. */
  void
  write_slice(const Triangulation<3> &tria,
              const double            z,
              const std::string      &path)
  {
    std::ofstream out(path);
    for (const auto &cell : tria.active_cell_iterators())
      {
        std::vector<Point<2>> points;
        for (unsigned int l = 0; l < GeometryInfo<3>::lines_per_cell; ++l)
          {
            const Point<3> a = cell->line(l)->vertex(0),
                           b = cell->line(l)->vertex(1);
            if ((a[2] - z) * (b[2] - z) < 0.)
              {
                const double t = (z - a[2]) / (b[2] - a[2]);
                points.emplace_back(a[0] + t * (b[0] - a[0]),
                                    a[1] + t * (b[1] - a[1]));
              }
          }
        if (points.size() < 3)
          continue;
        Point<2> c;
        for (const auto &p : points)
          c += p / double(points.size());
        std::sort(points.begin(), points.end(), [&](auto &p, auto &q) {
          return std::atan2(p[1] - c[1], p[0] - c[0])
                 < std::atan2(q[1] - c[1], q[0] - c[0]);
        });
        for (const auto &p : points)
          out << p << '\n';
        out << points.front() << "\n\n";
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 3)
    {
      std::cerr << "usage: " << argv[0] << " SURFACE OUTPUT_DIR [LEVELS]\n";
      return 2;
    }
  const std::string  output    = argv[2];
  const unsigned int max_level = argc > 3 ? std::stoi(argv[3]) : 2;
  std::filesystem::create_directories(output);

  geometry::TriangleMesh mesh;
  try
    {
      mesh = geometry::read_surface_mesh(argv[1]);
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << '\n';
      return 2;
    }
  const geometry::TriangulatedSurface surface(mesh);
  Eigen::Vector3d lower = mesh.vertices[0], upper = mesh.vertices[0];
  for (const auto &v : mesh.vertices)
    {
      lower = lower.cwiseMin(v);
      upper = upper.cwiseMax(v);
    }
  const double          size        = (upper - lower).maxCoeff();
  const double          true_volume = surface.volume();
  const Eigen::Vector3d centre      = 0.5 * (lower + upper);
  // A box 1.6 times the body's largest extent, 8 coarse cells a side.
  const Point<3> box_lower(centre[0] - 0.8 * size,
                           centre[1] - 0.8 * size,
                           centre[2] - 0.8 * size);
  const Point<3> box_upper(centre[0] + 0.8 * size,
                           centre[1] + 0.8 * size,
                           centre[2] + 0.8 * size);
  // Slightly off the middle, so that the plane meets no mesh vertex.
  const double                slice_z = centre[2] + 0.013 * size;
  const ShapeDistanceField<3> distance({{&surface, geometry::Pose()}});

  std::ofstream dat(output + "/geometry-resolution.dat");
  dat << "# level cells h method hausdorff/size mean_face_distance/size "
         "volume_error min_scaled_jacobian held_back seconds\n";
  std::cout << "surface " << argv[1] << ": " << mesh.triangles.size()
            << " triangles, extent " << size << ", volume " << true_volume
            << "\n\n level  cells     h/size  method         Hausdorff/size  "
               "mean |d|/size  volume err  min SJ   s\n";
  bool ok = true;
  for (unsigned int level = 0; level <= max_level; ++level)
    {
      double mean_plain = 0.;
      for (const bool adapt : {false, true})
        {
          Triangulation<3> tria;
          GridGenerator::subdivided_hyper_rectangle(tria,
                                                    {8, 8, 8},
                                                    box_lower,
                                                    box_upper);
          tria.refine_global(level);
          const double      h = 1.6 * size / (8 << level);
          Timer             timer;
          DeformationReport report;
          if (adapt)
            {
              SmoothingSettings s;
              s.width            = 2. * h * (1 << level); // two coarse cells
              s.sweeps_per_level = {4};
              report             = LaplaceKappa<3>(s).deform(tria, distance);
            }
          else
            report.quality = compute_mesh_quality(tria);
          const double            seconds = timer.wall_time();
          const SurfaceResolution r
            = measure_surface_resolution(tria, surface, geometry::Pose());
          const std::string name = adapt ? "Laplace-kappa" : "not adapted";
          dat << level << ' ' << tria.n_active_cells() << ' ' << h / size << ' '
              << (adapt ? "laplace-kappa" : "none") << ' ' << r.hausdorff / size
              << ' ' << r.mean_face_distance / size << ' ' << r.volume_error
              << ' ' << report.quality.min_scaled_jacobian << ' '
              << report.held_back_vertices << ' ' << seconds << '\n';
          std::cout << std::setw(6) << level << std::setw(7)
                    << tria.n_active_cells() << std::setw(11)
                    << std::setprecision(4) << h / size << "  " << std::left
                    << std::setw(15) << name << std::right << std::setw(14)
                    << r.hausdorff / size << std::setw(15)
                    << r.mean_face_distance / size << std::setw(12)
                    << r.volume_error << std::setw(8)
                    << report.quality.min_scaled_jacobian << std::setw(8)
                    << std::setprecision(3) << seconds << '\n';
          write_slice(tria,
                      slice_z,
                      output + "/slice-level" + std::to_string(level) + "-"
                        + (adapt ? "kappa" : "plain") + ".dat");
          if (!adapt)
            mean_plain = r.mean_face_distance;
          else if (!(r.mean_face_distance < mean_plain
                     && report.quality.min_scaled_jacobian >= 0.2))
            {
              std::cout << "FAIL: Laplace-kappa did not improve level " << level
                        << '\n';
              ok = false;
            }
        }
    }
  // The body's own section for the figure.
  std::ofstream section(output + "/slice-surface.dat");
  for (const auto &t : mesh.triangles)
    {
      std::vector<Eigen::Vector3d> cut;
      for (int k = 0; k < 3; ++k)
        {
          const Eigen::Vector3d a = mesh.vertices[t[k]],
                                b = mesh.vertices[t[(k + 1) % 3]];
          if ((a[2] - slice_z) * (b[2] - slice_z) < 0.)
            cut.push_back(a + (slice_z - a[2]) / (b[2] - a[2]) * (b - a));
        }
      if (cut.size() == 2)
        section << cut[0][0] << ' ' << cut[0][1] << '\n'
                << cut[1][0] << ' ' << cut[1][1] << "\n\n";
    }
  std::cout << (ok ? "\nall checks passed\n" : "\nCHECKS FAILED\n");
  return ok ? 0 : 1;
}
