#ifndef particulate_deformation_surface_resolution_h
#define particulate_deformation_surface_resolution_h

#include <particulate/geometry/pose.h>
#include <particulate/geometry/shape.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>

namespace particulate {
  namespace deformation {
    /**
     * How well the cells of a mesh see a body (thesis §6.6): the body as the
     * mesh resolves it is the set of its "solid" cells, those whose centre
     * lies inside the surface, and its boundary the faces between a solid
     * cell and a fluid one (or the domain's boundary). Those faces are
     * compared with the true surface.
     */
    struct SurfaceResolution
    {
      /** Solid cells, over all ranks. */
      unsigned long long solid_cells = 0;
      /**
       * [m] The Hausdorff distance between the solid cells' boundary and the
       * surface: the larger of the farthest face point from the surface and
       * the farthest surface point from the faces. The face points are the
       * faces' vertices and centres, the surface points the vertices and
       * centroids of the shape's surface triangles.
       */
      double hausdorff = 0.;
      /** [m] The mean distance of the face points from the surface. */
      double mean_face_distance = 0.;
      /** The solid cells' volume over the body's, less one. */
      double volume_error = 0.;
    };

    /**
     * Measure how the locally owned cells of @p tria, together on all ranks
     * of @p communicator, see @p shape placed at @p pose (every rank gets
     * the result). Distances come from Shape::signed_distance (a surface
     * mesh's distance map), the surface points from Shape::surface_mesh().
     * A body that covers no cell centre has a Hausdorff distance of its
     * surface points from the faces of an infinite distance.
     */
    SurfaceResolution
    measure_surface_resolution(const dealii::Triangulation<3> &tria,
                               const geometry::Shape          &shape,
                               const geometry::Pose           &pose,
                               MPI_Comm communicator = MPI_COMM_SELF);
  } // namespace deformation
} // namespace particulate

#endif
