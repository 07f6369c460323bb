#include <particulate/deformation/surface_resolution.h>
#include <particulate/fbm/particle_shape.h>
#include <particulate/fbm/surface_resolution_report.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace fbm {
    namespace {
      struct MeasuredBody
      {
        unsigned int                   id;
        deformation::SurfaceResolution resolution;
      };

      void
      write_table(const std::vector<MeasuredBody>        &measured,
                  const std::vector<ParticleDescription> &bodies,
                  const std::string                      &name)
      {
        std::ofstream out(name);
        out << "# How the flow mesh sees each surface-mesh body where it "
               "starts: its solid cells\n"
               "# (centre inside), the Hausdorff distance between their "
               "boundary faces and the surface,\n"
               "# the faces' mean distance from it, and the solid cells' "
               "volume over the body's, less one\n"
               "# id shape solid_cells hausdorff[m] mean_face_distance[m] "
               "volume_error\n"
            << std::setprecision(8);
        for (const MeasuredBody &m : measured)
          out << m.id << ' ' << bodies[m.id].shape_name << ' '
              << m.resolution.solid_cells << ' ' << m.resolution.hausdorff
              << ' ' << m.resolution.mean_face_distance << ' '
              << m.resolution.volume_error << '\n';
        if (!out)
          throw std::runtime_error("cannot write '" + name
                                   + "'; is the output folder writable?");
      }

      /** One line per body for the log, the first few of many. */
      std::string
      log_lines(const std::vector<MeasuredBody>        &measured,
                const std::vector<ParticleDescription> &bodies)
      {
        constexpr std::size_t shown = 4;
        std::ostringstream    out;
        out << "Surface resolution (the cells whose centre a body holds; "
               "surface_resolution.dat):\n"
            << std::setprecision(3);
        for (std::size_t i = 0; i < std::min(shown, measured.size()); ++i)
          {
            const auto &r = measured[i].resolution;
            out << "  body " << measured[i].id << " ("
                << bodies[measured[i].id].shape_name << "): ";
            if (r.solid_cells == 0)
              out << "holds no cell centre: thinner than the cells there\n";
            else
              out << r.solid_cells << " solid cells, Hausdorff distance "
                  << r.hausdorff << " m, mean face distance "
                  << r.mean_face_distance << " m, volume " << std::showpos
                  << 100. * r.volume_error << std::noshowpos << " %\n";
          }
        if (measured.size() > shown)
          out << "  ... and " << measured.size() - shown << " more\n";
        return out.str();
      }
    } // namespace



    template <int dim>
    std::string
    report_surface_resolution(const dealii::Triangulation<dim>       &tria,
                              const std::vector<ParticleDescription> &bodies,
                              const std::vector<geometry::Pose>      &poses,
                              const std::string                      &directory,
                              MPI_Comm communicator)
    {
      std::vector<MeasuredBody> measured;
      if constexpr (dim == 3)
        for (unsigned int i = 0; i < bodies.size(); ++i)
          if (is_surface_mesh(*bodies[i].shape))
            measured.push_back(
              {i,
               deformation::measure_surface_resolution(tria,
                                                       *bodies[i].shape,
                                                       poses[i],
                                                       communicator)});
      if (measured.empty())
        return "";
      if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
        write_table(measured, bodies, directory + "/surface_resolution.dat");
      return log_lines(measured, bodies);
    }

    template std::string
    report_surface_resolution<2>(const dealii::Triangulation<2> &,
                                 const std::vector<ParticleDescription> &,
                                 const std::vector<geometry::Pose> &,
                                 const std::string &,
                                 MPI_Comm);
    template std::string
    report_surface_resolution<3>(const dealii::Triangulation<3> &,
                                 const std::vector<ParticleDescription> &,
                                 const std::vector<geometry::Pose> &,
                                 const std::string &,
                                 MPI_Comm);
  } // namespace fbm
} // namespace particulate
