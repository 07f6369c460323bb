#ifndef particulate_rigid_all_pairs_broad_phase_h
#define particulate_rigid_all_pairs_broad_phase_h

#include <particulate/rigid/broad_phase.h>

namespace particulate {
  namespace rigid {
    /**
     * The O(n^2) reference broad phase: tests every pair with
     * proxies_overlap(). Used to verify HierarchicalHashGrid and as a
     * baseline in the benchmark.
     */
    class AllPairsBroadPhase : public BroadPhase
    {
    public:
      void
      update(const std::vector<BroadPhaseProxy> &proxies) override;
      void
      find_pairs(std::vector<BodyPair> &pairs) const override;

    private:
      std::vector<BroadPhaseProxy> proxies_;
    };
  } // namespace rigid
} // namespace particulate

#endif
