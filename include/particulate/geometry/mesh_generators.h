#ifndef particulate_geometry_mesh_generators_h
#define particulate_geometry_mesh_generators_h

#include <particulate/geometry/triangle_mesh.h>

namespace particulate {
  namespace geometry {

    /**
     * Closed, outward-oriented triangulations of simple solids, generated in
     * code for tests with exact answers (volumes, inertia, distances).
     */
    namespace mesh_generators {

      /**
       * A sphere of radius @p radius [m] centred at the origin: an icosahedron
       * whose triangles are split into four @p refinements times, with the new
       * vertices projected onto the sphere (20 * 4^refinements triangles).
       */
      TriangleMesh
      icosphere(const double radius, const unsigned int refinements);

      /**
       * The box [-h, h] with half extents @p half_extents [m], each face split
       * into n x n squares of two triangles (n = @p subdivisions >= 1).
       */
      TriangleMesh
      box(const Eigen::Vector3d &half_extents,
          const unsigned int     subdivisions = 1);

      /**
       * A torus around the z axis: distance @p major_radius from the axis to
       * the tube centre, tube radius @p minor_radius [m], with @p n_major x
       * @p n_minor quadrilaterals split into triangles.
       */
      TriangleMesh
      torus(const double       major_radius,
            const double       minor_radius,
            const unsigned int n_major,
            const unsigned int n_minor);

      /**
       * A prism along z over the ellipse of semi-axes @p semi_axis_x,
       * @p semi_axis_y [m] (a circular cylinder when they are equal), from
       * z = -@p half_height to @p half_height: @p n_around quadrilaterals
       * around the side, split into triangles, and two fans for the caps.
       */
      TriangleMesh
      elliptic_prism(const double       semi_axis_x,
                     const double       semi_axis_y,
                     const double       half_height,
                     const unsigned int n_around);

      /**
       * A capsule along z: the segment from z = -@p half_length to
       * @p half_length swept by a ball of radius @p radius [m]. Latitude rings
       * of @p n_around vertices, @p n_around / 2 of them over each hemisphere
       * (the equators doubled, joined by the cylindrical side), and fans at
       * the poles.
       */
      TriangleMesh
      capsule(const double       radius,
              const double       half_length,
              const unsigned int n_around);

    } // namespace mesh_generators
  }   // namespace geometry
} // namespace particulate

#endif
