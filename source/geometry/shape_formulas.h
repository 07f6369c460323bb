#ifndef particulate_geometry_shape_formulas_h
#define particulate_geometry_shape_formulas_h

// Closed forms that several analytic shapes share (private to the module).

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace particulate {
  namespace geometry {
    namespace detail {

      /** The 26 directions from a cube cell to its neighbours, (i, j, k) with
       *  components in {-1, 0, 1}, not normalised: a cheap, symmetric sampling
       *  of the directions for surface points. */
      inline std::vector<Eigen::Vector3d>
      cube_neighbour_directions()
      {
        std::vector<Eigen::Vector3d> directions;
        for (int i = -1; i <= 1; ++i)
          for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k)
              if (i != 0 || j != 0 || k != 0)
                directions.emplace_back(i, j, k);
        return directions;
      }

      /** The unit-density inertia V / n (b^2 + c^2, a^2 + c^2, a^2 + b^2) of a
       *  solid with half axes (a, b, c) = @p half_axes along the body axes and
       *  volume V: n = 3 for the box, 5 for the ellipsoid [m^5]. */
      inline Eigen::Matrix3d
      axis_aligned_inertia(const double           n,
                           const double           volume,
                           const Eigen::Vector3d &half_axes)
      {
        const Eigen::Vector3d s = half_axes.cwiseAbs2();
        return (volume / n
                * Eigen::Vector3d(s[1] + s[2], s[0] + s[2], s[0] + s[1]))
          .asDiagonal();
      }

      /** Surface points of a cylinder along z with an elliptic section of
       *  semi-axes @p a, @p b and half height @p hh: 16 points around each rim
       *  and the middle section, and the two cap centres (a circular cylinder
       *  has a = b). */
      inline std::vector<Eigen::Vector3d>
      elliptic_prism_surface_points(const double a,
                                    const double b,
                                    const double hh)
      {
        std::vector<Eigen::Vector3d> points;
        for (int k = 0; k < 16; ++k)
          {
            const double t = 2. * M_PI * k / 16.;
            for (const double z : {-hh, 0., hh})
              points.emplace_back(a * std::cos(t), b * std::sin(t), z);
          }
        points.emplace_back(0., 0., hh);
        points.emplace_back(0., 0., -hh);
        return points;
      }

    } // namespace detail
  }   // namespace geometry
} // namespace particulate

#endif
