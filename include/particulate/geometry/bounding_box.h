#ifndef particulate_geometry_bounding_box_h
#define particulate_geometry_bounding_box_h

#include <Eigen/Core>

#include <limits>

namespace particulate {
  namespace geometry {

    /**
     * An axis-aligned box [lower, upper] in 3D (lengths in metres, or whatever
     * unit the surrounding code uses consistently). A default-constructed box
     * is empty (lower > upper) so that extending it by points works from
     * scratch.
     */
    struct BoundingBox
    {
      /** Lower corner. */
      Eigen::Vector3d lower
        = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
      /** Upper corner. */
      Eigen::Vector3d upper
        = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

      BoundingBox() = default;

      /** A box with the given corners. */
      BoundingBox(const Eigen::Vector3d &lower_corner,
                  const Eigen::Vector3d &upper_corner)
        : lower(lower_corner)
        , upper(upper_corner)
      {}

      /** True if no point has been added (or lower > upper in some
       *  direction). */
      bool
      empty() const
      {
        return (lower.array() > upper.array()).any();
      }

      /** Grow the box so that it contains @p p. */
      void
      extend(const Eigen::Vector3d &p)
      {
        lower = lower.cwiseMin(p);
        upper = upper.cwiseMax(p);
      }

      /** Grow the box so that it contains @p other. */
      void
      extend(const BoundingBox &other)
      {
        lower = lower.cwiseMin(other.lower);
        upper = upper.cwiseMax(other.upper);
      }

      /** Grow the box by @p margin in every direction. */
      BoundingBox
      enlarged(const double margin) const
      {
        return BoundingBox(lower.array() - margin, upper.array() + margin);
      }

      /** True if @p p lies in the closed box. */
      bool
      contains(const Eigen::Vector3d &p) const
      {
        return (p.array() >= lower.array()).all()
               && (p.array() <= upper.array()).all();
      }

      /** True if the two closed boxes share at least one point. */
      bool
      intersects(const BoundingBox &other) const
      {
        return (lower.array() <= other.upper.array()).all()
               && (other.lower.array() <= upper.array()).all();
      }

      /** upper - lower. */
      Eigen::Vector3d
      extent() const
      {
        return upper - lower;
      }

      /** Midpoint of the box. */
      Eigen::Vector3d
      center() const
      {
        return 0.5 * (lower + upper);
      }
    };

  } // namespace geometry
} // namespace particulate

#endif
