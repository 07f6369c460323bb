#ifndef particulate_rigid_gjk_epa_h
#define particulate_rigid_gjk_epa_h

#include <particulate/geometry/shape.h>

#include <Eigen/Core>

namespace particulate {
  namespace rigid {
    /** A convex shape placed in the world: x + R s(R^T d). */
    struct ConvexPlacement
    {
      /** The (convex, bounded) shape. */
      const geometry::Shape *shape;
      /** Rotation body to world. */
      Eigen::Matrix3d rotation;
      /** Position of the body origin in m. */
      Eigen::Vector3d position;

      /** Radius removed from the shape (0: the full shape; the core radius:
       * the core point or segment of a sphere or capsule). */
      double shrink = 0.;

      /** World support point in world direction @p d. */
      Eigen::Vector3d
      support(const Eigen::Vector3d &d) const
      {
        Eigen::Vector3d s
          = position + rotation * shape->support(rotation.transpose() * d);
        if (shrink > 0.)
          s -= shrink / d.norm() * d;
        return s;
      }
    };

    /** Result of a convex distance/penetration query. */
    struct ConvexDistance
    {
      /** Signed distance in m (negative: penetration depth). */
      double distance = 0.;
      /** Unit normal from A to B. */
      Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
      /** Witness point on A (m, world). */
      Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
      /** Witness point on B (m, world). */
      Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
      /** Whether the query converged (false: a fallback answer). */
      bool converged = true;
      /** GJK iterations used. */
      unsigned int iterations = 0;
    };

    /**
     * Distance between two convex shapes by GJK (thesis §3.4.2; Gilbert,
     * Johnson, Keerthi 1988, with Ericson's closest-point sub-algorithms), and,
     * when they overlap, penetration depth and normal by the expanding
     * polytope algorithm (EPA, van den Bergen 2001).
     * @param a First shape.
     * @param b Second shape.
     * @param guess Initial search direction from A to B (e.g. the cached
     * normal of the previous step; GJK then usually converges in 1-2
     * iterations, §3.4.3); zero selects the centre difference.
     */
    ConvexDistance
    gjk_epa(const ConvexPlacement &a,
            const ConvexPlacement &b,
            const Eigen::Vector3d &guess = Eigen::Vector3d::Zero());
  } // namespace rigid
} // namespace particulate

#endif
