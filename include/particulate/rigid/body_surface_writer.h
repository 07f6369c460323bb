#ifndef particulate_rigid_body_surface_writer_h
#define particulate_rigid_body_surface_writer_h

#include <particulate/geometry/triangle_mesh.h>
#include <particulate/rigid/pvd_series.h>
#include <particulate/rigid/world.h>

#include <limits>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace particulate {
  namespace rigid {
    /**
     * ParaView output of the bodies as their surfaces, each body its own
     * series: per call, the display triangulation of every bounded body
     * (geometry::Shape::surface_mesh(), built once per shape) placed at its
     * pose, with the point data velocity (the rigid motion's velocity at the
     * point, v + omega x r, m/s) and the cell data id and fixed (0/1), as
     * `<prefix>/body_<id>_NNNNN.vtp` (plain ASCII XML) in the series
     * `<prefix>/body_<id>.pvd`; and a multiblock file `<prefix>_NNNNN.vtm`
     * naming every body's piece as a block "body <id>", in the series
     * `<prefix>.pvd`: all bodies at once, each selectable. Opens in ParaView
     * as it is, any shape.
     *
     * With many bodies, Layout::one_file writes all surfaces into one piece
     * `<prefix>_NNNNN.vtp` per call instead (the cell data id tells them
     * apart), in the series `<prefix>.pvd`: the number of files does not
     * grow with the bodies.
     */
    class BodySurfaceWriter
    {
    public:
      /** Files per call: one per body, each in its own series, or one. */
      enum class Layout
      {
        each_body,
        one_file
      };

      /** One body's surface in the world frame and its velocity there. */
      struct PlacedSurface
      {
        BodyId                        id;
        bool                          fixed;
        std::vector<Eigen::Vector3d>  points;
        std::vector<Eigen::Vector3d>  velocities;
        const geometry::TriangleMesh *mesh;
      };

      /** @param prefix Path prefix, e.g. "output/particle_surfaces". */
      explicit BodySurfaceWriter(std::string  prefix,
                                 const Layout layout = Layout::each_body);

      /** Writes the current state; returns the name of the file that holds
       *  all bodies (the multiblock file, or the one piece). */
      std::string
      write(const World &world);

      /** Choose the files of the calls to come (before the first). */
      void
      set_layout(const Layout l)
      {
        layout = l;
      }

      /** Leave out the bodies from @p id on (the walls a case adds after
       *  its particles); by default every bounded body is written. */
      void
      leave_out_from(const BodyId id)
      {
        first_left_out = id;
      }

      /** The series of all bodies written so far (time, multiblock file),
       *  for a checkpoint. */
      const std::vector<std::pair<double, std::string>> &
      written() const
      {
        return series.written();
      }

      /** Continues the series of a restarted run (see PvdSeries::resume()):
       *  the bodies' own series are continued from it as they are written
       *  next. */
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

      /** The series of body @p id, made (with its folder) on first use. */
      PvdSeries &
      body_series(const BodyId id);

      /** `body_<id>_NNNNN.vtp` of snapshot @p snapshot. */
      static std::string
      piece_name(const BodyId id, const std::size_t snapshot);

      /** Layout::each_body: a piece per body and the multiblock file. */
      std::string
      write_each_body(const World &world);

      /** Layout::one_file: one piece with every body. */
      std::string
      write_one_file(const World &world);

      /** The @p surfaces as the PolyData file @p name. */
      static void
      write_piece(const std::string                &name,
                  const std::vector<PlacedSurface> &surfaces);

      const std::string prefix;
      PvdSeries         series;
      Layout            layout;
      BodyId            first_left_out = std::numeric_limits<BodyId>::max();
      std::map<BodyId, PvdSeries> bodies;
      std::unordered_map<const geometry::Shape *,
                         std::pair<std::shared_ptr<const geometry::Shape>,
                                   geometry::TriangleMesh>>
        meshes;
    };
  } // namespace rigid
} // namespace particulate

#endif
