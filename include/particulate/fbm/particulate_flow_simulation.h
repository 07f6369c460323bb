#ifndef particulate_fbm_particulate_flow_simulation_h
#define particulate_fbm_particulate_flow_simulation_h

#include <particulate/core/checkpoint.h>
#include <particulate/deformation/deformation_parameters.h>
#include <particulate/fbm/particle_parameters.h>
#include <particulate/fluid/flow_simulation.h>
#include <particulate/fluid/run_profile.h>

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <mpi.h>

namespace particulate {
  namespace fluid {
    template <int dim>
    class NavierStokes;
  }
  namespace fbm {
    /** Everything a `Simulation / Type = particulate flow` case reads. */
    struct ParticulateFlowParameters
    {
      fluid::FlowCaseParameters flow;
      ParticleParameters        particles;
      /// r-adaptivity of the flow mesh to the particles
      deformation::DeformationParameters deformation;
      core::CheckpointParameters         checkpoint;
      /// continue from the checkpoint in the output folder (--restart)
      bool restart = false;

      /** Declare every entry a case file may set. */
      static void
      declare(dealii::ParameterHandler &prm);

      /** Read the entries of the already parsed @p prm; @p filename names
       *  the case in messages and locates its mesh files. */
      void
      parse(dealii::ParameterHandler &prm, const std::string &filename);
    };

    /**
     * Read the case file @p filename, then apply @p overrides (.prm text,
     * e.g. "subsection Mesh\n set Refinements = 3\nend\n"): how tests and
     * studies vary a library case without copying it.
     */
    ParticulateFlowParameters
    read_particulate_flow_case(const std::string &filename,
                               const std::string &overrides = "");

    /** What a run measured; used by tests and the final summary (and, by
     *  its RunProfile, the benchmarks). */
    struct ParticulateFlowSummary : fluid::RunProfile
    {
      unsigned int  n_steps  = 0;
      double        end_time = 0.;
      unsigned long n_dofs   = 0;
      /// per particle, at the end
      std::vector<Eigen::Vector3d> position, velocity, force, torque;
      /// per particle, the largest speed reached and when [m/s, s]
      std::vector<double> max_speed, time_of_max_speed;
      double              wall_seconds = 0.;
      /// wall seconds of each time step this run computed (its "coupled
      /// step (total)" section, the slowest rank's); benchmarks separate
      /// the first steps, which carry one-time set-ups, from the rest
      std::vector<double> step_seconds;
    };

    /**
     * The coupled time loop of the fictitious boundary method (thesis
     * §5.3): per time step t_n -> t_n+1
     *  1. mark the velocity nodes inside the particles at t_n and impose
     *     u = U + omega x (x - X) there (eq. 5.17);
     *  2. advance the fluid (fractional-step theta, eq. 5.14);
     *  3. hydrodynamic force and torque by the volume integrals (eq. 5.13);
     *  4. advance the rigid bodies with the fluid loads, buoyancy-corrected
     *     gravity and contacts (eq. 5.3) in the rigid-body engine, where the
     *     domain walls are fixed half-spaces.
     * The explicit coupling is stabilised for light particles by an
     * added-mass correction (doc/fbm.md).
     *
     * With subsection `Mesh deformation` the mesh is adapted to the
     * particles (BodyAdaptedMesh) before the run, and when they move, at
     * the start of every step, its velocity entering the flow's ALE term;
     * `<output>/mesh.dat` logs the mesh quality. Prescribed particles
     * (`Motion = prescribed`) are moved to t_n+1 first, so the fluid step
     * sees them where they end it.
     *
     * With subsection `Checkpoint` set, the run saves its state (fluid
     * solution, bodies with their contact cache, the coupling's added-mass
     * accelerations and loads, time step, output series) into
     * `<output>/checkpoint/`; with `restart` it continues from there and
     * computes the same numbers as the uninterrupted run.
     */
    template <int dim>
    class ParticulateFlowSimulation
    {
    public:
      ParticulateFlowSimulation(const ParticulateFlowParameters &parameters,
                                const std::string               &parameter_file,
                                MPI_Comm                         comm);

      ParticulateFlowSummary
      run();

      /**
       * @p inspector sees the flow solver at the end of run() (on every
       * rank; benchmarks time its matrix there).
       */
      void
      set_flow_inspector(
        std::function<void(const fluid::NavierStokes<dim> &)> inspector)
      {
        flow_inspector = std::move(inspector);
      }

    private:
      std::function<void(const fluid::NavierStokes<dim> &)> flow_inspector;
      const ParticulateFlowParameters                      &parameters;
      const std::string                                     parameter_file;
      MPI_Comm                                              communicator;
    };
  } // namespace fbm
} // namespace particulate

#endif
