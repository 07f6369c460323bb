#ifndef particulate_rigid_body_surface_writer_h
#define particulate_rigid_body_surface_writer_h

#include <particulate/geometry/triangle_mesh.h>
#include <particulate/rigid/pvd_series.h>
#include <particulate/rigid/world.h>

#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace particulate {
  namespace rigid {
    /**
     * ParaView output of the bodies as their surfaces: one VTK PolyData file
     * (`<prefix>_NNNNN.vtp`, plain ASCII XML) per call with the display
     * triangulation of every bounded body (geometry::Shape::surface_mesh(),
     * built once per shape) placed at the body's pose, the point data
     * velocity (the rigid motion's velocity at the point, v + omega x r, m/s)
     * and the cell data id and fixed (0/1); plus the series file
     * `<prefix>.pvd`. Opens in ParaView as it is, any shape.
     */
    class BodySurfaceWriter
    {
    public:
      /** @param prefix Path prefix, e.g. "output/particle_surfaces". */
      explicit BodySurfaceWriter(std::string prefix);

      /** Writes the current state; returns the file name. */
      std::string
      write(const World &world);

      /** The series written so far (time, file), for a checkpoint. */
      const std::vector<std::pair<double, std::string>> &
      written() const
      {
        return series.written();
      }

      /** Continues the series of a restarted run (see PvdSeries::resume()). */
      void
      resume(std::vector<std::pair<double, std::string>> written)
      {
        series.resume(std::move(written));
      }

    private:
      /** The display triangulation of @p body's shape (body frame), built on
       *  first use. */
      const geometry::TriangleMesh &
      display_mesh(const RigidBody &body);

      PvdSeries series;
      std::unordered_map<const geometry::Shape *,
                         std::pair<std::shared_ptr<const geometry::Shape>,
                                   geometry::TriangleMesh>>
        meshes;
    };
  } // namespace rigid
} // namespace particulate

#endif
