#ifndef particulate_fluid_flow_output_h
#define particulate_fluid_flow_output_h

#include <particulate/fluid/navier_stokes.h>

#include <string>
#include <utility>
#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * ParaView output of the flow: one `.vtu` per rank and a `.pvtu` per
     * output step, collected in `flow.pvd` with the physical time. Written
     * fields: velocity (vector), pressure, vorticity (scalar in 2D, vector in
     * 3D), for a viscosity that depends on the shear rate the shear rate
     * sqrt(2 D:D) and the viscosity, and the owning MPI rank. The `.pvd` is
     * rewritten after every step, so an interrupted run leaves a valid series.
     */
    template <int dim>
    class FlowOutput
    {
    public:
      FlowOutput(const std::string &directory, const std::string &basename);

      void
      write(const NavierStokes<dim> &flow,
            const unsigned int       step,
            const double             time);

      /** The series written so far (time, file), for a checkpoint. */
      const std::vector<std::pair<double, std::string>> &
      written() const
      {
        return records;
      }
      /** Continues the series of a restarted run: the files listed in the
       * checkpoint; files written after it are left out of the next .pvd. */
      void
      resume(std::vector<std::pair<double, std::string>> series)
      {
        records = std::move(series);
      }

    private:
      std::string                                 directory, basename;
      std::vector<std::pair<double, std::string>> records;
    };
  } // namespace fluid
} // namespace particulate

#endif
