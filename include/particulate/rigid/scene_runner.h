#ifndef particulate_rigid_scene_runner_h
#define particulate_rigid_scene_runner_h

#include <particulate/rigid/scene.h>

#include <ostream>

namespace particulate {
  namespace rigid {
    /**
     * Runs a SceneDescription without a fluid (`Simulation = rigid bodies`):
     * builds the World, steps it to the end time and, every
     * `output_interval` steps, writes `<output_directory>/bodies_*.vtp` +
     * `bodies.pvd` and the `.dat` series `rigid_bodies.dat` /
     * `rigid_energy.dat`, with one progress line per output on @p log
     * (step, time, contacts, solver sweeps, kinetic energy, max penetration,
     * wall time). The output folder is created if missing.
     * @return The world in its final state.
     */
    World
    run_scene(const SceneDescription &scene, std::ostream &log);
  } // namespace rigid
} // namespace particulate

#endif
