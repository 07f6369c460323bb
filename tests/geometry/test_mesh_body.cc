// A body from a surface-mesh file (load_mesh_body): an ellipsoid with
// semi-axes (2, 1.4, 1) x 0.01 m meshed as a scaled icosphere (5 120
// triangles), written in millimetres, turned by 0.5 rad about (1, 2, 3) and
// moved away from the origin:
// - the body frame found is the one the file was turned and moved by: the
//   centroid to 1e-12 of the size, the axes to 1e-9 (the icosphere keeps
//   the three mirror planes of the ellipsoid, so the axes are exact); an
//   aligned file keeps the identity exactly;
// - the shape is in its principal frame (centroid 0, diagonal inertia, as a
//   dynamic rigid body needs) with the polyhedron's exact volume;
// - its map answers the exact surface's distance near the surface (|d| <
//   2h) within the trilinear error h^2 / (8 R) of the most curved part
//   (R = c^2 / a: 0.05 h at the automatic h = c / 8; 0.071 h measured,
//   the polyhedron's edges add to it; bound 0.1 h), and the
//   inside test agrees with CGAL's exact one for every point more than
//   0.1 h from the surface;
// - the deepest map point is the smallest semi-axis c to within h;
// - a second load reads the map from the cache, with the same distances;
// - a scale of 0, a missing file and a map over the memory limit are
//   refused with what to do.
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mass_properties.h>
#include <particulate/geometry/mesh_body.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/mesh_io.h>

#include <Eigen/Geometry>

#include <filesystem>
#include <iostream>
#include <random>

#include "check.h"

using namespace particulate::geometry;
using Eigen::Vector3d;

namespace {
  const Vector3d semi_axes(0.02, 0.014, 0.01);

  /** The ellipsoid mesh in millimetres, turned by @p rotation and moved by
   *  @p shift [mm]. */
  std::string
  write_ellipsoid(const std::string     &name,
                  const Eigen::Matrix3d &rotation,
                  const Vector3d        &shift)
  {
    TriangleMesh mesh = mesh_generators::icosphere(1., 4);
    for (auto &v : mesh.vertices)
      v = rotation * (1000. * semi_axes).cwiseProduct(v) + shift;
    const std::string path
      = (std::filesystem::temp_directory_path() / name).string();
    write_surface_mesh(path, mesh);
    return path;
  }

  template <typename F>
  bool
  refused(F &&f, const std::string &words)
  {
    try
      {
        f();
      }
    catch (const GeometryError &e)
      {
        const std::string message = e.what();
        std::cout << "  refused: " << message << std::endl;
        return message.find(words) != std::string::npos;
      }
    return false;
  }
} // namespace

int
main()
{
  const Eigen::Matrix3d turn
    = Eigen::AngleAxisd(0.5, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Vector3d    shift(30., -12., 7.);
  const std::string turned
    = write_ellipsoid("mesh_body_turned.off", turn, shift);
  const std::string aligned = write_ellipsoid("mesh_body_aligned.off",
                                              Eigen::Matrix3d::Identity(),
                                              Vector3d::Zero());
  MeshBodyOptions   options;
  options.scale    = 0.001;
  const auto cache = std::filesystem::temp_directory_path() / "mesh_body_cache";
  std::filesystem::remove_all(cache);
  options.cache_folder = cache.string();

  const MeshBody body = load_mesh_body(turned, options);
  const double   size = semi_axes.maxCoeff();
  const double   h    = body.shape->map().spacing();
  std::cout << "map spacing " << h << " m, " << body.shape->map().n_points()[0]
            << " x " << body.shape->map().n_points()[1] << " x "
            << body.shape->map().n_points()[2] << " points" << std::endl;
  CHECK(std::abs(h - semi_axes.minCoeff() / 8.) < 1e-15);
  const double centre_error
    = (body.file_frame.translation() - 0.001 * shift).norm();
  const double axes_error = (body.file_frame.rotation() - turn).norm();
  std::cout << "frame: centroid off by " << centre_error << " m, axes by "
            << axes_error << std::endl;
  CHECK(centre_error <= 1e-12 * size);
  CHECK(axes_error <= 1e-9);
  CHECK(load_mesh_body(aligned, options).file_frame.rotation()
        == Eigen::Matrix3d::Identity());

  // the principal frame, with the exact polyhedron's mass properties
  const Shape          &shape = *body.shape;
  const Eigen::Matrix3d I     = shape.unit_inertia();
  const Eigen::Matrix3d off   = I - Eigen::Matrix3d(I.diagonal().asDiagonal());
  CHECK(shape.centroid().norm() <= 1e-12 * size);
  CHECK(off.cwiseAbs().maxCoeff() <= 1e-12 * I.diagonal().maxCoeff());
  CHECK(shape.volume() == body.shape->surface().volume());
  CHECK(std::abs(shape.volume() / (4. / 3. * M_PI * semi_axes.prod()) - 1.)
        < 0.01);

  // the map against the exact surface near it
  std::mt19937                           random(5);
  std::uniform_real_distribution<double> unit(-1., 1.);
  double                                 worst_distance = 0.;
  unsigned int                           disagreements = 0, compared = 0;
  for (unsigned int n = 0; n < 20000; ++n)
    {
      const Vector3d p
        = (semi_axes + Vector3d::Constant(3. * h))
            .cwiseProduct(Vector3d(unit(random), unit(random), unit(random)));
      const double exact = body.shape->surface().signed_distance(p);
      if (std::abs(exact) < 2. * h)
        worst_distance = std::max(worst_distance,
                                  std::abs(shape.signed_distance(p) - exact));
      if (std::abs(exact) > 0.1 * h)
        {
          ++compared;
          disagreements
            += shape.contains(p) != body.shape->surface().contains(p);
        }
    }
  std::cout << "largest map error near the surface " << worst_distance / h
            << " h; inside test: " << disagreements << " of " << compared
            << " differ" << std::endl;
  CHECK(worst_distance < 0.1 * h);
  CHECK(disagreements == 0);
  const double deepest = body.shape->map().deepest_inside();
  std::cout << "deepest map point " << deepest
            << " m (c = " << semi_axes.minCoeff() << ")" << std::endl;
  CHECK(std::abs(deepest - semi_axes.minCoeff()) < h);

  // the cache
  CHECK(!body.from_cache);
  const MeshBody again = load_mesh_body(turned, options);
  CHECK(again.from_cache);
  CHECK(again.shape->signed_distance(Vector3d(0.021, 0.001, -0.002))
        == shape.signed_distance(Vector3d(0.021, 0.001, -0.002)));

  // refusals
  MeshBodyOptions zero = options;
  zero.scale           = 0.;
  CHECK(
    refused([&] { load_mesh_body(turned, zero); }, "scale must be positive"));
  CHECK(refused([&] { load_mesh_body("no/such/file.stl", options); },
                "no/such/file.stl"));
  MeshBodyOptions small = options;
  small.memory_limit    = 1024;
  CHECK(refused([&] { load_mesh_body(turned, small); }, "would need"));

  std::filesystem::remove_all(cache);
  return test::finish("geometry_mesh_body");
}
