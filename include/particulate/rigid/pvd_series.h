#ifndef particulate_rigid_pvd_series_h
#define particulate_rigid_pvd_series_h

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace particulate {
  namespace rigid {
    /**
     * A ParaView time series of numbered files: the piece names
     * `<prefix>_NNNNN.<extension>` and the collection `<prefix>.pvd` that maps
     * physical time to them, valid at any moment: each piece's entry is
     * appended in place of the closing tags (the whole file is rewritten
     * only when it is not as this object left it, e.g. after a restart).
     */
    class PvdSeries
    {
    public:
      /** @param prefix Path prefix, e.g. "output/particles". */
      explicit PvdSeries(std::string prefix);

      /** The name of the next piece: `<prefix>_NNNNN.<extension>`. */
      std::string
      next_file(const std::string &extension) const;

      /** Record the piece @p file at @p time in the `.pvd`. */
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
        series     = std::move(written);
        file_bytes = 0;
      }

    private:
      /** Append the last entry to the `.pvd` as written before; false
       *  where that file is not as this object left it. */
      bool
      append_last_entry();

      /** Write the whole `.pvd`. */
      void
      rewrite();

      std::string                                 prefix;
      std::vector<std::pair<double, std::string>> series;
      /// size of the `.pvd` as this object last wrote it (0: not yet)
      std::uintmax_t file_bytes = 0;
    };
  } // namespace rigid
} // namespace particulate

#endif
