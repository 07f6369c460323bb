#ifndef particulate_fbm_set_up_warnings_h
#define particulate_fbm_set_up_warnings_h

#include <particulate/fbm/particle_description.h>

#include <string>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * Warnings about a particle set that will run but not as well as the
     * user may expect, given before the first step. Each returns an empty
     * string when there is nothing to say.
     */
    namespace set_up_warnings {
      /**
       * The fewest cells across a particle's size (the smallest edge of its
       * bounding box) below which a warning is given: the drag of the
       * fixed FBM cylinder of DFG 2D-1 is 2.6 % low at 4 cells per
       * diameter and within 1.3 % from 8 on
       * (doc/validation/dfg-2d-1-fbm.md).
       */
      constexpr double minimum_cells_across = 4.;

      /**
       * @param sizes each particle's size [m]
       * @param cell_sizes the size of the cell at each particle's centre
       *   [m] (0: not known)
       */
      std::string
      resolution(const std::vector<double> &sizes,
                 const std::vector<double> &cell_sizes);

      /**
       * The explicit coupling with the added-mass coefficient C amplifies
       * accelerations per step by |C rho_f V - m_a| / (m + C rho_f V)
       * (doc/developer/fbm.md, "Stability for light particles"): it is
       * unstable
       * where the fluid's added mass m_a = C_a rho_f V exceeds
       * m + 2 C rho_f V, i.e. where rho_p / rho_f < C_a - 2 C, with C_a =
       * 1/2 for a sphere and 1 for a disk, more in confinement.
       * @param density_ratios rho_p / rho_f of each free particle (the
       *   others do not count)
       * @param added_mass_coefficient C
       * @param dim 2 (disks, C_a = 1) or 3 (spheres, C_a = 1/2)
       */
      std::string
      coupling_stability(const std::vector<double> &density_ratios,
                         const double               added_mass_coefficient,
                         const unsigned int         dim);

      /**
       * A contact distance below the cell size (0.9 of it, for graded
       * meshes and rounding) at a free particle's centre: a
       * film between two particles, or between a particle and a wall,
       * thinner than a cell has too few free velocity nodes to carry its
       * squeeze and shear flow, and the pressure in it can throw particles
       * together or apart (doc/developer/fbm.md, "Near contact").
       * @param contact_distance the rigid engine's contact offset [m]
       * @param cell_sizes the size of the cell at each free particle's
       *   centre [m] (0: not known)
       */
      std::string
      contact_distance(const double               contact_distance,
                       const std::vector<double> &cell_sizes);

      /**
       * A surface-mesh shape whose distance map resolves it less than two
       * map cells thick: its thin parts may let nodes and contacts through.
       * @param names the shapes' names
       * @param thicknesses twice the deepest map point of each [m]
       *   (DistanceMap::deepest_inside())
       * @param spacings each map's spacing [m]
       */
      std::string
      thin_surface_meshes(const std::vector<std::string> &names,
                          const std::vector<double>      &thicknesses,
                          const std::vector<double>      &spacings);

      /** The same for the surface-mesh shapes of @p particles (each shape
       *  named once). */
      std::string
      thin_surface_meshes(const std::vector<ParticleDescription> &particles);
    } // namespace set_up_warnings
  }   // namespace fbm
} // namespace particulate

#endif
