#ifndef particulate_geometry_tube_h
#define particulate_geometry_tube_h

#include <particulate/geometry/shape.h>

namespace particulate {
  namespace geometry {

    /**
     * A thick-walled circular pipe around the body z axis: the solid between
     * the radii r_i and r_i + w, from z = -h to z = h. As a fixed body it is
     * the mantle of a cylindrical container (a fluidized-bed column): the
     * particles move in its bore. Exact signed distance, that of the
     * rectangle [r_i, r_i + w] x [-h, h] in the (distance from the axis, z)
     * half-plane, revolved. Not convex: the narrow phase meets it through
     * its signed distance (a sphere's centre, another shape's surface
     * points).
     */
    class Tube : public Shape
    {
    public:
      /**
       * @param inner_radius r_i > 0, the radius of the bore [m]
       * @param wall_thickness w > 0 [m]
       * @param half_length h > 0 [m]
       */
      Tube(const double inner_radius,
           const double wall_thickness,
           const double half_length);

      /** The radius of the bore [m]. */
      double
      inner_radius() const
      {
        return ri;
      }

      std::string
      name() const override
      {
        return "tube";
      }

      double
      signed_distance(const Eigen::Vector3d &p,
                      Eigen::Vector3d       *normal = nullptr) const override;

      BoundingBox
      bounding_box() const override;

      double
      bounding_radius() const override;

      double
      volume() const override;

      /** V (3 (r_i^2 + r_o^2) + 4 h^2) / 12 about the transverse axes,
       *  V (r_i^2 + r_o^2) / 2 about z, r_o = r_i + w. */
      Eigen::Matrix3d
      unit_inertia() const override;

      /** The display triangulation: the bore, the outer mantle and the two
       *  annular ends, 64 segments around. */
      TriangleMesh
      surface_mesh() const override;

    private:
      double ri;
      double w;
      double hh;
    };

  } // namespace geometry
} // namespace particulate

#endif
