// The bodies' surfaces in ParaView (BodySurfaceWriter): a rotated, spinning
// box, a sphere and a capsule above a floor (a half-space, which has no
// surface to draw). Each bounded body's piece must hold its display
// triangulation: as many points and triangles as the mesh, every point on
// the body's surface at its pose (|signed distance| < 1e-8 m, the file's ten
// digits), the point velocity the rigid motion's v + omega x (x - X) (to
// 1e-8 m/s), the cell ids the body's id; each body's series lists its
// pieces, the multiblock file of a call names every body's piece, its series
// one file per call, and a writer resumed from the written series goes on
// with all of them. With one file per call, that file holds every surface.
#include <particulate/geometry/box.h>
#include <particulate/geometry/capsule.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/sphere.h>
#include <particulate/rigid/body_surface_writer.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_tools.h"

using namespace particulate;
using Eigen::Vector3d;

namespace {
  /** The numbers of the @p index-th DataArray of the file @p text. */
  std::vector<double>
  data_array(const std::string &text, const unsigned int index)
  {
    std::size_t at = 0;
    for (unsigned int i = 0; i <= index; ++i)
      at = text.find("<DataArray", at) + 1;
    const std::size_t   begin = text.find('>', at) + 1;
    const std::size_t   end   = text.find("</DataArray>", begin);
    std::istringstream  in(text.substr(begin, end - begin));
    std::vector<double> values;
    for (double v; in >> v;)
      values.push_back(v);
    return values;
  }
} // namespace

