// `Simulation / Type = rigid bodies`: a case's particles under gravity and
// contacts alone. A sphere and a spheroid given as a surface mesh
// (prm/mesh-bodies/spheroid.off, semi-axes 11.906 x 5.953 x 5.953 mm,
// lying flat) fall onto the floor of a box:
// - in free fall the sphere follows z0 - g t^2 / 2 to within g dt t (the
//   engine's semi-implicit Euler step is first order: its error is
//   g dt t / 2), and no fluid load is written;
// - both come to rest one contact distance above the floor: the sphere's
//   centre at r + d to 1e-6 r, the spheroid's at its semi-minor axis + d
//   to a tenth of its map's spacing (the automatic one: 11.906 mm / 16);
// - the run writes the particles' series and table as a particulate flow
//   run does; with 'Particle files = shared' the one series particles.dat
//   holds the same rows.

#include <particulate/fbm/rigid_bodies_simulation.h>

#include <filesystem>

#include "../fluid/test_utilities.h"

using namespace particulate;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const std::string                        case_file
    = testing::source_path("tests/fbm/rigid_bodies/drop.prm");
  auto              parameters     = fbm::read_particulate_flow_case(case_file);
  const std::string output         = "rigid_bodies_run";
  parameters.flow.output.directory = output;
  std::filesystem::create_directories(output);
  fbm::RigidBodiesSimulation<3> simulation(parameters,
                                           case_file,
                                           MPI_COMM_SELF);
  const fbm::RigidBodiesSummary summary = simulation.run();

  const double g = 9.81, dt = 0.001, r = 0.01, d = 0.001;
  const double z0 = 0.06, c = 0.005953, map_spacing = 0.011906 / 16.;
  // particle_0.dat: time (0), z (3), F_x..T_z (10-15)
  const auto series = testing::read_time_series(output + "/particle_0.dat");
  double     free_fall_error = 0., fluid_load = 0., bound = 0.;
  for (const std::vector<double> &row : series)
    {
      const double t = row[0];
      for (unsigned int k = 10; k < 16; ++k)
        fluid_load = std::max(fluid_load, std::abs(row[k]));
      // before the sphere comes within the contact margin of the floor
      if (z0 - 0.5 * g * t * t > r + d + 0.002)
        {
          free_fall_error
            = std::max(free_fall_error,
                       std::abs(row[3] - (z0 - 0.5 * g * t * t)) / t);
          bound = g * dt;
        }
    }
  std::cout << summary.n_steps << " steps; free fall: largest |z - z0 + g t^2"
            << "/2| / t " << free_fall_error << " m/s (bound g dt = " << bound
            << "); at rest: sphere " << summary.position[0][2] << " m, "
            << "spheroid " << summary.position[1][2] << " m; speeds "
            << summary.velocity[0].norm() << ", " << summary.velocity[1].norm()
            << " m/s; deepest overlap " << summary.max_penetration << " m\n";
  checker.check(summary.n_steps == 300 && series.size() == 301,
                "all 300 steps run and written");
  checker.check(bound > 0. && free_fall_error <= bound,
                "free fall within the first-order bound g dt t");
  checker.check(fluid_load == 0., "no fluid load");
  checker.check(std::abs(summary.position[0][2] - (r + d)) < 1e-6 * r,
                "the sphere rests one contact distance above the floor");
  checker.check(std::abs(summary.position[1][2] - (c + d)) < 0.1 * map_spacing,
                "the mesh spheroid rests on its semi-minor axis");
  checker.check(summary.velocity[0].norm() < 1e-3
                  && summary.velocity[1].norm() < 1e-3,
                "both at rest");
  checker.check(std::filesystem::exists(output + "/particle_set.csv")
                  && std::filesystem::exists(output + "/flow.dat")
                  && std::filesystem::exists(output + "/particles.pvd")
                  && std::filesystem::exists(output + "/particle_surfaces.pvd"),
                "the particles' table, series and ParaView files");

  // the same run with shared particle files: particles.dat holds every
  // particle's rows, equal to its own series, and each output step one file
  // of all surfaces
  const std::string shared = "rigid_bodies_run_shared";
  std::filesystem::remove_all(shared);
  std::filesystem::create_directories(shared);
  parameters.flow.output.directory = shared;
  parameters.flow.output.particle_files
    = core::OutputParameters::ParticleFiles::shared;
  fbm::RigidBodiesSimulation<3>(parameters, case_file, MPI_COMM_SELF).run();
  const auto rows = testing::read_time_series(shared + "/particles.dat");
  bool       same = rows.size() == 2 * series.size();
  for (unsigned int id = 0; id < 2 && same; ++id)
    {
      const auto own = testing::read_time_series(output + "/particle_"
                                                 + std::to_string(id) + ".dat");
      for (unsigned int k = 0; k < own.size() && same; ++k)
        {
          std::vector<double> row = rows[2 * k + id];
          same                    = row[1] == id;
          row.erase(row.begin() + 1);
          same = same && row == own[k];
        }
    }
  checker.check(same,
                "particles.dat: a row per particle and step (id in its second "
                "column), equal to the particle's own series");
  checker.check(std::filesystem::exists(shared + "/particle_surfaces_00001.vtp")
                  && !std::filesystem::exists(shared + "/particle_surfaces")
                  && !std::filesystem::exists(shared + "/particle_0.dat"),
                "shared: one surface file per output step, no files per "
                "particle");
  return checker.exit_code();
}
