#include <particulate/rigid/body_state_writer.h>
#include <particulate/rigid/body_surface_writer.h>
#include <particulate/rigid/scene_runner.h>
#include <particulate/rigid/vtp_writer.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>

namespace particulate {
  namespace rigid {
    World
    run_scene(const SceneDescription &scene, std::ostream &log)
    {
      World              world   = scene.build_world();
      const unsigned int n_steps = static_cast<unsigned int>(
        std::ceil(scene.end_time / scene.time_step - 1.e-9));
      std::unique_ptr<BodyStateWriter>   dat;
      std::unique_ptr<VtpWriter>         vtp;
      std::unique_ptr<BodySurfaceWriter> surfaces;
      if (scene.output_interval > 0)
        {
          std::filesystem::create_directories(scene.output_directory);
          dat = std::make_unique<BodyStateWriter>(scene.output_directory
                                                  + "/rigid");
          vtp = std::make_unique<VtpWriter>(scene.output_directory + "/bodies");
          surfaces = std::make_unique<BodySurfaceWriter>(scene.output_directory
                                                         + "/body_surfaces");
          dat->write(world);
          vtp->write(world);
          surfaces->write(world);
        }
      log << "rigid bodies: " << world.n_bodies() << " bodies, " << n_steps
          << " steps of " << scene.time_step << " s, solver "
          << to_string(scene.world.contact_solver) << "\n";
      const auto t0 = std::chrono::steady_clock::now();
      for (unsigned int step = 1; step <= n_steps; ++step)
        {
          world.step(scene.time_step);
          if (scene.output_interval > 0 && step % scene.output_interval == 0)
            {
              dat->write(world);
              vtp->write(world);
              surfaces->write(world);
              const double wall = std::chrono::duration<double>(
                                    std::chrono::steady_clock::now() - t0)
                                    .count();
              const auto &s = world.statistics();
              log << "step " << std::setw(7) << step
                  << "  t = " << std::setw(10) << world.time() << "  contacts "
                  << std::setw(7) << s.contacts << "  sweeps " << std::setw(4)
                  << s.solver_iterations << "  E_kin " << std::setw(11)
                  << world.kinetic_energy() << " J  max pen. " << std::setw(10)
                  << world.max_penetration() << " m  wall " << std::setw(8)
                  << wall << " s  left ~" << wall * (n_steps - step) / step
                  << " s\n";
            }
        }
      return world;
    }
  } // namespace rigid
} // namespace particulate
