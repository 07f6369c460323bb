#ifndef particulate_rigid_pvd_series_h
#define particulate_rigid_pvd_series_h

#include <string>
#include <utility>
#include <vector>

namespace particulate {
  namespace rigid {
    /**
     * A ParaView time series of numbered files: the piece names
     * `<prefix>_NNNNN.<extension>` and the collection `<prefix>.pvd` that maps
     * physical time to them, rewritten after each piece so that it is valid at
     * any moment.
     */
    class PvdSeries
    {
    public:
      /** @param prefix Path prefix, e.g. "output/particles". */
      explicit PvdSeries(std::string prefix);

      /** The name of the next piece: `<prefix>_NNNNN.<extension>`. */
      std::string
      next_file(const std::string &extension) const;

      /** Record the piece @p file at @p time and rewrite the `.pvd`. */
      void
      add(const double time, const std::string &file);

      /** The series written so far (time, file relative to the `.pvd`), for a
       *  checkpoint. */
      const std::vector<std::pair<double, std::string>> &
      written() const
      {
        return series;
      }

      /** Continues the series of a restarted run: the files listed in the
       *  checkpoint; files written after it are left out of the next .pvd. */
      void
      resume(std::vector<std::pair<double, std::string>> written)
      {
        series = std::move(written);
      }

    private:
      std::string                                 prefix;
      std::vector<std::pair<double, std::string>> series;
    };
  } // namespace rigid
} // namespace particulate

#endif
