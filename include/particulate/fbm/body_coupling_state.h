#ifndef particulate_fbm_body_coupling_state_h
#define particulate_fbm_body_coupling_state_h

#include <particulate/fbm/hydrodynamic_load.h>

#include <Eigen/Core>

#include <iosfwd>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * What the coupled loop carries for one body from one time step to the
     * next (thesis §5.3): the rigid accelerations of the last step (for the
     * added-mass correction and the predicted interface), the loads, the
     * rigid velocities the flow was given and solved with, and the body's
     * largest speed so far.
     *
     * save() and load() write and read what a restart needs; the imposed
     * velocities and the load centre are set again by every marking of the
     * interface, which a restart performs before its first step.
     */
    struct BodyCouplingState
    {
      /// rigid accelerations of the last step [m/s^2], [1/s^2]
      Eigen::Vector3d acceleration         = Eigen::Vector3d::Zero();
      Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();
      /// the rigid velocities the covered nodes were last given [m/s, 1/s]
      Eigen::Vector3d imposed_velocity = Eigen::Vector3d::Zero();
      Eigen::Vector3d imposed_angular  = Eigen::Vector3d::Zero();
      /// those of the last solve, which the flow holds at the covered
      /// nodes when a step starts: the difference to the imposed ones is
      /// the rigid acceleration the fluid inside the body saw
      Eigen::Vector3d solved_velocity = Eigen::Vector3d::Zero();
      Eigen::Vector3d solved_angular  = Eigen::Vector3d::Zero();
      /// where the interface was last marked around: the torque's
      /// reference point [m]
      Eigen::Vector3d load_centre = Eigen::Vector3d::Zero();
      /// the fluid's force and torque on the body
      HydrodynamicLoad fluid_load;
      /// the largest speed reached so far and when [m/s, s]
      double max_speed         = 0.;
      double time_of_max_speed = 0.;

      /** The velocities just imposed become those the flow solved with. */
      void
      mark_solved()
      {
        solved_velocity = imposed_velocity;
        solved_angular  = imposed_angular;
      }

      /** Keep the largest @p speed, reached at time @p t. */
      void
      record_speed(const double speed, const double t);

      void
      save(std::ostream &out) const;

      /** Read what save() wrote; throws std::runtime_error on a short
       *  stream. */
      void
      load(std::istream &in);
    };

    /** The states of all bodies, in body order, with their number first. */
    void
    save_coupling_states(std::ostream                         &out,
                         const std::vector<BodyCouplingState> &states);

    /** Read what save_coupling_states() wrote into @p states, which must
     *  hold as many bodies as the checkpoint; throws std::runtime_error
     *  otherwise. */
    void
    load_coupling_states(std::istream                   &in,
                         std::vector<BodyCouplingState> &states);
  } // namespace fbm
} // namespace particulate

#endif
