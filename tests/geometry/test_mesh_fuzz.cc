// Fuzzing the mesh readers: random bytes and randomly mutated valid files in
// every format must either read as a mesh that bounds a solid or fail with
// a GeometryError -- never crash, hang, or throw anything else.
// Usage: geometry_mesh_fuzz [cases per format (400)] [seed (12345)].
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/mesh_io.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "check.h"
#include <unistd.h>

using namespace particulate::geometry;
namespace fs = std::filesystem;

namespace {
  std::string
  slurp(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
  }

  long n_read = 0, n_refused = 0;

  void
  try_read(const std::string &path, const std::string &what)
  {
    try
      {
        const TriangleMesh m = read_surface_mesh(path);
        CHECK_MSG(check_surface_mesh(m, false).bounds_a_solid(),
                  what + ": a mesh that was accepted must bound a solid");
        ++n_read;
      }
    catch (const GeometryError &)
      {
        ++n_refused;
      }
    catch (const std::exception &e)
      {
        CHECK_MSG(false, what + ": unexpected exception type: " + e.what());
      }
  }

  std::string
  mutate(std::string s, std::mt19937 &rng)
  {
    std::uniform_int_distribution<int> kind(0, 6), byte(0, 255);
    const int                          n_mutations = 1 + rng() % 4;
    for (int m = 0; m < n_mutations && !s.empty(); ++m)
      {
        const std::size_t pos = rng() % s.size();
        switch (kind(rng))
          {
            case 0: // flip a byte
              s[pos] = static_cast<char>(byte(rng));
              break;
            case 1: // truncate
              s.resize(pos);
              break;
            case 2: // delete a range
              s.erase(pos, 1 + rng() % 64);
              break;
            case 3: // duplicate a range
              s.insert(pos, s.substr(pos, 1 + rng() % 64));
              break;
            case 4: // a hostile number
              {
                static const char *numbers[] = {"-1",
                                                "nan",
                                                "inf",
                                                "1e308",
                                                "4294967295",
                                                "99999999999",
                                                "-0",
                                                "0x7fffffff"};
                s.insert(pos, std::string(" ") + numbers[rng() % 8] + " ");
                break;
              }
            case 5: // random bytes inserted
              for (int i = 0; i < 16; ++i)
                s.insert(s.begin() + pos, static_cast<char>(byte(rng)));
              break;
            default: // swap two digits' worth of text
              if (pos + 1 < s.size())
                std::swap(s[pos], s[pos + 1]);
          }
      }
    return s;
  }
} // namespace

int
main(int argc, char **argv)
{
  const int      cases = argc > 1 ? std::atoi(argv[1]) : 400;
  const fs::path tmp   = fs::temp_directory_path()
                       / ("particulate_fuzz_" + std::to_string(::getpid()));
  fs::create_directories(tmp);
  std::mt19937 rng(argc > 2 ? std::atoi(argv[2]) : 12345);

  const TriangleMesh base = mesh_generators::icosphere(1., 1);
  for (const std::string ext : {".off", ".stl", ".obj", ".ply"})
    {
      const std::string valid = (tmp / ("valid" + ext)).string();
      write_surface_mesh(valid, base);
      try_read(valid, "valid" + ext);
      const std::string text = slurp(valid);
      const std::string path = (tmp / ("case" + ext)).string();

      // Hand-made hostile headers.
      for (const std::string &h : std::vector<std::string>{
             "OFF\n999999999 999999999 0\n0 0 0\n",
             "OFF\n-5 -5 0\n",
             "OFF\nnan nan 0\n0 0 0\n",
             "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n999999999 0 1 2\n",
             "ply\nformat ascii 1.0\nelement vertex 999999999999\nproperty "
             "float x\nend_header\n",
             "solid x\nfacet normal 0 0 0\nouter loop\nvertex 1 2\n",
             "v 1 2 3\nf 1 2 99999999\n",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
             "property float y\nproperty float z\nelement face 1\nproperty "
             "list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
             "999999999 0 1 2\n",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
             "property float y\nproperty float z\nelement face 1\nproperty "
             "list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
             "nan 0 1 2\n",
             std::string("ply\nformat binary_little_endian 1.0\nelement vertex "
                         "3\nproperty float x\nproperty float y\nproperty "
                         "float z\nelement face 1\nproperty list int int "
                         "vertex_indices\nend_header\n")
               + std::string(36, '\0') + std::string("\xff\xc9\x9a\x3b", 4)
               + std::string(12, '\0'),
             "v nan nan nan\nv 1 0 0\nv 0 1 0\n"
             "v 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n"})
        {
          std::ofstream(path, std::ios::binary) << h;
          try_read(path, "hostile header " + ext);
        }
      for (int c = 0; c < cases; ++c)
        {
          std::string bytes;
          if (c % 4 == 0)
            {
              // Pure random bytes.
              bytes.resize(rng() % 2048);
              for (char &b : bytes)
                b = static_cast<char>(rng() % 256);
            }
          else
            bytes = mutate(text, rng);
          std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
          try_read(path, "case " + std::to_string(c) + ext);
        }
    }
  std::cout << "fuzz: " << n_read << " files read, " << n_refused
            << " refused with a GeometryError" << std::endl;
  CHECK(n_refused > 0);
  fs::remove_all(tmp);
  return test::finish("geometry_mesh_fuzz");
}
