#ifndef particulate_rigid_contact_graph_h
#define particulate_rigid_contact_graph_h

#include <particulate/rigid/broad_phase.h>
#include <particulate/rigid/contact.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace particulate {
  namespace rigid {
    /** Relational state of a contact-graph edge (thesis §3.3.1). */
    enum class EdgeState
    {
      /** Bounding volumes overlap, no contact point within the margin. */
      proximity,
      /** Contact points found this step, none in the previous one. */
      new_contact,
      /** Contact points found in this and the previous step. */
      persistent_contact
    };

    /** One edge of the contact graph: a broad-phase pair and its cache. */
    struct ContactEdge
    {
      /** State of the pair. */
      EdgeState state = EdgeState::proximity;
      /** Current contact points (with the impulses carried over from the
       * previous step for warm starting). */
      ContactManifold manifold;
      /** Last GJK separating direction (world), used to warm start GJK. */
      Eigen::Vector3d gjk_direction = Eigen::Vector3d::Zero();
      /** Impulse on body b summed over the substeps of the current step,
       *  N s. */
      Eigen::Vector3d step_impulse = Eigen::Vector3d::Zero();
      /** Sum of |impulse| times contact position over the step (N s m). */
      Eigen::Vector3d step_moment = Eigen::Vector3d::Zero();
      /** Sum of |impulse| over the step (N s). */
      double step_weight = 0.;
    };

    /**
     * The contact graph G(V, E) of thesis §3.3: nodes are bodies, edges are
     * broad-phase pairs. It carries contact points and impulses from one step
     * to the next (warm start) and splits the bodies into contact groups with
     * the modified connected-components search of Algorithm 3, in which fixed
     * bodies never join (and so never connect) groups.
     */
    class ContactGraph
    {
    public:
      /**
       * Replaces the edge set by the broad-phase @p pairs: edges that persist
       * keep their cache, new pairs get fresh edges, pairs that the broad
       * phase no longer reports are dropped. Edges are ordered by pair so the
       * result does not depend on the broad phase's traversal order.
       * @param pairs The broad-phase pairs.
       * @param dropped If given, receives the dropped edges that still carry
       * impulse accumulated during the current step (so that their contact
       * forces are not lost).
       */
      void
      update(std::vector<BodyPair>     pairs,
             std::vector<ContactEdge> *dropped = nullptr);

      /** All edges. */
      std::vector<ContactEdge> &
      edges()
      {
        return edges_;
      }
      /** All edges. */
      const std::vector<ContactEdge> &
      edges() const
      {
        return edges_;
      }

      /**
       * Transfers cached impulses from @p old_points to the matching points of
       * @p edge (same feature: body-a local position within @p tolerance m
       * and normals within ~25 degrees), and updates the edge state.
       */
      static void
      warm_start(ContactEdge                     &edge,
                 const std::vector<ContactPoint> &old_points,
                 double                           tolerance);

      /**
       * Contact groups by Algorithm 3 over the edges that hold contact
       * points. Fills group_of_body (-1 for fixed bodies and bodies without
       * contacts) and, per group, the indices of its edges in a breadth-first
       * order that starts at bodies touching fixed bodies, so solvers sweep
       * stacks from the ground up (shock propagation, Fig. 3.11).
       * @return The number of groups.
       */
      unsigned int
      compute_contact_groups(const std::vector<RigidBody> &bodies);

      /** Consistency check (debug aid, Box2D style): edges sorted by pair
       * without duplicates, a < b < @p n_bodies, contact normals of unit
       * length, finite positions and gaps, non-negative normal impulses.
       * Throws std::logic_error naming the first broken invariant. */
      void
      validate(unsigned int n_bodies) const;

      /** Group index per body (-1: fixed or contact-free). */
      const std::vector<int> &
      group_of_body() const
      {
        return group_of_body_;
      }
      /** Edge indices per group, in propagation order. */
      const std::vector<std::vector<unsigned int>> &
      group_edges() const
      {
        return group_edges_;
      }

    private:
      std::vector<ContactEdge>               edges_;
      std::vector<int>                       group_of_body_;
      std::vector<std::vector<unsigned int>> group_edges_;
    };
  } // namespace rigid
} // namespace particulate

#endif
