#ifndef particulate_fbm_energy_balance_h
#define particulate_fbm_energy_balance_h

#include <particulate/rigid/world.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * The energy the bodies gained that no load paid for: a watch on the
     * contacts and the rigid integrator, which may dissipate energy but
     * must not create it.
     *
     * Over each coupled step the loads the engine got (fluid, buoyancy-
     * corrected gravity, the added-mass correction) do the work
     * W = F . dx + T . dphi on each free body, with its displacement dx and
     * the rotation vector dphi of the step. The kinetic energy the engine
     * integrates (with its masses) then changes by dK = W - D, where D >= 0
     * is what the contacts and the integrator dissipated: inelastic
     * contacts and friction remove energy, a DEM spring gives back at most
     * what it stored, and the symplectic Euler step of constant loads loses
     * m |dv|^2 / 2 per step. The sum of dK - W since the start (or the
     * restart) of the run is therefore at most the quadrature error of W,
     * of the order of (omega dt)^2 of the rotational work.
     *
     * A contact that creates energy (a DEM spring too stiff for the
     * substep, a position correction throwing bodies apart) makes that sum
     * grow. warning() reports it once it exceeds gain_fraction of the
     * energy the bodies held and exchanged with the loads, K(start) +
     * sum |W|: a body that gained a tenth of all the energy it ever handled
     * from nothing is not a rounding error.
     */
    class EnergyBalance
    {
    public:
      /** The fraction of K(start) + sum |W| that the unexplained gain may
       *  reach before the warning. */
      static constexpr double gain_fraction = 0.1;

      /** @param free_ids the bodies that move freely in the engine */
      explicit EnergyBalance(const std::vector<rigid::BodyId> &free_ids);

      /** Remembers the bodies' poses, kinetic energy and loads before a
       *  step, once the loads are set in the engine (which clears them
       *  when it steps). */
      void
      start_step(const rigid::World &world);

      /** Adds the step that just ended. */
      void
      end_step(const rigid::World &world);

      /** The energy gained that no load paid for, sum (dK - W) [J]. */
      double
      unexplained_gain() const
      {
        return gain;
      }

      /** K(start) + sum |W| [J]. */
      double
      energy_handled() const;

      /**
       * A warning to print, once: empty while the gain is within
       * gain_fraction of energy_handled(), and after the warning was
       * given.
       * @param t the time the last step ended at [s]
       */
      std::string
      warning(const double t);

    private:
      /** Kinetic energy of @p body with the engine's mass and inertia. */
      static double
      kinetic_energy(const rigid::RigidBody &body);

      std::vector<rigid::BodyId>      ids;
      std::vector<Eigen::Vector3d>    start_position;
      std::vector<Eigen::Quaterniond> start_orientation;
      std::vector<Eigen::Vector3d>    force, torque;
      double                          start_energy   = 0.;
      double                          initial_energy = -1.;
      double                          gain           = 0.;
      double                          work_handled   = 0.;
      bool                            warned         = false;
    };
  } // namespace fbm
} // namespace particulate

#endif
