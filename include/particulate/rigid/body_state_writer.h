#ifndef particulate_rigid_body_state_writer_h
#define particulate_rigid_body_state_writer_h

#include <particulate/rigid/world.h>

#include <fstream>
#include <string>

namespace particulate {
  namespace rigid {
    /**
     * Whitespace-separated time series for numpy.loadtxt (GUIDE §6):
     * `<prefix>_bodies.dat`, one line per dynamic body per call,
     *   # time id x y z qw qx qy qz u v w omega_x omega_y omega_z fx fy fz
     * (f: total contact force of the last step, N), and `<prefix>_energy.dat`,
     *   # time kinetic_energy potential_energy n_contacts max_penetration
     * (potential energy -m g . x relative to the origin, J).
     */
    class BodyStateWriter
    {
    public:
      /** Opens (truncates) both files and writes their header lines; throws
       * std::runtime_error when a file cannot be opened. */
      explicit BodyStateWriter(const std::string &prefix);

      /** Appends the current state of @p world. */
      void
      write(const World &world);

    private:
      std::ofstream bodies_, energy_;
    };
  } // namespace rigid
} // namespace particulate

#endif
