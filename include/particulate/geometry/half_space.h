#ifndef particulate_geometry_half_space_h
#define particulate_geometry_half_space_h

#include <particulate/geometry/shape.h>

namespace particulate {
  namespace geometry {

    /**
     * The half-space {x : n.x <= c} (a wall or floor; the solid lies on the
     * side opposite to the unit normal n); exact signed distance n.x - c.
     */
    class HalfSpace : public Shape
    {
    public:
      /**
       * @param normal outward normal n (normalised here; must not be zero)
       * @param offset c [m]: the boundary plane is n.x = c
       */
      HalfSpace(const Eigen::Vector3d &normal, const double offset);

      /** Unit outward normal n. */
      const Eigen::Vector3d &
      normal() const
      {
        return n;
      }

      /** Offset c of the plane n.x = c [m]. */
      double
      offset() const
      {
        return c;
      }

      ShapeKind
      kind() const override
      {
        return ShapeKind::half_space;
      }

      std::string
      name() const override
      {
        return "half-space";
      }

      bool
      is_bounded() const override
      {
        return false;
      }

      double
      signed_distance(const Eigen::Vector3d &p,
                      Eigen::Vector3d       *normal = nullptr) const override;

      BoundingBox
      bounding_box() const override;

      double
      volume() const override;

    private:
      Eigen::Vector3d n;
      double          c;
    };

  } // namespace geometry
} // namespace particulate

#endif
