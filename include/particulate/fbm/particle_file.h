#ifndef particulate_fbm_particle_file_h
#define particulate_fbm_particle_file_h

#include <particulate/fbm/particle_description.h>
#include <particulate/fbm/shape_template.h>

#include <string>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * Read the particles of file @p filename (`Particle file`, subsection
     * `Particles`): one particle per line, values separated by commas or
     * blanks, after a header line (which may start with '#') that names
     * the columns. Lines that start with '#' and blank lines are skipped.
     *
     * Columns: `shape` (the name of a `Shape <name>` template), `x`, `y`
     * and in 3D `z` are required; optional are the velocity `vx`, `vy`
     * (`vz`), the angular velocity `omega` (2D, about z) or `omega_x`,
     * `omega_y`, `omega_z` (3D), the orientation as `angle` [rad] (2D:
     * about z; 3D: with `axis_x`, `axis_y`, `axis_z`) or as a quaternion
     * `qw`, `qx`, `qy`, `qz`, and `motion` (`free` or `fixed`).
     *
     * @param shapes the case's shape templates
     * @param dim the space dimension of the run
     * @throw std::runtime_error naming the file and line for a missing
     *   file, an unknown or missing column, a line with another number of
     *   values than the header, a value that is no number, an unknown
     *   shape or motion
     */
    std::vector<ParticleDescription>
    read_particle_file(const std::string  &filename,
                       const ShapeLibrary &shapes,
                       const unsigned int  dim);
  } // namespace fbm
} // namespace particulate

#endif
