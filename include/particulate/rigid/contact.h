#ifndef particulate_rigid_contact_h
#define particulate_rigid_contact_h

#include <particulate/rigid/rigid_body.h>

#include <Eigen/Core>

#include <vector>

namespace particulate {
  namespace rigid {
    /**
     * One contact point between bodies a and b (thesis §3.4–3.5): where it is,
     * the normal from a to b, the signed gap (negative: penetration; positive:
     * a speculative contact that may close within the step, Fig. 3.17), and
     * the solver's cached results, kept between steps for warm starting.
     */
    struct ContactPoint
    {
      /** World position in m (midpoint of the two witness points). */
      Eigen::Vector3d position = Eigen::Vector3d::Zero();
      /** Unit normal in the world frame, pointing from body a to body b. */
      Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
      /** Signed gap in m along the normal (negative when overlapping). */
      double distance = 0.;
      /** Witness position on a in a's body frame (for cache matching). */
      Eigen::Vector3d local_a = Eigen::Vector3d::Zero();

      /** Accumulated normal impulse in N s over the last step (>= 0). */
      double normal_impulse = 0.;
      /** Accumulated tangential (friction) impulse in N s, world vector. */
      Eigen::Vector3d tangent_impulse = Eigen::Vector3d::Zero();
      /** DEM tangential spring elongation in m (world vector, history). */
      Eigen::Vector3d dem_spring = Eigen::Vector3d::Zero();
      /** Total impulse in N s applied to body b at this point during the last
       * (sub)step, all solver phases included (body a got the opposite). */
      Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
    };

    /** All contact points of one body pair, with the combined material. */
    struct ContactManifold
    {
      /** First body (a < b by id). */
      BodyId a = 0;
      /** Second body. */
      BodyId b = 0;
      /** The contact points (reduced contact set, §3.4.1). */
      std::vector<ContactPoint> points;
    };

    /**
     * Force that one contact exerted on one body during the last World::step()
     * (averaged over the step: impulse / dt for the velocity solvers, the time
     * average of the spring–dashpot force for DEM). This is what the coupling
     * reads per body after the step.
     */
    struct ContactForce
    {
      /** The body the force acts on. */
      BodyId body = 0;
      /** The other body of the contact. */
      BodyId other = 0;
      /** World point of application in m. */
      Eigen::Vector3d point = Eigen::Vector3d::Zero();
      /** Force on `body` in N (world frame). */
      Eigen::Vector3d force = Eigen::Vector3d::Zero();
    };
  } // namespace rigid
} // namespace particulate

#endif
