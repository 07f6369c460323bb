// Internal to particulate_rigid: the pairwise contact generators used by
// NarrowPhase::collide(). Every function appends contact points with normals
// from its first to its second body and gaps up to `margin`.
#ifndef particulate_rigid_collide_detail_h
#define particulate_rigid_collide_detail_h

#include <particulate/rigid/contact.h>
#include <particulate/rigid/rigid_body.h>

#include <vector>

namespace particulate {
  namespace rigid {
    namespace detail {
      /** Fills a contact point from the witness points on A and B. */
      inline ContactPoint
      make_point(const RigidBody       &A,
                 const Eigen::Vector3d &on_a,
                 const Eigen::Vector3d &on_b,
                 const Eigen::Vector3d &normal,
                 const double           distance)
      {
        ContactPoint c;
        c.position = 0.5 * (on_a + on_b);
        c.normal   = normal;
        c.distance = distance;
        c.local_a  = A.to_body(on_a);
        return c;
      }

      void
      box_box(const RigidBody           &A,
              const RigidBody           &B,
              double                     margin,
              std::vector<ContactPoint> &out);

      /** Reduces a contact set to at most @p n points that keep the deepest
       * point and span the largest area (§3.4.1, reduced contact set). */
      void
      reduce_points(std::vector<ContactPoint> &pts, unsigned int n);
    } // namespace detail
  }   // namespace rigid
} // namespace particulate

#endif
