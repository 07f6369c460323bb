#ifndef PARTICULATE_GEOMETRY_SHAPE_H
#define PARTICULATE_GEOMETRY_SHAPE_H

#include <particulate/geometry/bounding_box.h>
#include <particulate/geometry/geometry_error.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace particulate::geometry {

  /**
   * A solid in its own body frame, seen through its signed distance: the one
   * interface the distance maps, the inner spheres, the point containment and
   * the narrow phase use for every geometry representation of thesis §3.4
   * (analytic shapes and surface triangulations alike).
   *
   * Convention: the signed distance is negative inside, zero on the surface and
   * positive outside, in the length unit of the shape's coordinates [m]; the
   * normal is its gradient, the outward unit normal of the closest surface
   * point. Implementations are thread-safe for concurrent const calls.
   */
  class Shape
  {
  public:
    virtual ~Shape() = default;

    /**
     * Signed distance from the body-frame point @p p to the surface [m].
     * @param p query point in the body frame [m]
     * @param normal if not null, receives the outward unit normal (the
     *   gradient of the signed distance; at points with several closest surface
     *   points one of them is chosen)
     */
    virtual double
    signed_distance(const Eigen::Vector3d &p,
                    Eigen::Vector3d       *normal = nullptr) const = 0;

    /**
     * Signed distances and normals of many points at once, in order, e.g. a
     * line of distance-map grid points. The default calls signed_distance()
     * per point; triangulated surfaces override it to reuse the previous
     * closest point as a search hint, which is much faster for neighbouring
     * points.
     * @param points body-frame points [m]
     * @param distances receives points.size() signed distances [m]
     * @param normals if not null, receives points.size() outward normals
     */
    virtual void
    signed_distances(const std::vector<Eigen::Vector3d> &points,
                     std::vector<double>                &distances,
                     std::vector<Eigen::Vector3d> *normals = nullptr) const;

    /**
     * True if @p p (body frame) is inside or on the surface. The default uses
     * the sign of signed_distance(); shapes with a more robust or faster test
     * override it.
     */
    virtual bool
    contains(const Eigen::Vector3d &p) const;

    /**
     * The inside test of many points at once: @p inside[i] =
     * contains(@p points[i]), exactly. The default calls contains() per
     * point; shapes with a faster batched query override it (a
     * DistanceMapShape answers through DistanceMap::distances(), which
     * overlaps the memory accesses of the points). The point containment
     * (classify_points) hands each body its candidate points this way.
     * @param points body-frame points [m]
     * @param count number of points
     * @param inside receives @p count answers
     */
    virtual void
    contains_points(const Eigen::Vector3d *points,
                    std::size_t            count,
                    bool                  *inside) const;

    /** A box containing the solid, in the body frame [m]. Infinite for
     *  unbounded shapes (the half-space). */
    virtual BoundingBox
    bounding_box() const = 0;

    /** Volume of the solid [m^3] (infinity for unbounded shapes). */
    virtual double
    volume() const = 0;
  };

} // namespace particulate::geometry

#endif
