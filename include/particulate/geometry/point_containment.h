#ifndef particulate_geometry_point_containment_h
#define particulate_geometry_point_containment_h

#include <particulate/geometry/point_hash_grid.h>
#include <particulate/geometry/pose.h>
#include <particulate/geometry/shape.h>

#include <cstddef>
#include <vector>

namespace particulate {
  namespace geometry {

    /** A shape placed in the world: what the containment functions classify
     *  against. The shape is not owned and must outlive the call. */
    struct PlacedShape
    {
      const Shape *shape = nullptr;
      Pose         pose;
    };

    /** Counters of one classification (for the benchmark and the tests). */
    struct ContainmentStatistics
    {
      /** Points in the set. */
      std::size_t n_points = 0;
      /** Point-in-body tests made (a point counts once per body whose box holds
       *  it): the work the hash grid saves against n_points x n_bodies. */
      std::size_t n_tests = 0;
      /** Distinct points tested at least once (the "vertices touched"). */
      std::size_t n_points_touched = 0;
    };

    /**
     * Point classification by bounding boxes and a hash grid (thesis §5.4.1-2,
     * Algorithm 9 generalised to unstructured point sets): for each body, only
     * the points of the hash grid inside the body's world bounding box are
     * tested with Shape::contains in the body frame.
     *
     * @param grid the points (e.g. a rank's mesh vertices or support points)
     * @param bodies the placed shapes
     * @param distances if not null, receives per point the smallest signed
     *   distance [m] to any body whose box holds it (+infinity for points in no
     *   box); costs a distance query per tested point
     * @param statistics if not null, receives the counters
     * @return per point the index of the first body containing it, or -1
     */
    std::vector<int>
    classify_points(const PointHashGrid            &grid,
                    const std::vector<PlacedShape> &bodies,
                    std::vector<double>            *distances  = nullptr,
                    ContainmentStatistics          *statistics = nullptr);

    /**
     * The reference: every point against every body, O(points x bodies).
     * Returns the same as classify_points().
     */
    std::vector<int>
    classify_points_brute_force(const std::vector<Eigen::Vector3d> &points,
                                const std::vector<PlacedShape>     &bodies);

    /** The world box of a placed shape, slightly enlarged against rounding;
     *  infinite shapes (half-spaces) give an infinite box. */
    BoundingBox
    world_bounding_box(const PlacedShape &body);

  } // namespace geometry
} // namespace particulate

#endif
