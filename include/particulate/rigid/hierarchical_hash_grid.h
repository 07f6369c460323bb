#ifndef particulate_rigid_hierarchical_hash_grid_h
#define particulate_rigid_hierarchical_hash_grid_h

#include <particulate/rigid/broad_phase.h>

#include <array>
#include <cstdint>
#include <vector>

namespace particulate {
  namespace rigid {
    /**
     * Hierarchical hash grid broad phase (thesis §3.2, Algorithm 2).
     *
     * - Level l has cubic cells of edge h_l = h_0 r^l (eq. 3.3, ratio r = 2 by
     *   default); an object goes to the finest level whose cell edge exceeds
     *   its bounding-sphere diameter (eq. 3.2), so two objects of one level
     *   can only overlap if their cells are neighbours (Fig. 3.7).
     * - Each object is stored once, in the cell holding its centre.
     * - Same-level search visits the object's own cell (objects behind it in
     *   the cell list) and half of the 26 neighbours, so no pair is reported
     *   twice (Fig. 3.8); cross-level search locates the object in every
     *   coarser non-empty level and visits the 27 cells around it
     *   (Algorithm 2).
     * - The grid is unbounded: cells live in an open-addressing hash table per
     *   level, keyed by integer cell coordinates, and only occupied cells
     *   cost memory.
     * - update() is O(n) and incremental: an object that stays in its cell
     *   costs one hash computation; one that moves is unlinked from its
     *   intrusive cell list and linked into the new one in O(1).
     *
     * Unbounded proxies (half-spaces) are kept aside and tested against every
     * bounded proxy through its plane distance.
     */
    class HierarchicalHashGrid : public BroadPhase
    {
    public:
      /**
       * @param level_ratio Ratio r > 1 of cell sizes of successive levels.
       */
      explicit HierarchicalHashGrid(double level_ratio = 2.);

      void
      update(const std::vector<BroadPhaseProxy> &proxies) override;
      void
      find_pairs(std::vector<BodyPair> &pairs) const override;

      /** Number of levels currently allocated. */
      unsigned int
      n_levels() const
      {
        return levels_.size();
      }
      /** Cell edge h_l of level @p l in m. */
      double
      cell_size(unsigned int l) const;
      /** Number of objects that changed cell in the last update(). */
      unsigned int
      n_moved_last_update() const
      {
        return n_moved_;
      }
      /** Checks the internal consistency of lists and tables; throws
       * std::logic_error on the first broken invariant (debug aid, O(n)). */
      void
      validate() const;

    private:
      /** A hash-table slot: 16 bytes so that probing stays in cache. The
       * key packs 21 bits per cell coordinate (cells more than 2^20 apart
       * alias, which only costs exact overlap tests of far-apart objects,
       * never a missed or duplicated pair). */
      struct Cell
      {
        std::uint64_t key   = 0;
        int           head  = -1;  // first object, -1: empty
        unsigned int  count = ~0u; // number of objects; ~0u: slot unused
        bool
        used() const
        {
          return count != ~0u;
        }
      };
      struct Level
      {
        double            h = 1.;
        std::vector<Cell> table; // power-of-two capacity
        unsigned int      n_used_slots = 0;
        unsigned int      n_objects    = 0;
      };
      static std::uint64_t
      pack(std::int64_t x, std::int64_t y, std::int64_t z);
      struct Object
      {
        int          level = -1; // -1: unbounded or not inserted
        int          slot  = -1;
        int          next = -1, prev = -1;
        std::int64_t x = 0, y = 0, z = 0;
      };

      int
      level_for(double radius);
      int
      find_slot(const Level &lvl,
                std::int64_t x,
                std::int64_t y,
                std::int64_t z) const;
      int
      insert_slot(Level &lvl, std::int64_t x, std::int64_t y, std::int64_t z);
      void
      rehash(unsigned int level, std::size_t capacity);
      void
      unlink(unsigned int id);
      void
      link(unsigned int id, unsigned int level, int slot);

      double                       ratio_;
      double                       h0_ = 0.;
      std::vector<Level>           levels_;
      std::vector<Object>          objects_;
      std::vector<BroadPhaseProxy> proxies_;
      std::vector<Eigen::Vector4d> spheres_; // centre and radius, compact
      std::vector<char>            fixed_;
      std::vector<unsigned int>    unbounded_;
      unsigned int                 n_moved_ = 0;
    };
  } // namespace rigid
} // namespace particulate

#endif
