#include <particulate/rigid/hierarchical_hash_grid.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace particulate {
  namespace rigid {
    namespace {
      inline std::size_t
      hash_key(std::uint64_t h)
      {
        // splitmix64 finaliser: spreads neighbouring keys over the table.
        h ^= h >> 31;
        h *= 0xBF58476D1CE4E5B9ull;
        h ^= h >> 29;
        return std::size_t(h);
      }

      inline std::int64_t
      cell_coordinate(const double x, const double h)
      {
        return std::int64_t(std::floor(x / h));
      }

      /** The 13 neighbour offsets that are lexicographically positive: with
       * the own cell they form the half neighbourhood of Fig. 3.8. */
      constexpr int half_offsets[13][3] = {{0, 0, 1},
                                           {0, 1, -1},
                                           {0, 1, 0},
                                           {0, 1, 1},
                                           {1, -1, -1},
                                           {1, -1, 0},
                                           {1, -1, 1},
                                           {1, 0, -1},
                                           {1, 0, 0},
                                           {1, 0, 1},
                                           {1, 1, -1},
                                           {1, 1, 0},
                                           {1, 1, 1}};
    } // namespace



    HierarchicalHashGrid::HierarchicalHashGrid(const double level_ratio)
      : ratio_(level_ratio)
    {
      if (!(level_ratio > 1.))
        throw std::invalid_argument(
          "rigid::HierarchicalHashGrid: the ratio of cell sizes of successive "
          "levels must exceed 1 (2 is a good choice).");
    }



    double
    HierarchicalHashGrid::cell_size(const unsigned int l) const
    {
      return h0_ * std::pow(ratio_, double(l));
    }



    int
    HierarchicalHashGrid::level_for(const double radius)
    {
      const double d = 2. * radius;
      int          l
        = d > h0_ ? int(std::ceil(std::log(d / h0_) / std::log(ratio_))) : 0;
      while (cell_size(l) <= d)
        ++l;
      while (l > 0 && cell_size(l - 1) > d)
        --l;
      while (int(levels_.size()) <= l)
        {
          Level lvl;
          lvl.h = cell_size(levels_.size());
          lvl.table.resize(64);
          levels_.push_back(std::move(lvl));
        }
      return l;
    }



    std::uint64_t
    HierarchicalHashGrid::pack(const std::int64_t x,
                               const std::int64_t y,
                               const std::int64_t z)
    {
      constexpr std::uint64_t m = (1ull << 21) - 1;
      return (std::uint64_t(x) & m) | ((std::uint64_t(y) & m) << 21)
             | ((std::uint64_t(z) & m) << 42);
    }



    int
    HierarchicalHashGrid::find_slot(const Level       &lvl,
                                    const std::int64_t x,
                                    const std::int64_t y,
                                    const std::int64_t z) const
    {
      const std::uint64_t key  = pack(x, y, z);
      const std::size_t   mask = lvl.table.size() - 1;
      for (std::size_t s = hash_key(key) & mask;; s = (s + 1) & mask)
        {
          const Cell &c = lvl.table[s];
          if (!c.used())
            return -1;
          if (c.key == key)
            return int(s);
        }
    }



    int
    HierarchicalHashGrid::insert_slot(Level             &lvl,
                                      const std::int64_t x,
                                      const std::int64_t y,
                                      const std::int64_t z)
    {
      const std::uint64_t key  = pack(x, y, z);
      const std::size_t   mask = lvl.table.size() - 1;
      for (std::size_t s = hash_key(key) & mask;; s = (s + 1) & mask)
        {
          Cell &c = lvl.table[s];
          if (!c.used())
            {
              c.key   = key;
              c.head  = -1;
              c.count = 0;
              ++lvl.n_used_slots;
              return int(s);
            }
          if (c.key == key)
            return int(s);
        }
    }



    void
    HierarchicalHashGrid::rehash(const unsigned int level, std::size_t capacity)
    {
      Level            &lvl = levels_[level];
      std::vector<Cell> old;
      old.swap(lvl.table);
      // Keep the load factor at most 1/4 for the occupied cells; empty cells
      // are dropped here, which is how the table forgets vacated cells.
      std::size_t n_occupied = 0;
      for (const Cell &c : old)
        n_occupied += (c.used() && c.count > 0);
      while (capacity < 4 * n_occupied + 64)
        capacity *= 2;
      lvl.table.assign(capacity, Cell());
      lvl.n_used_slots = 0;
      for (const Cell &c : old)
        if (c.used() && c.count > 0)
          {
            const int     first = c.head;
            const Object &o     = objects_[first];
            const int     s     = insert_slot(lvl, o.x, o.y, o.z);
            lvl.table[s].head   = c.head;
            lvl.table[s].count  = c.count;
            for (int q = c.head; q >= 0; q = objects_[q].next)
              objects_[q].slot = s;
          }
    }



    void
    HierarchicalHashGrid::unlink(const unsigned int id)
    {
      Object &o = objects_[id];
      if (o.level < 0)
        return;
      Level &lvl = levels_[o.level];
      Cell  &c   = lvl.table[o.slot];
      if (o.prev >= 0)
        objects_[o.prev].next = o.next;
      else
        c.head = o.next;
      if (o.next >= 0)
        objects_[o.next].prev = o.prev;
      --c.count;
      --lvl.n_objects;
      o.level = o.slot = o.next = o.prev = -1;
    }



    void
    HierarchicalHashGrid::link(const unsigned int id,
                               const unsigned int level,
                               int                slot)
    {
      Object &o   = objects_[id];
      Level  &lvl = levels_[level];
      Cell   &c   = lvl.table[slot];
      o.level     = level;
      o.slot      = slot;
      o.prev      = -1;
      o.next      = c.head;
      if (c.head >= 0)
        objects_[c.head].prev = id;
      c.head = id;
      ++c.count;
      ++lvl.n_objects;
    }



    void
    HierarchicalHashGrid::update(const std::vector<BroadPhaseProxy> &proxies)
    {
      if (proxies.size() < objects_.size())
        {
          // Bodies are never removed from a World; a shrinking input means a
          // new scene: start over.
          *this = HierarchicalHashGrid(ratio_);
        }
      proxies_ = proxies;
      spheres_.resize(proxies.size());
      fixed_.resize(proxies.size());
      for (std::size_t i = 0; i < proxies.size(); ++i)
        {
          spheres_[i] << proxies[i].center, proxies[i].radius;
          fixed_[i] = proxies[i].fixed;
        }
      objects_.resize(proxies.size());
      unbounded_.clear();
      n_moved_ = 0;

      if (h0_ == 0.)
        {
          double rmin = std::numeric_limits<double>::infinity();
          for (const auto &p : proxies)
            if (std::isfinite(p.radius))
              rmin = std::min(rmin, p.radius);
          if (std::isfinite(rmin))
            h0_ = rmin > 0. ? 2. * rmin * (1. + 1.e-9) : 1.e-6;
        }

      for (unsigned int id = 0; id < proxies.size(); ++id)
        {
          const BroadPhaseProxy &p = proxies[id];
          if (!p.center.allFinite() || std::isnan(p.radius) || p.radius < 0.)
            throw std::runtime_error(
              "rigid::HierarchicalHashGrid::update(): body "
              + std::to_string(id)
              + " has a non-finite position or an invalid bounding radius; "
                "the simulation has probably blown up (reduce the time step "
                "or raise the number of substeps).");
          if (!std::isfinite(p.radius))
            {
              unlink(id);
              unbounded_.push_back(id);
              continue;
            }
          const int          l = level_for(p.radius);
          const double       h = levels_[l].h;
          const std::int64_t x = cell_coordinate(p.center[0], h),
                             y = cell_coordinate(p.center[1], h),
                             z = cell_coordinate(p.center[2], h);
          Object &o            = objects_[id];
          if (o.level == l && o.x == x && o.y == y && o.z == z)
            continue;
          ++n_moved_;
          unlink(id);
          Level &lvl = levels_[l];
          if (2 * (lvl.n_used_slots + 1) > lvl.table.size())
            rehash(l, lvl.table.size());
          const int s = insert_slot(levels_[l], x, y, z);
          o.x         = x;
          o.y         = y;
          o.z         = z;
          link(id, l, s);
        }
    }



    void
    HierarchicalHashGrid::find_pairs(std::vector<BodyPair> &pairs) const
    {
      pairs.clear();
      const unsigned int n  = objects_.size();
      const unsigned int nl = levels_.size();
      // Bounded pairs are tested on the compact sphere array (32 bytes per
      // body instead of the 72-byte proxy: the search is memory bound).
      auto report = [&](const unsigned int a, const unsigned int b) {
        if (fixed_[a] && fixed_[b])
          return;
        const Eigen::Vector4d &sa = spheres_[a], &sb = spheres_[b];
        const double           r = sa[3] + sb[3];
        if ((sa.head<3>() - sb.head<3>()).squaredNorm() <= r * r)
          pairs.push_back(a < b ? BodyPair{a, b} : BodyPair{b, a});
      };
      auto visit_cell = [&](const Level       &lvl,
                            const std::int64_t x,
                            const std::int64_t y,
                            const std::int64_t z,
                            const unsigned int id) {
        const int s = find_slot(lvl, x, y, z);
        if (s < 0)
          return;
        for (int o = lvl.table[s].head; o >= 0; o = objects_[o].next)
          report(id, o);
      };

      for (unsigned int id = 0; id < n; ++id)
        {
          const Object &o = objects_[id];
          if (o.level < 0)
            continue;
          const Level           &lvl = levels_[o.level];
          const Eigen::Vector3d &c   = proxies_[id].center;
          const double           r   = proxies_[id].radius;
          // Own cell: only the objects behind this one in the list.
          for (int q = o.next; q >= 0; q = objects_[q].next)
            report(id, q);
          // Half of the neighbours on the own level, skipping those out of
          // reach: a partner on this level has a radius below h/2, so a
          // neighbour cell across a face further than r + h/2 away cannot
          // hold one.
          const double       reach = r + 0.5 * lvl.h;
          bool               lo_ok[3], hi_ok[3];
          const std::int64_t cell[3] = {o.x, o.y, o.z};
          for (int k = 0; k < 3; ++k)
            {
              lo_ok[k] = c[k] - cell[k] * lvl.h <= reach;
              hi_ok[k] = (cell[k] + 1) * lvl.h - c[k] <= reach;
            }
          for (const auto &d : half_offsets)
            {
              bool ok = true;
              for (int k = 0; k < 3; ++k)
                ok = ok && (d[k] == 0 || (d[k] > 0 ? hi_ok[k] : lo_ok[k]));
              if (ok)
                visit_cell(lvl, o.x + d[0], o.y + d[1], o.z + d[2], id);
            }
          // All coarser levels that hold objects (Algorithm 2, inner loop):
          // only the cells within r + h_l/2 of the centre, i.e. 2 x 2 x 2 of
          // the 27 around it for small objects.
          for (unsigned int l = o.level + 1; l < nl; ++l)
            {
              const Level &up = levels_[l];
              if (up.n_objects == 0)
                continue;
              const double       reach_l = r + 0.5 * up.h;
              const std::int64_t x0 = cell_coordinate(c[0] - reach_l, up.h),
                                 x1 = cell_coordinate(c[0] + reach_l, up.h),
                                 y0 = cell_coordinate(c[1] - reach_l, up.h),
                                 y1 = cell_coordinate(c[1] + reach_l, up.h),
                                 z0 = cell_coordinate(c[2] - reach_l, up.h),
                                 z1 = cell_coordinate(c[2] + reach_l, up.h);
              for (std::int64_t x = x0; x <= x1; ++x)
                for (std::int64_t y = y0; y <= y1; ++y)
                  for (std::int64_t z = z0; z <= z1; ++z)
                    visit_cell(up, x, y, z, id);
            }
        }
      // Unbounded bodies against everything else.
      for (const unsigned int u : unbounded_)
        for (unsigned int id = 0; id < n; ++id)
          if (id != u && (std::isfinite(proxies_[id].radius) || id > u))
            {
              if (proxies_overlap(proxies_[u], proxies_[id]))
                pairs.push_back(u < id ? BodyPair{u, id} : BodyPair{id, u});
            }
    }



    void
    HierarchicalHashGrid::validate() const
    {
      auto fail = [](const std::string &what) {
        throw std::logic_error("rigid::HierarchicalHashGrid::validate(): "
                               + what);
      };
      std::vector<unsigned int> seen(objects_.size(), 0);
      for (unsigned int l = 0; l < levels_.size(); ++l)
        {
          unsigned int n_obj = 0;
          for (unsigned int s = 0; s < levels_[l].table.size(); ++s)
            {
              const Cell &c = levels_[l].table[s];
              if (!c.used())
                continue;
              unsigned int cnt  = 0;
              int          prev = -1;
              for (int o = c.head; o >= 0; o = objects_[o].next)
                {
                  const Object &ob = objects_[o];
                  if (ob.level != int(l) || ob.slot != int(s)
                      || ob.prev != prev)
                    fail("object " + std::to_string(o) + " has stale links");
                  if (pack(ob.x, ob.y, ob.z) != c.key)
                    fail("object " + std::to_string(o) + " in the wrong cell");
                  const double h = levels_[l].h;
                  const auto  &p = proxies_[o].center;
                  if (cell_coordinate(p[0], h) != ob.x
                      || cell_coordinate(p[1], h) != ob.y
                      || cell_coordinate(p[2], h) != ob.z)
                    fail("object " + std::to_string(o)
                         + " centre outside its cell");
                  if (!(h > 2. * proxies_[o].radius))
                    fail("cell smaller than the diameter (eq. 3.2)");
                  ++seen[o];
                  ++cnt;
                  prev = o;
                }
              if (cnt != c.count)
                fail("cell count mismatch");
              n_obj += cnt;
            }
          if (n_obj != levels_[l].n_objects)
            fail("level object count mismatch");
        }
      for (unsigned int i = 0; i < objects_.size(); ++i)
        if (std::isfinite(proxies_[i].radius) && seen[i] != 1)
          fail("object " + std::to_string(i) + " stored "
               + std::to_string(seen[i]) + " times");
    }
  } // namespace rigid
} // namespace particulate
