#ifndef particulate_rigid_broad_phase_h
#define particulate_rigid_broad_phase_h

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace particulate {
  namespace rigid {
    /**
     * What the broad phase knows of a body: its bounding sphere (already
     * inflated by the contact margin), whether it is fixed (fixed–fixed pairs
     * are never reported) and, for unbounded bodies (half-spaces), the world
     * plane n . x = offset that bounds the solid below it.
     */
    struct BroadPhaseProxy
    {
      /** Bounding-sphere centre in m (world). */
      Eigen::Vector3d center = Eigen::Vector3d::Zero();
      /** Bounding-sphere radius in m; infinity for an unbounded body. */
      double radius = 0.;
      /** Whether the body is fixed. */
      bool fixed = false;
      /** Unit outward plane normal (unbounded bodies only). */
      Eigen::Vector3d plane_normal = Eigen::Vector3d::UnitZ();
      /** Plane offset in m (unbounded bodies only). */
      double plane_offset = 0.;
    };

    /** A candidate pair of body indices with first < second. */
    struct BodyPair
    {
      unsigned int first;
      unsigned int second;
      bool
      operator<(const BodyPair &o) const
      {
        return first != o.first ? first < o.first : second < o.second;
      }
      bool
      operator==(const BodyPair &o) const
      {
        return first == o.first && second == o.second;
      }
    };

    /**
     * Whether two proxies are a candidate pair: bounding spheres overlap (or
     * the bounded one reaches the plane of an unbounded one) and not both are
     * fixed. Shared by every broad phase so they report identical sets.
     */
    bool
    proxies_overlap(const BroadPhaseProxy &a, const BroadPhaseProxy &b);

    /**
     * Interface of a broad phase (thesis §3.2): given the proxies of all
     * bodies, report every pair whose bounding volumes overlap, each once.
     */
    class BroadPhase
    {
    public:
      virtual ~BroadPhase() = default;

      /** Brings the search structure up to date with @p proxies (indexed by
       * body id; the number may grow between calls). */
      virtual void
      update(const std::vector<BroadPhaseProxy> &proxies)
        = 0;

      /** Appends the candidate pairs to @p pairs (cleared first). */
      virtual void
      find_pairs(std::vector<BodyPair> &pairs) const = 0;
    };
  } // namespace rigid
} // namespace particulate

#endif
