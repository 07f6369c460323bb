#ifndef particulate_geometry_mass_properties_h
#define particulate_geometry_mass_properties_h

#include <particulate/geometry/pose.h>
#include <particulate/geometry/triangle_mesh.h>

#include <Eigen/Core>

namespace particulate {
  namespace geometry {

    /**
     * Volume, centre of mass and inertia tensor of a homogeneous solid (thesis
     * §4.2.2, eqs. 4.24-4.29). The inertia is given for unit density, about the
     * centre of mass, in the frame of the coordinates it was computed in;
     * multiply by the density [kg/m^3] to get kg m^2.
     */
    struct MassProperties
    {
      /** Volume [m^3]. */
      double volume = 0.;
      /** Centre of mass (centroid of the homogeneous solid) [m]. */
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      /** Inertia tensor about the centre for unit density [m^5]: diagonal
       *  I_xx = int (y^2 + z^2) dV, off-diagonal -int x y dV (eq. 4.28). */
      Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();

      /** Mass [kg] for density @p density [kg/m^3]. */
      double
      mass(const double density) const
      {
        return density * volume;
      }

      /**
       * The properties of the same solid moved by @p pose: the centre moves
       * with the pose, the tensor rotates as R I R^T (eq. 4.30), the volume
       * stays.
       */
      MassProperties
      transformed(const Pose &pose) const;

      /** Inertia tensor about the point @p p instead of the centre
       *  (parallel-axis theorem), unit density [m^5]. */
      Eigen::Matrix3d
      inertia_about(const Eigen::Vector3d &p) const;

      /**
       * The principal frame (§4.2.1): a pose whose translation is the centre
       * and whose rotation has the principal axes as columns (right-handed),
       * sorted by increasing principal moment.
       * @param moments if not null, receives the principal moments [m^5]
       */
      Pose
      principal_frame(Eigen::Vector3d *moments = nullptr) const;
    };

    /**
     * Exact mass properties of the solid bounded by a closed, outward-oriented
     * triangle mesh, by the divergence theorem: the solid is the signed sum of
     * the tetrahedra spanned by each triangle and a reference point, and the
     * polynomial moments of each tetrahedron are known in closed form. Exact up
     * to rounding for the polyhedron the mesh describes (no quadrature error).
     *
     * @param mesh closed surface, outward oriented (as read_surface_mesh gives)
     * @throw GeometryError if the enclosed volume is not positive (inward
     *   orientation or an empty or open mesh)
     */
    MassProperties
    compute_mass_properties(const TriangleMesh &mesh);

  } // namespace geometry
} // namespace particulate

#endif
