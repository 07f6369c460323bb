#ifndef particulate_rigid_narrow_phase_h
#define particulate_rigid_narrow_phase_h

#include <particulate/rigid/contact_graph.h>
#include <particulate/rigid/rigid_body.h>

namespace particulate {
  namespace rigid {
    /**
     * Narrow phase and contact generation (thesis §3.4–3.5, Algorithm 4):
     * turns a broad-phase pair into a reduced contact set.
     *
     * - analytic: sphere–sphere, sphere–box, sphere–capsule, sphere–plane,
     *   box–plane, capsule–plane;
     * - box–box: separating axes plus Sutherland–Hodgman clipping of the
     *   incident face against the reference face (up to 4 points), edge–edge
     *   contacts by closest points of the edges; boxes that are apart add
     *   the GJK closest pair where the clipped points miss it;
     * - other convex pairs, general shapes that are convex (the elliptic
     *   cylinder) included: GJK distance warm-started from the cached normal,
     *   EPA for penetrations; convex–plane by support points in a fan of
     *   directions around the plane normal, so cylinders rest on several
     *   points (§3.4.1);
     * - a sphere against any general shape: its centre against the shape's
     *   signed distance (exact);
     * - non-convex general (mesh) shapes: the surface points of each body are
     *   tested against the other body's distance function (§3.4.2, the
     *   distance-map approach).
     *
     * Contacts are reported for gaps up to the given margin: speculative
     * contacts for pairs still apart that could close within the step
     * (Fig. 3.17); the solvers only act on them if the gap would close.
     */
    class NarrowPhase
    {
    public:
      /**
       * Computes the contact points of bodies @p a and @p b (a's id is
       * edge.manifold.a) into edge.manifold.points, normals from a to b.
       * @param margin Largest gap in m that still yields a contact point.
       * @return The number of contact points.
       */
      static unsigned int
      collide(const RigidBody &a,
              const RigidBody &b,
              double           margin,
              ContactEdge     &edge);
    };
  } // namespace rigid
} // namespace particulate

#endif
