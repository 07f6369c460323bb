#ifndef particulate_fbm_rigid_bodies_simulation_h
#define particulate_fbm_rigid_bodies_simulation_h

#include <particulate/fbm/particulate_flow_simulation.h>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

#include <mpi.h>

namespace particulate {
  namespace fbm {
    /** What a rigid-bodies run measured (tests, the closing lines). */
    struct RigidBodiesSummary
    {
      unsigned int n_steps  = 0;
      double       end_time = 0.;
      /// per particle, at the end
      std::vector<Eigen::Vector3d> position, velocity;
      /// the deepest contact overlap of any step, against the contact
      /// distance [m]
      double max_penetration = 0.;
      /// the kinetic energy of the particles at the end [J]
      double kinetic_energy = 0.;
      /// wall seconds of the whole run and of each step's engine work
      double              wall_seconds = 0.;
      std::vector<double> step_seconds;
    };

    /**
     * `Simulation / Type = rigid bodies`: the particles of a case under
     * gravity and contacts alone, without a fluid. The set-up is the one a
     * particulate flow run of the same file makes (the mesh's box and its
     * walls, the contact distance, fixed and prescribed bodies, locked
     * axes), so that a case can be tried dry and then in the fluid by
     * changing one entry; the fluid's entries and the mesh deformation are
     * not used, and the time step is the fixed 'Time step'. Particles weigh
     * rho_p V g (no buoyancy, no added mass).
     *
     * It writes what a particulate flow run writes about the bodies
     * (ParticulateFlowOutput): `particle_<i>.dat` with zero fluid loads,
     * `flow.dat` with the particles' kinetic energy and the deepest
     * overlap, `particle_set.csv`, and the ParaView series of the bodies;
     * no flow fields. Every rank steps the same engine; rank 0 writes.
     */
    template <int dim>
    class RigidBodiesSimulation
    {
    public:
      RigidBodiesSimulation(const ParticulateFlowParameters &parameters,
                            const std::string               &parameter_file,
                            MPI_Comm                         comm);
      ~RigidBodiesSimulation();

      /** Set up, step to the end time, write the output. */
      RigidBodiesSummary
      run();

    private:
      struct Run;

      void
      set_up();
      void
      say_what_is_not_used() const;
      /** One step of the engine by @p k, checked (BodyStateGuard). */
      void
      advance(const double k);
      /** Prescribed bodies to their pose and velocity at @p t_new. */
      void
      move_prescribed_bodies(const double t_new);
      void
      record(const double k);
      void
      write_fields();
      /** The summary of the run, which took @p wall_seconds, and its
       *  closing line. */
      RigidBodiesSummary
      summarise(const double wall_seconds);

      const ParticulateFlowParameters parameters;
      const std::string               parameter_file;
      MPI_Comm                        communicator;
      std::unique_ptr<Run>            run_;
    };
  } // namespace fbm
} // namespace particulate

#endif
