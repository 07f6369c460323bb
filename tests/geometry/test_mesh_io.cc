// Reading, checking and orienting surface meshes (issue: OFF/STL/OBJ/PLY via
// CGAL, refuse broken inputs with a message that says what is wrong).
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mass_properties.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/mesh_io.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "check.h"
#include <unistd.h>

using namespace particulate::geometry;
namespace fs = std::filesystem;

namespace {
  // Read @p path and expect a GeometryError containing @p expected.
  void
  expect_error(const std::string &path, const std::string &expected)
  {
    try
      {
        read_surface_mesh(path);
        CHECK_MSG(false,
                  "reading " + path + " should fail with '" + expected
                    + "' but succeeded");
      }
    catch (const GeometryError &e)
      {
        const std::string msg = e.what();
        std::cout << "  expected error for " << fs::path(path).filename()
                  << ":\n    " << msg << std::endl;
        CHECK_MSG(msg.find(expected) != std::string::npos,
                  "error for " + path + " should mention '" + expected
                    + "', got: " + msg);
        CHECK_MSG(msg.find(path) != std::string::npos,
                  "error should name the file " + path);
      }
  }

  void
  write_text(const std::string &path, const std::string &text)
  {
    std::ofstream(path, std::ios::binary) << text;
  }
} // namespace

