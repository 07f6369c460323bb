#ifndef particulate_geometry_shape_h
#define particulate_geometry_shape_h

#include <particulate/geometry/bounding_box.h>
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace particulate {
  namespace geometry {

    /**
     * The kinds of shape that the rigid engine's narrow phase pairs with
     * dedicated routines (thesis §3.4). Every other solid (surface meshes,
     * distance maps, tori) is `general`: met through its signed distance and
     * its surface points. The numbering is the narrow phase's dispatch order:
     * of two bodies, the one of lower kind is body "a" of the pair.
     */
    enum class ShapeKind
    {
      sphere     = 0,
      box        = 1,
      capsule    = 2,
      cylinder   = 3,
      ellipsoid  = 4,
      general    = 5,
      half_space = 6
    };

    /**
     * A solid in its own body frame: the one description of a body's shape
     * that every module reads (thesis §3.4, §4.2, §5.4). The rigid engine uses
     * the support function (GJK/EPA), the signed distance and the surface
     * points for contacts and the mass properties for the dynamics; the
     * fictitious boundary method uses the containment; the mesh deformation
     * uses the signed distance; distance maps and inner spheres are built from
     * it.
     *
     * Conventions: the signed distance is negative inside, zero on the surface
     * and positive outside, in the length unit of the shape's coordinates [m];
     * the normal is its gradient, the outward unit normal of the closest
     * surface point. The analytic shapes are centred at their centroid with
     * their principal axes along the body axes, the frame the rigid engine
     * needs. Implementations are thread-safe for concurrent const calls.
     */
    class Shape
    {
    public:
      virtual ~Shape() = default;

      /** Which of the narrow phase's kinds this is (general by default). */
      virtual ShapeKind
      kind() const
      {
        return ShapeKind::general;
      }

      /** Short name for messages and output ("sphere", "box", ...). */
      virtual std::string
      name() const = 0;

      /**
       * Signed distance from the body-frame point @p p to the surface [m].
       * @param p query point in the body frame [m]
       * @param normal if not null, receives the outward unit normal (the
       *   gradient of the signed distance; at points with several closest
       *   surface points one of them is chosen)
       */
      virtual double
      signed_distance(const Eigen::Vector3d &p,
                      Eigen::Vector3d       *normal = nullptr) const = 0;

      /**
       * The point of the surface closest to @p p (body frame) [m]. The default
       * steps back along the normal by the signed distance, which is exact for
       * every shape whose signed distance is the Euclidean one.
       */
      virtual Eigen::Vector3d
      closest_point(const Eigen::Vector3d &p) const;

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

      /** Radius of a ball about the body-frame origin that contains the solid
       *  [m] (infinite for unbounded shapes). The default is the farthest
       *  corner of bounding_box(); analytic shapes give the tight value. */
      virtual double
      bounding_radius() const;

      /** Whether the solid is bounded (false only for the half-space). */
      virtual bool
      is_bounded() const
      {
        return true;
      }

      /** Volume of the solid [m^3] (infinity for unbounded shapes). */
      virtual double
      volume() const = 0;

      /** Centroid of the solid in the body frame [m] (the origin for the
       *  analytic shapes). */
      virtual Eigen::Vector3d
      centroid() const
      {
        return Eigen::Vector3d::Zero();
      }

      /**
       * Inertia tensor for unit density about the centroid, in the body frame
       * [m^5] (multiply by the density [kg/m^3] to get kg m^2; thesis eqs.
       * 4.24-4.29). The default throws: a shape that does not know its mass
       * properties cannot be a dynamic rigid body.
       */
      virtual Eigen::Matrix3d
      unit_inertia() const;

      /** Whether the solid is convex and bounded, so that support() exists. */
      virtual bool
      is_convex() const
      {
        return false;
      }

      /**
       * Support point: the point of the solid furthest along the body-frame
       * direction @p d (need not be unit), as GJK/EPA need it (thesis §3.4.2).
       * The default throws: only convex shapes have one.
       */
      virtual Eigen::Vector3d
      support(const Eigen::Vector3d &d) const;

      /** Radius of the ball swept over the shape's core: r for spheres (core:
       *  the centre) and capsules (core: the axis segment), 0 for the rest.
       *  GJK works on the cores when they are apart, which is exact and needs
       *  no EPA for shallow overlaps of round shapes. */
      virtual double
      core_radius() const
      {
        return 0.;
      }

      /** Representative points on the surface in the body frame [m] (the
       *  vertices of a surface mesh), which the narrow phase tests against the
       *  signed distance of a partner that has no support function. */
      virtual std::vector<Eigen::Vector3d>
      surface_points() const
      {
        return {};
      }

      /**
       * A closed, outward-oriented triangulation of the surface in the body
       * frame, fine enough to show the shape (the bodies' ParaView output),
       * with its vertices on the surface. The default projects the
       * triangulation of the sphere inscribed in the bounding box about the
       * centroid onto the surface (steps along the normal by the distance),
       * which suits shapes that are star-shaped about their centroid; the
       * analytic shapes and surface meshes give their own. Empty for unbounded
       * shapes.
       */
      virtual TriangleMesh
      surface_mesh() const;
    };

  } // namespace geometry
} // namespace particulate

#endif
