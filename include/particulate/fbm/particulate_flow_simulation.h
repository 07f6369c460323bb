#ifndef particulate_fbm_particulate_flow_simulation_h
#define particulate_fbm_particulate_flow_simulation_h

#include <particulate/core/checkpoint.h>
#include <particulate/deformation/deformation_parameters.h>
#include <particulate/fbm/body_coupling_state.h>
#include <particulate/fbm/particle_parameters.h>
#include <particulate/fbm/solver_failure_diagnosis.h>
#include <particulate/fluid/flow_simulation.h>
#include <particulate/fluid/run_profile.h>

#include <deal.II/base/types.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

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
  namespace rigid {
    class World;
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

      /** Declare every entry a case file may set, with the particle list
       *  subsections of @p layout (ParticleSetLayout::of() the case file,
       *  or ParticleSetLayout::documentation()). */
      static void
      declare(dealii::ParameterHandler &prm, const ParticleSetLayout &layout);

      /** Read the entries of the already parsed @p prm; @p outline is the
       *  case file: it names the case, the file and line in messages, and
       *  locates its mesh and particle files. */
      void
      parse(dealii::ParameterHandler &prm, const core::InputOutline &outline);
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
      /// wall seconds of each time step this run computed (its "coupled
      /// step (total)" section, the slowest rank's); benchmarks separate
      /// the first steps, which carry one-time set-ups, from the rest
      std::vector<double> step_seconds;
    };

    /**
     * The coupled time loop of the fictitious boundary method (thesis
     * §5.3). run() is set_up() and then, per time step t_n -> t_n+1, the
     * stages
     *  1. move_mesh(): prescribed bodies to t_n+1, hinged parts on their
     *     parents with the hinge at t_n+1; the adapted mesh follows
     *     the bodies to the poses at which stage 2 marks them (free bodies
     *     at their predicted midpoint), its velocity entering the flow's
     *     ALE term;
     *  2. impose_interface(): mark the velocity nodes inside the bodies and
     *     impose u = U + omega x (x - X) there (eq. 5.17);
     *  3. advance_fluid(): fractional-step theta (eq. 5.14);
     *  4. compute_loads(): hydrodynamic force and torque by the volume
     *     integrals (eq. 5.13);
     *  5. advance_bodies(): the rigid engine moves the bodies with the
     *     fluid loads, buoyancy-corrected gravity and contacts (eq. 5.3;
     *     RigidBodyUpdate), the domain walls being fixed half-spaces, and
     *     BodyStateGuard stops the run if a body went wrong; bodies that do
     *     not move before a step are marked at t_n+1;
     *     with `Coupling = iterated`, stages 2 to 5 are repeated from the
     *     step's start until the velocities the fluid was given are those
     *     the free bodies reach (iterate_coupled_step(), CouplingIteration);
     *  6. write_output(): the time series, the ParaView output and the
     *     progress line;
     *  7. write_checkpoint() when one is due.
     * The stages are public so that a test can drive a step stage by
     * stage.
     *
     * With subsection `Mesh deformation` the mesh is adapted to the bodies
     * (BodyAdaptedMesh) before the run, and when they move, at the start of
     * every step; `<output>/mesh.dat` logs the mesh quality. With
     * subsection `Checkpoint` set, the run saves its state (fluid solution,
     * bodies with their contact cache, each body's BodyCouplingState, time
     * step, output series) into `<output>/checkpoint/`; with `restart` it
     * continues from there and computes the same numbers as the
     * uninterrupted run.
     */
    template <int dim>
    class ParticulateFlowSimulation
    {
    public:
      ParticulateFlowSimulation(const ParticulateFlowParameters &parameters,
                                const std::string               &parameter_file,
                                MPI_Comm                         comm);
      ~ParticulateFlowSimulation();

      /** set_up(), every step's stages, and the summary. */
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

      /** @name Set-up and the stages of a coupled step */
      /** @{ */
      /** Mesh, adapted mesh, flow solver, bodies, interface, output; the
       *  checkpoint's state with `restart`; the interface and the first
       *  output at t = 0. */
      void
      set_up();

      /** Stage 1 of a step of size @p k: prescribed bodies to t_n+1, and
       *  the adapted mesh after the bodies, to the poses at which they are
       *  marked over the step. */
      void
      move_mesh(const double k);

      /** Stage 2: the covered nodes and their rigid velocities. */
      void
      impose_interface(const double k);

      /** Stage 3: the fluid over the step. A solve that fails stops the
       *  run with the likely cause, named from measure_step_conditions(). */
      void
      advance_fluid(const double k);

      /** Stage 4: the fluid's loads on the bodies. */
      void
      compute_loads(const double k);

      /** Stage 5: the bodies over the step. The run is then at t_n+1, and
       *  bodies that do not move before a step are marked there. */
      void
      advance_bodies(const double k);

      /** Stages 2 to 5 with `Coupling = iterated`: solved again from the
       *  step's start, the fluid given the velocities that the
       *  quasi-Newton model of CouplingIteration takes from the step's
       *  iterates, until the free bodies
       *  reach those velocities. Stops the run if they do not within
       *  'Maximum coupling iterations'. */
      void
      iterate_coupled_step(const double k);

      /** Stage 6: the time series, the fields when due, the progress line. */
      void
      write_output(const double k);

      /** Stage 7: save the state into the output folder's checkpoint. */
      void
      write_checkpoint();
      /** @} */

      /** @name What the stages leave behind (for tests and inspection) */
      /** @{ */
      /** The time the run has reached [s]. */
      double
      time() const
      {
        return t;
      }

      /** The number of steps taken. */
      unsigned int
      step_number() const
      {
        return step;
      }

      /** The rigid engine with the particles and the walls. */
      const rigid::World &
      world() const;

      /** The particles' ids in world(), in the order of the case file. */
      const std::vector<unsigned int> &
      body_ids() const;

      /** What the coupling carries for each particle. */
      const std::vector<BodyCouplingState> &
      coupling_states() const;

      /** The velocity nodes each particle covers now (collective). */
      std::vector<unsigned long>
      n_covered_nodes() const;

      /** The fluid's kinetic energy in the mesh [J] (collective). */
      double
      fluid_kinetic_energy() const;
      /** @} */

    private:
      struct Run;

      /** Where a body is and how it moves. */
      struct BodyMotion
      {
        Eigen::Vector3d    position;
        Eigen::Quaterniond orientation;
        Eigen::Vector3d    velocity;
        Eigen::Vector3d    angular_velocity;
      };

      /** @name Parts of set_up() */
      /** @{ */
      /** The prescribed and hinged particles' motions, and where every
       *  particle starts. */
      void
      set_up_given_motions();
      void
      create_mesh();
      void
      adapt_mesh_to_bodies();
      void
      add_bodies();
      void
      set_up_interface();
      void
      read_checkpoint();
      /** @} */

      /** Mark the nodes the bodies cover where they stand, and with
       *  'Films between parts = cover' the films between parts. */
      void
      mark_covered_nodes();

      /** The covered velocity DoFs where parts of one articulated body
       *  meet (none, without a scan, when there is no such body). */
      std::vector<dealii::types::global_dof_index>
      joint_dofs() const;
      /** Put each hinged part where its parent now is and its hinge at
       *  @p time puts it, with the velocity of the composite motion. */
      void
      pose_hinged_parts(const double time);
      /** The rigid engine's step with the loads (stage 5 without its
       *  checks and without moving on to t_n+1). */
      void
      move_bodies(const double k);
      /** The run moves on to t_n+1 after the bodies have moved. */
      void
      end_step(const double k);
      /** Where every body is and how it moves. */
      std::vector<BodyMotion>
      body_motions() const;
      /** Which velocities of a body free_velocities() stacks. */
      enum class Velocities
      {
        /// those the fluid was given over the step
        given,
        /// those the body has
        reached
      };
      /** The free bodies' @p which velocities, rotation times the bounding
       *  radius. */
      Eigen::VectorXd
      free_velocities(const Velocities which) const;
      /** The largest speed a free body has reached so far [m/s]. */
      double
      free_bodies_speed() const;
      /** Make the free bodies' predicted velocities @p next (as
       *  free_velocities() stacks them) by the accelerations the
       *  prediction uses. */
      void
      predict_free_velocities(const Eigen::VectorXd &next, const double k);
      /** Mark the nodes around the bodies' current poses and give them the
       *  bodies' velocities. */
      void
      impose_body_velocities();
      /** The interface a free body shows the fluid over a step of size
       *  @p k: 'Constraint velocity = extrapolated' gives the covered nodes
       *  U_n + k a_n, 'Interface position = midpoint' marks them around
       *  X_n + k/2 (U_n + k/2 a_n), the body turned by
       *  k/2 (omega_n + k/2 alpha_n); the bodies keep their state. */
      void
      impose_predicted_interface(const double k);
      /** Move every free body to the state it shows the fluid over a step
       *  of size @p k (see impose_predicted_interface()); returns every
       *  body's state before, for restore_bodies(). */
      std::vector<BodyMotion>
      move_free_bodies_to_prediction(const double k);
      /** Give the bodies back the @p states move_free_bodies_to_prediction()
       *  returned. */
      void
      restore_bodies(const std::vector<BodyMotion> &states);
      /** The bodies' poses where the step of size @p k marks them: free
       *  bodies at their predicted midpoint when the interface is placed
       *  there, every other body where it is. */
      std::vector<geometry::Pose>
      poses_marked_over_step(const double k);
      /** The imposed velocities are the bodies' current ones. */
      void
      record_imposed();
      /** The rigid velocities of the marked nodes at the start of the
       *  step, in the order of FictitiousBoundary::constraint_values(): a
       *  prescribed body's from the velocity it was last solved with (its
       *  own at t_n), so that the stages of the step take its nodes along
       *  its motion; with 'Stage velocities = interpolated' a free body's
       *  from its velocity in @p step_start (its own at t_n, before the
       *  prediction); every other body's as imposed (its nodes hold the
       *  imposed velocity from the first stage on: doc/developer/fbm.md,
       *  "Constraint values through the stages"). Empty when no body's
       *  nodes are interpolated. */
      std::vector<double>
      step_start_constraint_values(const std::vector<BodyMotion> &step_start);
      /** A row of every time series at time t, after a step of size @p k
       *  (with the last solve's counts). */
      void
      record(const double k);
      /** Whether the run has reached its 'End time' (to rounding). */
      bool
      at_end_time() const;
      /** Whether a checkpoint is due after this step: at the end, and
       *  every 'Step interval' steps or 'Wall-time interval' minutes. */
      bool
      checkpoint_due() const;
      /** What the progress line adds to the solver's counts: the speed of
       *  particle 0, and the pockets of fluid the bodies wall off from the
       *  flow, if any (fluid::NavierStokes::n_enclosed_pockets()). */
      std::string
      progress_details() const;

      /** What the step of size @p k starts from (CFL number, the fastest
       *  particle, contacts), for the message of a failed flow solve. */
      StepConditions
      measure_step_conditions(const double k) const;

      /** Measure, write and print how the mesh sees each surface-mesh
       *  body where it starts (report_surface_resolution()). */
      void
      report_surface_resolution_at_start() const;

      /** Print the set-up warnings (particles resolved by few cells, too
       *  light for the coupling). */
      void
      warn_about_set_up() const;

      /** The smallest edge of the cell at each particle's centre [m] (0
       *  where no cell holds it). */
      std::vector<double>
      cell_sizes_at_particles() const;

      /** The smallest edge of any cell [m]. */
      double
      smallest_cell_size() const;
      /** The time loop: the stages of each step, the output and the
       *  checkpoints, up to 'End time'. */
      void
      run_time_steps();
      /** Time steps of a steady case: one nonlinear solve. */
      void
      solve_steady();
      ParticulateFlowSummary
      summarise();

      std::function<void(const fluid::NavierStokes<dim> &)> flow_inspector;
      const ParticulateFlowParameters                      &parameters;
      const std::string                                     parameter_file;
      MPI_Comm                                              communicator;
      /// everything the run holds (mesh, solvers, bodies, output)
      std::unique_ptr<Run> run_;
      double               t    = 0.;
      double               dt   = 0.;
      unsigned int         step = 0;
    };
  } // namespace fbm
} // namespace particulate

#endif