int
main()
{
  const std::string dir = test::cgal_meshes_or_skip();
  const fs::path    tmp = fs::temp_directory_path()
                       / ("particulate_mesh_io_" + std::to_string(::getpid()));
  fs::create_directories(tmp);

  // Real meshes: closed and bounding a solid, positive volume.
  for (const char *name :
       {"bunny00.off", "elephant.off", "knot1.off", "sphere966.off"})
    {
      const TriangleMesh m = read_surface_mesh(dir + "/" + name);
      const double       V = compute_mass_properties(m).volume;
      std::cout << "  " << name << ": " << m.n_vertices() << " vertices, "
                << m.n_triangles() << " triangles, volume " << V << std::endl;
      CHECK_MSG(V > 0., std::string(name) + " encloses a positive volume");
      CHECK_MSG(check_surface_mesh(m).bounds_a_solid(),
                std::string(name) + " bounds a solid after reading");
    }

  // Every format round-trips a generated sphere with the same volume.
  const TriangleMesh sphere = mesh_generators::icosphere(1., 3);
  const double       V0     = compute_mass_properties(sphere).volume;
  for (const char *ext : {".off", ".stl", ".obj", ".ply"})
    {
      const std::string path = (tmp / ("sphere" + std::string(ext))).string();
      write_surface_mesh(path, sphere);
      const TriangleMesh m = read_surface_mesh(path);
      CHECK_MSG(m.n_triangles() == sphere.n_triangles(),
                std::string(ext) + " keeps the triangles");
      CHECK_MSG(std::abs(compute_mass_properties(m).volume - V0) < 1e-6 * V0,
                std::string(ext) + " keeps the volume");
    }

  // Inward and partly flipped orientations are repaired.
  {
    TriangleMesh inward = sphere;
    inward.flip_orientation();
    write_surface_mesh((tmp / "inward.off").string(), inward);
    const TriangleMesh a = read_surface_mesh((tmp / "inward.off").string());
    CHECK(std::abs(compute_mass_properties(a).volume - V0) < 1e-9 * V0);

    TriangleMesh mixed = sphere;
    for (std::size_t t = 0; t < mixed.triangles.size(); t += 7)
      std::swap(mixed.triangles[t][1], mixed.triangles[t][2]);
    CHECK(check_surface_mesh(mixed).inconsistent_edges > 0);
    write_surface_mesh((tmp / "mixed.off").string(), mixed);
    const TriangleMesh b = read_surface_mesh((tmp / "mixed.off").string());
    CHECK(std::abs(compute_mass_properties(b).volume - V0) < 1e-9 * V0);
    MeshReadOptions strict;
    strict.orient = false;
    bool threw    = false;
    try
      {
        read_surface_mesh((tmp / "mixed.off").string(), strict);
      }
    catch (const GeometryError &e)
      {
        threw = std::string(e.what()).find("inconsistently oriented")
                != std::string::npos;
      }
    CHECK_MSG(threw, "with orient = false flipped faces are an error");
  }

  // Broken inputs, each with its message.
  {
    TriangleMesh open = sphere;
    open.triangles.resize(open.triangles.size() - 4);
    write_surface_mesh((tmp / "open.off").string(), open);
    expect_error((tmp / "open.off").string(), "open: ");
    expect_error(dir + "/cube-ouvert.off", "open: ");
    // A real mesh with holes: CGAL's pig has 55 border edges.
    expect_error(dir + "/pig.off", "open: 55 border edges");
    // ... and CGAL's cow intersects itself.
    expect_error(dir + "/cow.off", "101 self-intersecting triangle pairs");

    // Three triangles on one edge (a fin glued to a tetrahedron).
    write_text((tmp / "fin.off").string(),
               "OFF\n5 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n"
               "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 1 4\n");
    expect_error((tmp / "fin.off").string(),
                 "non-manifold: 1 edges shared by more than two triangles");

    // Two tetrahedra touching in one vertex.
    write_text((tmp / "pinched.off").string(),
               "OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n"
               "0 0 -1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
               "3 0 4 5\n3 0 6 4\n3 0 5 6\n3 4 6 5\n");
    expect_error((tmp / "pinched.off").string(), "1 pinched vertices");

    // Two interpenetrating closed boxes in one file.
    TriangleMesh a = mesh_generators::box(Eigen::Vector3d(1, 1, 1));
    TriangleMesh b = a.transformed(
      Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0.3, 0.2)));
    const int off = static_cast<int>(a.vertices.size());
    for (const auto &v : b.vertices)
      a.vertices.push_back(v);
    for (const auto &t : b.triangles)
      a.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
    write_surface_mesh((tmp / "overlap.off").string(), a);
    expect_error((tmp / "overlap.off").string(),
                 "self-intersecting triangle pairs");

    write_text((tmp / "empty.off").string(), "");
    expect_error((tmp / "empty.off").string(), "could not be parsed");
    write_text((tmp / "nofaces.off").string(),
               "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
    expect_error((tmp / "nofaces.off").string(), "empty mesh");

    // Truncated: the first third of the bunny.
    {
      std::ifstream in(dir + "/bunny00.off", std::ios::binary);
      std::string   all((std::istreambuf_iterator<char>(in)), {});
      write_text((tmp / "truncated.off").string(),
                 all.substr(0, all.size() / 3));
      expect_error((tmp / "truncated.off").string(), "could not be parsed");
    }
    write_text((tmp / "garbage.stl").string(),
               "this is not a mesh at all \x01\x02\x03 \n");
    // CGAL's STL reader takes text without "solid" as an ASCII STL with no
    // facets, so garbage is reported as holding no faces.
    expect_error((tmp / "garbage.stl").string(), "no faces");
    write_text((tmp / "badindex.off").string(),
               "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    expect_error((tmp / "badindex.off").string(),
                 "face line 6 refers to vertex 7, but the header declares 3 "
                 "vertices");
    // A negative index (CGAL would convert it to an unsigned integer).
    write_text((tmp / "negindex.off").string(),
               "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n");
    expect_error((tmp / "negindex.off").string(), "refers to vertex -1");
    // A tetrahedron with a repeated vertex in one face.
    write_text((tmp / "degenerate.off").string(),
               "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
               "3 0 2 2\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    expect_error((tmp / "degenerate.off").string(),
                 "degenerate (zero-area) triangles: 1");
    // A NaN coordinate.
    write_text((tmp / "nan.obj").string(),
               "v nan 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
               "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    // CGAL's parsers refuse "nan"; the check catches non-finite vertices
    // that reach it by other routes.
    expect_error((tmp / "nan.obj").string(), "could not be parsed");
    TriangleMesh nan_mesh     = sphere;
    nan_mesh.vertices[5][1]   = std::nan("");
    const MeshCheck nan_check = check_surface_mesh(nan_mesh);
    CHECK(nan_check.non_finite_vertices == 1 && !nan_check.bounds_a_solid()
          && nan_check.describe().find("NaN") != std::string::npos);
    expect_error((tmp / "missing.off").string(), "no such file");
    write_text((tmp / "mesh.xyz").string(), "1 2 3\n");
    expect_error((tmp / "mesh.xyz").string(), "unknown extension");
  }

  fs::remove_all(tmp);
  return test::finish("geometry_mesh_io");
}
