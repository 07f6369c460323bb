#include <particulate/rigid/all_pairs_broad_phase.h>
#include <particulate/rigid/broad_phase.h>

#include <cmath>

namespace particulate {
  namespace rigid {
    bool
    proxies_overlap(const BroadPhaseProxy &a, const BroadPhaseProxy &b)
    {
      if (a.fixed && b.fixed)
        return false;
      const bool ua = !std::isfinite(a.radius), ub = !std::isfinite(b.radius);
      if (ua && ub)
        return false;
      if (ua)
        return a.plane_normal.dot(b.center) - a.plane_offset <= b.radius;
      if (ub)
        return b.plane_normal.dot(a.center) - b.plane_offset <= a.radius;
      const double r = a.radius + b.radius;
      return (a.center - b.center).squaredNorm() <= r * r;
    }



    void
    AllPairsBroadPhase::update(const std::vector<BroadPhaseProxy> &proxies)
    {
      proxies_ = proxies;
    }



    void
    AllPairsBroadPhase::find_pairs(std::vector<BodyPair> &pairs) const
    {
      pairs.clear();
      const unsigned int n = proxies_.size();
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = i + 1; j < n; ++j)
          if (proxies_overlap(proxies_[i], proxies_[j]))
            pairs.push_back({i, j});
    }
  } // namespace rigid
} // namespace particulate
