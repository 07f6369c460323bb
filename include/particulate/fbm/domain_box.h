#ifndef particulate_fbm_domain_box_h
#define particulate_fbm_domain_box_h

#include <particulate/core/mesh.h>
#include <particulate/geometry/shape.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <optional>

namespace particulate {
  namespace fbm {
    struct ParticleParameters;

    /** The box of the mesh and what its faces are to the bodies. */
    struct DomainBox
    {
      Eigen::Vector3d lower = Eigen::Vector3d::Zero();
      Eigen::Vector3d upper = Eigen::Vector3d::Zero();
      /// faces x-, x+, y-, y+, z-, z+ that are walls of the rigid engine
      std::array<bool, 6> walls{};
      /// faces that are mirror planes of a symmetric set-up
      std::array<bool, 6> mirror_planes{};
      unsigned int        dim = 3;
      /// > 0 for a 'column' mesh: the domain is the circular cylinder of
      /// this radius [m] about the z axis through the centre of the box's
      /// x-y rectangle, and the faces x-, x+, y-, y+ stand for its mantle
      /// (a wall when they are)
      double column_radius = 0.;
      /// where there is one, the height [m] of a fluidized bed's
      /// distributor: the lowest wall (z-, y- in 2D) lies there instead
      std::optional<double> distributor;

      /** Where the wall of @p face (x-, x+, y-, y+, z-, z+ = 0..5) lies
       *  along its axis: the box's face, the lowest one raised to the
       *  distributor where there is one. */
      double
      wall_position(const unsigned int face) const
      {
        const unsigned int d = face / 2;
        if (face % 2 == 1)
          return upper[d];
        return (distributor && d == dim - 1) ? *distributor : lower[d];
      }

      /** Whether the domain is a column. */
      bool
      is_column() const
      {
        return column_radius > 0.;
      }

      /** How far the world point @p x lies from the column's axis [m]. */
      double
      distance_from_axis(const Eigen::Vector3d &x) const
      {
        return std::hypot(x[0] - 0.5 * (lower[0] + upper[0]),
                          x[1] - 0.5 * (lower[1] + upper[1]));
      }
    };

    /**
     * The domain of a run for its bodies: the mesh's bounding box
     * @p lower, @p upper, a column's radius where @p mesh is one, and the
     * walls and mirror planes of @p particles.
     * @throw std::runtime_error where the walls or mirror planes do not fit
     *   a column: its mantle is one wall (x-, x+, y-, y+ together, or
     *   'mantle') and no mirror plane
     */
    DomainBox
    make_domain_box(const core::MeshParameters &mesh,
                    const ParticleParameters   &particles,
                    const Eigen::Vector3d      &lower,
                    const Eigen::Vector3d      &upper,
                    const unsigned int          dim);

    /** How far from the axis of the column @p domain a body of @p shape at
     *  @p orientation, @p position reaches [m]: a convex shape's support
     *  point along the direction from the axis to its centre (exact for a
     *  body small against the column), the farthest surface point of a
     *  non-convex one, else its centre's distance plus its bounding
     *  radius. */
    double
    reach_from_axis(const DomainBox          &domain,
                    const geometry::Shape    &shape,
                    const Eigen::Quaterniond &orientation,
                    const Eigen::Vector3d    &position);
  } // namespace fbm
} // namespace particulate

#endif
