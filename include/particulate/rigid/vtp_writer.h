#ifndef particulate_rigid_vtp_writer_h
#define particulate_rigid_vtp_writer_h

#include <particulate/rigid/pvd_series.h>
#include <particulate/rigid/world.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace particulate {
  namespace rigid {
    /**
     * ParaView output of the bodies as glyph points: one VTK PolyData file
     * (`<prefix>_NNNNN.vtp`, plain ASCII XML) per call with a point per bounded
     * body and the point data id, radius (bounding radius, m), velocity (m/s),
     * angular_velocity (rad/s), orientation (quaternion w x y z) and fixed
     * (0/1), plus the series file `<prefix>.pvd` that maps physical time to
     * files (rewritten after each call, so it is valid at any moment).
     * In ParaView: Glyph filter, sphere glyph, scale by "radius".
     */
    class VtpWriter
    {
    public:
      /** @param prefix Path prefix, e.g. "output/bodies". */
      explicit VtpWriter(std::string prefix);

      /** Writes the current state; returns the file name. */
      std::string
      write(const World &world);

      /** Leave out the bodies from @p id on (the walls a case adds after
       *  its particles); by default every bounded body is written. */
      void
      leave_out_from(const BodyId id)
      {
        first_left_out = id;
      }

      /** The series written so far (time, file), for a checkpoint. */
      const std::vector<std::pair<double, std::string>> &
      written() const
      {
        return series.written();
      }
      /** Continues the series of a restarted run: the files listed in the
       * checkpoint; files written after it are left out of the next .pvd. */
      void
      resume(std::vector<std::pair<double, std::string>> written)
      {
        series.resume(std::move(written));
      }

    private:
      PvdSeries series;
      BodyId    first_left_out = std::numeric_limits<BodyId>::max();
    };
  } // namespace rigid
} // namespace particulate

#endif
