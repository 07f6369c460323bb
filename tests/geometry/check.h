// Small assertion helpers shared by the geometry tests (plain mains, no
// test framework: exit 0 pass, 1 fail, 77 skip).
#ifndef particulate_tests_geometry_check_h
#define particulate_tests_geometry_check_h

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace test {

  inline int failures = 0;

  inline void
  check(const bool ok, const std::string &what, const char *file, int line)
  {
    if (!ok)
      {
        ++failures;
        std::cerr << file << ":" << line << ": FAILED: " << what << std::endl;
      }
  }

  inline int
  finish(const char *name)
  {
    if (failures > 0)
      {
        std::cerr << name << ": " << failures << " check(s) failed"
                  << std::endl;
        return 1;
      }
    std::cout << name << ": all checks passed" << std::endl;
    return 0;
  }

  /** Folder with CGAL's sample meshes (data/meshes, OFF files), or exit 77. */
  inline std::string
  cgal_meshes_or_skip()
  {
    const char       *env = std::getenv("PARTICULATE_CGAL_DATA_DIR");
    const std::string dir
      = std::string(env ? env : "cgal-data") + "/data/meshes";
    if (!std::filesystem::is_directory(dir))
      {
        std::cout << "SKIP: CGAL sample meshes not found in '" << dir
                  << "'. Run scripts/setup.sh or unpack "
                     "/usr/share/doc/libcgal-dev/data.tar.gz there."
                  << std::endl;
        std::exit(77);
      }
    return dir;
  }

} // namespace test

#define CHECK(cond) test::check((cond), #cond, __FILE__, __LINE__)
#define CHECK_MSG(cond, msg) test::check((cond), msg, __FILE__, __LINE__)

#endif
