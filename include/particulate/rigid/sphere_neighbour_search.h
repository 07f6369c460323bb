#ifndef particulate_rigid_sphere_neighbour_search_h
#define particulate_rigid_sphere_neighbour_search_h

#include <Eigen/Core>

#include <cstdint>
#include <utility>
#include <vector>

namespace particulate {
  namespace rigid {
    /**
     * Broad phase of the sphere-only DEM path (SphereDem): a uniform cell list
     * that puts the spheres in spatial order and lists the close pairs in that
     * order.
     *
     * The cells are at least as wide as the largest cutoff distance, so that
     * every close pair lies in the same or in adjacent cells; cells are
     * numbered z-major, y, x, and a sphere's new index is its rank in (cell,
     * old index) order, so that spheres of one cell, and mostly of
     * neighbouring cells, sit next to each other in memory: the force loop
     * then reads the positions and velocities of a pair from nearby cache
     * lines. The result depends only on the positions and radii (a restart
     * rebuilds exactly the same order and list).
     */
    class SphereNeighbourSearch
    {
    public:
      /**
       * Sorts and searches.
       * @param x Sphere centres in m.
       * @param radius Sphere radii in m.
       * @param extra Cutoff beyond touching in m: (i, j) is a pair when
       * |x_i - x_j| <= r_i + r_j + extra.
       */
      SphereNeighbourSearch(const std::vector<Eigen::Vector3d> &x,
                            const std::vector<double>          &radius,
                            double                              extra);

      /** order()[k]: index into x of the sphere that gets the new index k. */
      const std::vector<unsigned int> &
      order() const
      {
        return order_;
      }

      /** Close pairs as new indices (first < second), cell by cell. */
      const std::vector<std::pair<std::uint32_t, std::uint32_t>> &
      pairs() const
      {
        return pairs_;
      }

    private:
      std::vector<unsigned int>                            order_;
      std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
    };
  } // namespace rigid
} // namespace particulate

#endif
