#ifndef particulate_rigid_material_h
#define particulate_rigid_material_h

#include <string>

namespace particulate {
  namespace rigid {
    /**
     * Bulk and contact properties of a rigid-body material (thesis §4.2.4 for
     * friction, §4.4.4 for the DEM spring–dashpot coefficients). All values are
     * SI. When two bodies of different materials touch, the pair values are
     * combined by Material::combine().
     */
    struct Material
    {
      /** Human readable name, used in error messages and output. */
      std::string name = "default";
      /** Mass density in kg/m^3. */
      double density = 1000.;
      /** Coefficient of restitution e in [0,1] (ratio of separating to
       * approaching normal velocity in a binary collision). */
      double restitution = 0.;
      /** Static friction coefficient mu_s (eq. 4.34), dimensionless. */
      double static_friction = 0.;
      /** Dynamic (kinetic) friction coefficient mu_d (eq. 4.35). */
      double dynamic_friction = 0.;
      /** DEM normal spring stiffness k_n in N/m (eq. 4.87). */
      double dem_stiffness = 1.e5;
      /** DEM tangential spring stiffness k_t in N/m; the tangential spring
       * force is clamped to the Coulomb cone. */
      double dem_tangential_stiffness = 2.e4;

      /** Throws std::invalid_argument with a readable sentence when a value is
       * outside its physical range. */
      void
      check() const;

      /**
       * Pair values for a contact between materials @p a and @p b: restitution
       * takes the minimum (the more dissipative body wins), friction the
       * geometric mean, stiffnesses the series spring 1/k = 1/k_a + 1/k_b.
       */
      static Material
      combine(const Material &a, const Material &b);
    };
  } // namespace rigid
} // namespace particulate

#endif