int
main()
{
  rigid::World       world;
  const unsigned int steel = world.add_material(rigid::Material());
  world.add_body(std::make_shared<geometry::HalfSpace>(Vector3d(0., 0., 1.),
                                                       0.),
                 steel,
                 Vector3d::Zero(),
                 Eigen::Quaterniond::Identity(),
                 true);
  const Eigen::Quaterniond turned(
    Eigen::AngleAxisd(0.7, Vector3d(1., 2., 3.).normalized()));
  const rigid::BodyId box
    = world.add_body(std::make_shared<geometry::Box>(Vector3d(0.3, 0.2, 0.1)),
                     steel,
                     Vector3d(1., 0., 1.),
                     turned);
  world.body(box).linear_velocity  = Vector3d(0.5, -1., 2.);
  world.body(box).angular_velocity = Vector3d(3., 1., -2.);
  world.add_body(std::make_shared<geometry::Sphere>(0.25),
                 steel,
                 Vector3d(-1., 0.5, 0.6));
  world.add_body(std::make_shared<geometry::Capsule>(0.1, 0.3),
                 steel,
                 Vector3d(0., -1., 0.8),
                 turned.inverse());

  std::filesystem::create_directories("body_surface_files");
  rigid::BodySurfaceWriter writer("body_surface_files/surfaces");
  writer.write(world);
  const std::string name = writer.write(world);
  CHECK(name == "body_surface_files/surfaces_00001.vtm", name);

  const auto read = [](const std::string &file) {
    std::ifstream in(file);
    return std::string((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
  };
  const std::string blocks   = read(name);
  std::size_t       n_points = 0, n_triangles = 0;
  for (rigid::BodyId b = 1; b < world.n_bodies(); ++b)
    {
      // the multiblock file names the body's own piece, which its own
      // series lists
      const std::string piece = "body_" + std::to_string(b) + "_00001.vtp";
      CHECK(blocks.find("name=\"body " + std::to_string(b)
                        + "\" file=\"surfaces/" + piece + "\"")
              != std::string::npos,
            blocks);
      const std::string own = read("body_surface_files/surfaces/body_"
                                   + std::to_string(b) + ".pvd");
      CHECK(own.find("body_" + std::to_string(b) + "_00000.vtp")
                != std::string::npos
              && own.find(piece) != std::string::npos,
            own);
      const std::string text = read("body_surface_files/surfaces/" + piece);
      // arrays: points, connectivity, offsets, velocity, id, fixed
      const std::vector<double> points   = data_array(text, 0),
                                offsets  = data_array(text, 2),
                                velocity = data_array(text, 3),
                                ids      = data_array(text, 4);
      const rigid::RigidBody      &body  = world.body(b);
      const geometry::TriangleMesh mesh  = body.shape().surface_mesh();
      CHECK(points.size() == 3 * mesh.n_vertices(),
            points.size() / 3 << " points of body " << b << ", expected "
                              << mesh.n_vertices());
      CHECK(offsets.size() == mesh.n_triangles()
              && ids.size() == mesh.n_triangles(),
            offsets.size() << " triangles of body " << b << ", expected "
                           << mesh.n_triangles());
      for (std::size_t k = 0; k < mesh.n_vertices(); ++k)
        {
          const std::size_t p = 3 * k;
          const Vector3d    x(points[p], points[p + 1], points[p + 2]);
          const Vector3d    v(velocity[p], velocity[p + 1], velocity[p + 2]);
          CHECK(std::abs(body.signed_distance(x)) < 1e-8,
                "body " << b << " point " << k << " off the surface by "
                        << body.signed_distance(x));
          const Vector3d rigid_velocity
            = body.linear_velocity
              + body.angular_velocity.cross(x - body.position);
          CHECK((v - rigid_velocity).norm() < 1e-8,
                "body " << b << " point " << k << " velocity "
                        << v.transpose());
        }
      for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
        CHECK(ids[t] == b, "triangle of body " << b);
      n_points += mesh.n_vertices();
      n_triangles += mesh.n_triangles();
    }
  CHECK(blocks.find("body 0") == std::string::npos,
        "the floor, unbounded, has no surface");

  const std::string series = read("body_surface_files/surfaces.pvd");
  CHECK(series.find("surfaces_00000.vtm") != std::string::npos
          && series.find("surfaces_00001.vtm") != std::string::npos,
        series);

  // a restarted run continues every series from the checkpointed one
  rigid::BodySurfaceWriter resumed("body_surface_files/surfaces");
  resumed.resume(writer.written());
  CHECK(resumed.write(world) == "body_surface_files/surfaces_00002.vtm",
        "the resumed series goes on counting");
  const std::string own = read("body_surface_files/surfaces/body_2.pvd");
  CHECK(own.find("body_2_00000.vtp") != std::string::npos
          && own.find("body_2_00002.vtp") != std::string::npos,
        own);
  std::cout << n_points << " points, " << n_triangles
            << " triangles of 3 bodies, each its own series: OK\n";

  // one file per call: every surface in one piece, told apart by id
  rigid::BodySurfaceWriter one("body_surface_files/all",
                               rigid::BodySurfaceWriter::Layout::one_file);
  for (unsigned int call = 0; call < 3; ++call)
    one.write(world);
  const std::string all = read("body_surface_files/all_00002.vtp");
  CHECK(all.find("NumberOfPoints=\"" + std::to_string(n_points) + "\"")
            != std::string::npos
          && all.find("NumberOfPolys=\"" + std::to_string(n_triangles) + "\"")
               != std::string::npos,
        "one piece holds all " << n_points << " points");
  std::vector<std::size_t> triangles_of(world.n_bodies(), 0);
  for (const double id : data_array(all, 4))
    ++triangles_of.at(std::size_t(id));
  for (rigid::BodyId b = 1; b < world.n_bodies(); ++b)
    CHECK(triangles_of[b] == world.body(b).shape().surface_mesh().n_triangles(),
          "body " << b << " has " << triangles_of[b] << " triangles");
  CHECK(!std::filesystem::exists("body_surface_files/all"),
        "no folder of per-body pieces");

  // the series file is appended to, and stays a valid collection; one
  // that is not as the writer left it is written anew
  const auto count = [](const std::string &text, const std::string &what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos;
         at             = text.find(what, at + 1))
      ++n;
    return n;
  };
  const std::string appended = read("body_surface_files/all.pvd");
  CHECK(count(appended, "<DataSet") == 3
          && count(appended, "</Collection>") == 1 && appended.size() > 11
          && appended.substr(appended.size() - 11) == "</VTKFile>\n"
          && appended.find("all_00002.vtp") != std::string::npos,
        appended);
  std::ofstream("body_surface_files/all.pvd", std::ios::app) << "junk\n";
  one.write(world);
  const std::string rewritten = read("body_surface_files/all.pvd");
  CHECK(count(rewritten, "<DataSet") == 4 && count(rewritten, "junk") == 0
          && rewritten.substr(0, appended.size() - 27)
               == appended.substr(0, appended.size() - 27),
        rewritten);
  std::cout << "one file per call, the series appended: OK\n";
  return 0;
}
