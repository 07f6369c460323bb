#ifndef particulate_fbm_surface_resolution_report_h
#define particulate_fbm_surface_resolution_report_h

#include <particulate/fbm/particle_description.h>
#include <particulate/geometry/pose.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * How the flow mesh of a 3D run sees each body read from a surface mesh,
     * where the bodies start (thesis §6.6; deformation::SurfaceResolution:
     * the Hausdorff distance between the surface and the faces of the cells
     * whose centres it holds, their mean distance, the volume error). Rank 0
     * writes one row per such body to @p directory/surface_resolution.dat.
     * Collective over @p communicator; nothing is measured in 2D or without
     * surface-mesh bodies.
     *
     * @return the lines for the run's log (empty when nothing was measured)
     */
    template <int dim>
    std::string
    report_surface_resolution(const dealii::Triangulation<dim>       &tria,
                              const std::vector<ParticleDescription> &bodies,
                              const std::vector<geometry::Pose>      &poses,
                              const std::string                      &directory,
                              MPI_Comm communicator);
  } // namespace fbm
} // namespace particulate

#endif
