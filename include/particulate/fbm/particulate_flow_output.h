#ifndef particulate_fbm_particulate_flow_output_h
#define particulate_fbm_particulate_flow_output_h

#include <particulate/core/simulation_parameters.h>
#include <particulate/core/time_series_writer.h>
#include <particulate/deformation/moving_mesh.h>
#include <particulate/fbm/hydrodynamic_load.h>
#include <particulate/fbm/particle_description.h>
#include <particulate/fluid/flow_output.h>
#include <particulate/fluid/navier_stokes.h>
#include <particulate/rigid/body_surface_writer.h>
#include <particulate/rigid/vtp_writer.h>
#include <particulate/rigid/world.h>

#include <iosfwd>
#include <memory>
#include <vector>

#include <mpi.h>

namespace particulate {
  namespace fbm {
    /** One body's row of `particle_<i>.dat`. */
    struct BodyRecord
    {
      const rigid::RigidBody *body = nullptr;
      HydrodynamicLoad        load;
      /// the sum of the contact forces on the body over the step [N]
      Eigen::Vector3d contact_force = Eigen::Vector3d::Zero();
      /// with the true mass and inertia [J]
      double        kinetic_energy = 0.;
      unsigned long nodes_inside   = 0;
    };

    /**
     * What a particulate-flow run writes into its output folder: the time
     * series `particle_<i>.dat` (one per body: pose, velocities, loads,
     * contact force, kinetic energy, covered nodes; with many particles, or
     * 'Particle files = shared', one `particles.dat` with a row per body
     * and its number in the column id), `particle_set.csv`
     * (what each particle is), `flow.dat` (kinetic
     * energies, iteration counts, time step, deepest contact overlap) and, on
     * an adapted mesh, `mesh.dat` (its quality); and the ParaView series
     * `flow.pvd`, `particles.pvd` (a point per body with its state, for glyphs)
     * and the bodies' surfaces, any shape: each body's own series
     * `particle_surfaces/body_<i>.pvd` and all of them in
     * `particle_surfaces.pvd` (rigid::BodySurfaceWriter; shared files: one
     * piece of all surfaces per output step, in `particle_surfaces.pvd`).
     *
     * A restart continues every series: the ParaView files listed in the
     * checkpoint (save(), load()), and the `.dat` files without the rows
     * that the cut-off run wrote after its checkpoint.
     */
    template <int dim>
    class ParticulateFlowOutput
    {
    public:
      /** Nothing is written yet. */
      ParticulateFlowOutput(const core::OutputParameters &parameters,
                            MPI_Comm                      comm);

      /**
       * Open the `.dat` series for @p n_bodies bodies (and `mesh.dat` with
       * @p adapted_mesh); with @p restart continue them from time
       * @p time, dropping later rows.
       */
      void
      open_time_series(const unsigned int n_bodies,
                       const bool         adapted_mesh,
                       const bool         restart,
                       const double       time);

      /**
       * The table `particle_set.csv` of the particles as the case file
       * made them (lattices and random fills expanded): per particle its
       * number (the i of `particle_<i>.dat`), shape name, motion, density,
       * volume and mass (per unit depth in 2D), and initial centre.
       */
      void
      write_particle_table(const std::vector<ParticleDescription> &particles);

      /** A row of `mesh.dat` (nothing without an adapted mesh). */
      void
      record_mesh(const double                          time,
                  const deformation::DeformationReport &report);

      /** A row of each `particle_<i>.dat` (shared files: a row per body
       *  of `particles.dat`), one record per body. */
      void
      record_bodies(const double time, const std::vector<BodyRecord> &bodies);

      /** A row of `flow.dat`; @p max_penetration: the rigid world's
       *  deepest contact overlap of the shapes inflated by the contact
       *  distance [m] (0 apart). */
      void
      record_flow(const double                  time,
                  const double                  fluid_kinetic_energy,
                  const double                  particle_kinetic_energy,
                  const fluid::SolveStatistics &statistics,
                  const double                  time_step,
                  const double                  max_penetration);

      /** The fields at @p step, @p time, if the case writes them. */
      void
      write_fields(const fluid::NavierStokes<dim> &flow,
                   const rigid::World             &world,
                   const unsigned int              step,
                   const double                    time);

      /** The bodies alone, at the engine's time, if the case writes
       *  fields (a run without a fluid). */
      void
      write_bodies(const rigid::World &world);

      /** Ends every `.dat` series with a comment line saying that the run
       *  stopped after @p time and why (@p reason). */
      void
      note_stop(const double time, const std::string &reason);

      /** The ParaView series written so far, for a checkpoint. */
      void
      save(std::ostream &out) const;

      /** Continue the ParaView series that save() wrote. */
      void
      load(std::istream &in);

      const std::string &
      directory() const
      {
        return parameters.directory;
      }

    private:
      /** The series `<name>.dat` with @p columns; on a restart the
       *  existing file, cut at @p time and continued. */
      std::unique_ptr<core::TimeSeriesWriter>
      open_series(const std::string              &name,
                  const std::vector<std::string> &columns,
                  const bool                      restart,
                  const double                    time) const;

      const core::OutputParameters parameters;
      MPI_Comm                     communicator;
      fluid::FlowOutput<dim>       flow_output;
      rigid::VtpWriter             body_output;
      rigid::BodySurfaceWriter     surface_output;
      /// particles.dat and one surface file per output instead of files
      /// per particle ('Particle files')
      bool                                                 shared_files = false;
      std::vector<std::unique_ptr<core::TimeSeriesWriter>> body_series;
      std::unique_ptr<core::TimeSeriesWriter>              mesh_series;
      std::unique_ptr<core::TimeSeriesWriter>              flow_series;
    };
  } // namespace fbm
} // namespace particulate

#endif
