// The scene front end and the writers: a scene with one sphere dropped
// from 0.5 m (no contact during the run) is run by run_scene(); the .dat
// series must load column-wise with the closed-form free fall
// z(t) = z0 - g t^2 / 2 at every written time (to 1e-9 m with the exact
// kick-drift time stepping error accounted for: z_n = z0 - g dt^2 n(n+1)/2),
// and the .pvd/.vtp files must exist with one DataSet per output.
#include <particulate/rigid/scene_runner.h>

#include <fstream>
#include <sstream>
#include <string>

#include "test_tools.h"

using namespace particulate::rigid;

int
main()
{
  SceneDescription scene;
  BodyDescription  b;
  b.shape.kind   = particulate::geometry::ShapeKind::sphere;
  b.shape.radius = 0.05;
  b.position     = Eigen::Vector3d(0.1, 0.2, 0.5);
  scene.bodies.push_back(b);
  scene.time_step        = 1.e-3;
  scene.end_time         = 0.2;
  scene.output_interval  = 50;
  scene.output_directory = "rigid_scene_files";
  std::ostringstream log;
  const World        w = run_scene(scene, log);
  std::cout << log.str();

  std::ifstream in("rigid_scene_files/rigid_bodies.dat");
  CHECK(in, "rigid_bodies.dat missing");
  std::string line;
  std::getline(in, line);
  CHECK(line.rfind("# time id x y z", 0) == 0, "header line: " << line);
  unsigned int rows = 0;
  while (std::getline(in, line))
    {
      if (line.empty() || line[0] == '#')
        continue;
      std::istringstream s(line);
      double             t, id, x, y, z;
      s >> t >> id >> x >> y >> z;
      const double n     = std::round(t / 1.e-3);
      const double exact = 0.5 - 9.81 * 1.e-6 * n * (n + 1.) / 2.;
      CHECK(std::abs(z - exact) < 1.e-9,
            "z(" << t << ") = " << z << ", expected " << exact);
      ++rows;
    }
  CHECK(rows == 5, "expected 5 rows (t = 0, 0.05, ..., 0.2), got " << rows);
  std::ifstream pvd("rigid_scene_files/bodies.pvd");
  std::string   all((std::istreambuf_iterator<char>(pvd)),
                  std::istreambuf_iterator<char>());
  std::size_t   n_sets = 0;
  for (std::size_t p = all.find("<DataSet"); p != std::string::npos;
       p             = all.find("<DataSet", p + 1))
    ++n_sets;
  CHECK(n_sets == 5, "pvd data sets: " << n_sets);
  CHECK(std::ifstream("rigid_scene_files/bodies_00004.vtp").good(),
        "last vtp file missing");
  std::cout << "OK\n";
  return 0;
}
