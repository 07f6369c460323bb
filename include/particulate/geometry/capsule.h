#ifndef particulate_geometry_capsule_h
#define particulate_geometry_capsule_h

#include <particulate/geometry/shape.h>

namespace particulate {
  namespace geometry {

    /**
     * A capsule: the points within radius r of the core segment from
     * (0, 0, -h) to (0, 0, h) in the body frame (a cylinder of length 2h with
     * hemispherical caps); exact distance |p - clamp(p)| - r. A stadium in a
     * 2D run is not a capsule but a 3D body; 2D runs use it as the body of a
     * slab.
     */
    class Capsule : public Shape
    {
    public:
      /**
       * @param radius r > 0 [m]
       * @param half_length h >= 0, half the length of the core segment [m]
       */
      Capsule(const double radius, const double half_length);

      /** Radius [m]. */
      double
      radius() const
      {
        return r;
      }

      /** Half the length of the core segment [m]. */
      double
      half_length() const
      {
        return hl;
      }

      ShapeKind
      kind() const override
      {
        return ShapeKind::capsule;
      }

      std::string
      name() const override
      {
        return "capsule";
      }

      double
      signed_distance(const Eigen::Vector3d &p,
                      Eigen::Vector3d       *normal = nullptr) const override;

      BoundingBox
      bounding_box() const override;

      double
      bounding_radius() const override
      {
        return hl + r;
      }

      double
      volume() const override;

      /** The cylinder's inertia plus that of the two hemispheres, moved to
       *  their centroids 3r/8 beyond the segment's ends. */
      Eigen::Matrix3d
      unit_inertia() const override;

      bool
      is_convex() const override
      {
        return true;
      }

      Eigen::Vector3d
      support(const Eigen::Vector3d &d) const override;

      double
      core_radius() const override
      {
        return r;
      }

      /** 12 points around each end circle and the middle circle, and the two
       *  poles. */
      std::vector<Eigen::Vector3d>
      surface_points() const override;

      /** The display triangulation: 32 segments around, 16 rings over each
       *  hemisphere. */
      TriangleMesh
      surface_mesh() const override;

    private:
      double r;
      double hl;
    };

  } // namespace geometry
} // namespace particulate

#endif
