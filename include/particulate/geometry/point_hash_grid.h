#ifndef particulate_geometry_point_hash_grid_h
#define particulate_geometry_point_hash_grid_h

#include <particulate/geometry/bounding_box.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace particulate {
  namespace geometry {

    /**
     * A hash grid over a fixed set of points (thesis §5.4.2): the points are
     * sorted into uniform cubic cells, and only non-empty cells are stored, in
     * a hash table keyed by the integer cell coordinates. So a rank's irregular
     * part of a mesh costs no memory for the empty parts of its bounding box,
     * and finding the points inside a box costs the cells the box overlaps plus
     * the points in them, not all points.
     */
    class PointHashGrid
    {
    public:
      /**
       * @param points the points (copied) [m]
       * @param cell_size edge of the cubic cells [m]; 0 chooses about two
       *   points per cell on average from the points' bounding box
       * @throw GeometryError for a negative cell size or non-finite points
       */
      explicit PointHashGrid(std::vector<Eigen::Vector3d> points,
                             const double                 cell_size = 0.);

      /**
       * Call @p f(i) for every point i inside the closed box @p box, in order
       * of cells. Returns the number of points inside the box.
       */
      template <typename F>
      std::size_t
      for_each_in_box(const BoundingBox &box, F &&f) const;

      /** The points. */
      const std::vector<Eigen::Vector3d> &
      points() const
      {
        return pts;
      }

      /** Number of points. */
      std::size_t
      size() const
      {
        return pts.size();
      }

      /** Cell edge [m]. */
      double
      cell_size() const
      {
        return h;
      }

      /** Number of non-empty cells. */
      std::size_t
      n_cells() const
      {
        return cells.size();
      }

      /** Box of all points. */
      const BoundingBox &
      bounding_box() const
      {
        return box;
      }

    private:
      std::vector<Eigen::Vector3d> pts;
      BoundingBox                  box;
      double                       h = 1.;
      // Point ids sorted by cell; each non-empty cell maps to its range.
      std::vector<std::uint32_t> order;
      struct Range
      {
        std::uint32_t begin, end;
      };
      std::unordered_map<std::uint64_t, Range> cells;
      std::vector<std::uint64_t>               cell_keys; // for sparse sweeps

      static std::uint64_t
      key(std::int64_t i, std::int64_t j, std::int64_t k);
      std::int64_t
      coord(const double x, const int d) const;
    };

    // -------------------------------------------------------------------------

    inline std::uint64_t
    PointHashGrid::key(std::int64_t i, std::int64_t j, std::int64_t k)
    {
      // 21 bits per direction, offset so that cell coordinates relative to the
      // points' box (>= 0) fit; coordinates are clamped before this is called.
      return (static_cast<std::uint64_t>(i) << 42)
             | (static_cast<std::uint64_t>(j) << 21)
             | static_cast<std::uint64_t>(k);
    }

    inline std::int64_t
    PointHashGrid::coord(const double x, const int d) const
    {
      const double s = std::floor((x - box.lower[d]) / h);
      return static_cast<std::int64_t>(std::min(std::max(s, 0.), 2097151.));
    }

    template <typename F>
    std::size_t
    PointHashGrid::for_each_in_box(const BoundingBox &query, F &&f) const
    {
      if (pts.empty() || query.empty() || !query.intersects(box))
        return 0;
      std::int64_t lo[3], hi[3];
      double       n_box_cells = 1.;
      for (int d = 0; d < 3; ++d)
        {
          lo[d] = coord(std::max(query.lower[d], box.lower[d]), d);
          hi[d] = coord(std::min(query.upper[d], box.upper[d]), d);
          n_box_cells *= double(hi[d] - lo[d] + 1);
        }
      std::size_t found = 0;
      auto        visit = [&](const Range &r) {
        for (std::uint32_t q = r.begin; q < r.end; ++q)
          if (query.contains(pts[order[q]]))
            {
              ++found;
              f(static_cast<std::size_t>(order[q]));
            }
      };
      if (n_box_cells <= double(cells.size()))
        {
          for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
            for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
              for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
                {
                  const auto it = cells.find(key(i, j, k));
                  if (it != cells.end())
                    visit(it->second);
                }
        }
      else
        {
          // The box spans more cells than are occupied: sweep the occupied
          // ones.
          for (const std::uint64_t c : cell_keys)
            {
              const std::int64_t i = c >> 42, j = (c >> 21) & 2097151,
                                 k = c & 2097151;
              if (i >= lo[0] && i <= hi[0] && j >= lo[1] && j <= hi[1]
                  && k >= lo[2] && k <= hi[2])
                visit(cells.at(c));
            }
        }
      return found;
    }

  } // namespace geometry
} // namespace particulate

#endif
