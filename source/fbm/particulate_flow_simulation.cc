#include <particulate/core/checkpoint.h>
#include <particulate/core/mesh.h>
#include <particulate/core/time_series_writer.h>
#include <particulate/fbm/body_adapted_mesh.h>
#include <particulate/fbm/body_coupling_state.h>
#include <particulate/fbm/body_state_guard.h>
#include <particulate/fbm/case_file.h>
#include <particulate/fbm/coupling_iteration.h>
#include <particulate/fbm/energy_balance.h>
#include <particulate/fbm/fictitious_boundary.h>
#include <particulate/fbm/hinged_motion.h>
#include <particulate/fbm/hydrodynamic_forces.h>
#include <particulate/fbm/particle_set_checks.h>
#include <particulate/fbm/particle_shape.h>
#include <particulate/fbm/particle_world.h>
#include <particulate/fbm/particulate_flow_output.h>
#include <particulate/fbm/particulate_flow_simulation.h>
#include <particulate/fbm/prescribed_motion.h>
#include <particulate/fbm/rigid_body_update.h>
#include <particulate/fbm/set_up_warnings.h>
#include <particulate/fbm/surface_resolution_report.h>
#include <particulate/fluid/flow_diagnostics.h>
#include <particulate/fluid/navier_stokes.h>
#include <particulate/fluid/run_frame.h>
#include <particulate/rigid/world.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

namespace particulate {
  namespace fbm {
    using namespace dealii;

    namespace {
      /** The marking that 'Covered nodes' chooses. */
      template <int dim>
      typename FictitiousBoundary<dim>::Marking
      marking_of(const CoveredNodes choice)
      {
        using Marking = typename FictitiousBoundary<dim>::Marking;
        switch (choice)
          {
            case CoveredNodes::nearest:
              return Marking::nearest;
            case CoveredNodes::halfway:
              return Marking::halfway;
            case CoveredNodes::inside:
              break;
          }
        return Marking::inside;
      }

      /** The message of a coupled step from @p t that @p iteration left
       *  unconverged. */
      std::string
      unconverged_coupling(const double             t,
                           const CouplingIteration &iteration,
                           const double             tolerance)
      {
        return "The coupled step from t = " + std::to_string(t)
               + " s did not converge in "
               + std::to_string(iteration.n_iterations())
               + " fluid solves: the velocities the fluid was given and "
                 "those the free bodies reached still differ by "
               + std::to_string(iteration.relative_residual())
               + " of their speed ('Coupling tolerance' = "
               + std::to_string(tolerance)
               + "). The loads are only as precise as the flow's solvers: "
                 "lower 'Relative tolerance' in subsections 'Nonlinear "
                 "solver' and 'Linear solver', raise 'Maximum coupling "
                 "iterations' in subsection 'Particles', or reduce 'Time "
                 "step'.";
      }
    } // namespace



    /** Everything a run holds between its stages: the frame every flow
     *  run has (rank-0 stream, timers, mesh, progress) and the coupling's
     *  own objects. */
    template <int dim>
    struct ParticulateFlowSimulation<dim>::Run : fluid::RunFrame<dim>
    {
      Run(const ParticulateFlowParameters &parameters,
          const std::string               &parameter_file,
          MPI_Comm                         comm)
        : fluid::RunFrame<dim>(parameters.flow, parameter_file, comm)
        , output(parameters.flow.output, comm)
        , checkpoint(parameters.flow.output.directory, comm)
      {}

      /// the mesh's box, a column's radius, walls and mirror planes
      DomainBox domain;
      /// 2 per mirror plane: the loads and energies of the whole set-up
      unsigned int n_images = 1;
      /// per particle: its motion where it is prescribed, else null
      std::vector<std::unique_ptr<PrescribedMotion<dim>>> prescribed;
      /// per particle: its motion on its parent where it is hinged, else
      /// null
      std::vector<std::unique_ptr<HingedMotion<dim>>> hinged;
      /// per particle: where it starts (a prescribed one at d(0), phi(0))
      std::vector<BodyStart>                              starts;
      std::unique_ptr<BodyAdaptedMesh<dim>>               adapted_mesh;
      deformation::DeformationReport                      initial_report;
      std::unique_ptr<fluid::NavierStokes<dim>>           flow;
      std::unique_ptr<rigid::World>                       world;
      std::vector<rigid::BodyId>                          ids;
      std::unique_ptr<RigidBodyUpdate>                    rigid_update;
      std::unique_ptr<BodyStateGuard>                     guard;
      std::unique_ptr<EnergyBalance>                      energy;
      std::unique_ptr<FictitiousBoundary<dim>>            interface;
      std::vector<typename FictitiousBoundary<dim>::Body> interface_bodies;
      /// per particle: its articulated body's head where it has parts or is
      /// one, else -1 (FictitiousBoundary::joint_dofs())
      std::vector<int>               joint_of_body;
      std::vector<BodyCouplingState> states;
      /// 'Force integral = stress and inertia': the flow at the start of
      /// the step
      std::optional<typename fluid::NavierStokes<dim>::BlockVector> step_start;
      /// the counts of the last solve
      fluid::SolveStatistics     statistics;
      ParticulateFlowOutput<dim> output;
      const core::Checkpoint     checkpoint;
      /// wall seconds of the last checkpoint
      double                 last_checkpoint = 0.;
      ParticulateFlowSummary summary;
      /// some particle moves by a given motion (prescribed or hinged)
      bool any_prescribed = false;
      /// the mesh follows moving bodies at the start of every step
      bool mesh_follows = false;
      /// a free body shows the fluid a predicted interface
      bool predict_interface = false;
      /// 'Coupling = iterated' with free bodies: the step's iteration
      std::optional<CouplingIteration> coupling;
      /// the iterates after a step's first keep its covered nodes and
      /// give them new velocities only: the loads then change smoothly
      /// with those velocities, and the iteration has a fixed point
      bool keep_covered_nodes = false;
    };



    template <int dim>
    ParticulateFlowSimulation<dim>::ParticulateFlowSimulation(
      const ParticulateFlowParameters &parameters,
      const std::string               &parameter_file,
      MPI_Comm                         comm)
      : parameters(parameters)
      , parameter_file(parameter_file)
      , communicator(comm)
    {}



    template <int dim>
    ParticulateFlowSimulation<dim>::~ParticulateFlowSimulation() = default;



    template <int dim>
    ParticulateFlowSummary
    ParticulateFlowSimulation<dim>::run()
    {
      set_up();
      const auto &time_p = parameters.flow.time;
      if (time_p.scheme == core::TimeParameters::Scheme::steady)
        solve_steady();
      else
        {
          try
            {
              run_time_steps();
            }
          catch (const std::exception &e)
            {
              // the series end with why; the checkpoint and the output
              // written so far stay as they are
              run_->output.note_stop(t, e.what());
              throw;
            }
        }
      return summarise();
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::run_time_steps()
    {
      const auto &time_p = parameters.flow.time;
      while (!at_end_time())
        {
          const double k = dt  = std::min(dt, time_p.end_time - t);
          const auto   started = std::chrono::steady_clock::now();
          {
            // everything of a step but output and diagnostics
            TimerOutput::Scope scope(run_->timer, "coupled step (total)");
            move_mesh(k);
            if (run_->coupling)
              iterate_coupled_step(k);
            else
              {
                impose_interface(k);
                advance_fluid(k);
                compute_loads(k);
                advance_bodies(k);
              }
          }
          run_->summary.step_seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now()
                                          - started)
              .count());
          write_output(k);
          if (time_p.adaptive)
            dt = time_p.next_time_step(dt, run_->flow->cfl_number(dt));
          if (checkpoint_due())
            write_checkpoint();
          else if (parameters.checkpoint.wall_time_step(step))
            run_->flow->reset_preconditioners(); // as a checkpoint would
        }
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::set_up()
    {
      const auto &particle_p = parameters.particles;
      const auto &time_p     = parameters.flow.time;
      check_particles_suit_the_run(parameters, parameter_file);
      run_   = std::make_unique<Run>(parameters, parameter_file, communicator);
      Run &r = *run_;

      create_mesh();
      set_up_given_motions();
      adapt_mesh_to_bodies();

      r.flow = std::make_unique<fluid::NavierStokes<dim>>(parameters.flow.fluid,
                                                          r.tria,
                                                          r.timer);
      r.flow->setup_dofs();
      r.flow->set_initial_condition(0.);
      add_bodies();
      if (!parameters.restart)
        {
          r.guard->check_given_motions(*r.world, 0.);
          check_contact_clearance(*r.world,
                                  r.ids,
                                  particle_p.bodies,
                                  r.world->parameters().contact_offset);
        }
      set_up_interface();

      r.states.assign(r.ids.size(), BodyCouplingState());
      r.summary.n_dofs = r.flow->n_dofs();
      t                = 0.;
      dt               = time_p.time_step;
      step             = 0;
      if (parameters.restart)
        read_checkpoint();
      r.output.open_time_series(r.ids.size(),
                                r.adapted_mesh != nullptr,
                                parameters.restart,
                                t);
      r.output.write_particle_table(particle_p.bodies);
      if (!parameters.restart)
        report_surface_resolution_at_start();
      r.start_progress(t);
      r.mesh_follows
        = r.adapted_mesh
          && (particle_p.any(ParticleMotion::free) || r.any_prescribed);
      r.rigid_update = std::make_unique<RigidBodyUpdate>(
        particle_p,
        parameters.flow.fluid.properties.density,
        r.starts);
      r.predict_interface = particle_p.any(ParticleMotion::free)
                            && (particle_p.extrapolate_constraint_velocity
                                || particle_p.midpoint_interface_position);
      if (particle_p.coupling == Coupling::iterated
          && particle_p.any(ParticleMotion::free))
        r.coupling.emplace(particle_p.coupling_tolerance,
                           particle_p.max_coupling_iterations);

      impose_body_velocities();
      if (!parameters.restart)
        {
          for (auto &s : r.states)
            s.mark_solved();
          r.output.record_mesh(0., r.initial_report);
          record(dt);
          TimerOutput::Scope scope(r.timer, "output");
          r.output.write_fields(*r.flow, *r.world, 0, 0.);
        }
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::set_up_given_motions()
    {
      Run        &r         = *run_;
      const auto &particles = parameters.particles.bodies;
      const auto  start_of  = [](const PrescribedState &s) {
        return BodyStart{s.position,
                         s.orientation,
                         s.velocity,
                         s.angular_velocity};
      };
      for (const ParticleDescription &p : particles)
        {
          r.prescribed.push_back(p.motion == ParticleMotion::prescribed ?
                                   std::make_unique<PrescribedMotion<dim>>(
                                     p,
                                     parameters.flow.time.end_time) :
                                   nullptr);
          r.starts.push_back(start_of(r.prescribed.back() ?
                                        r.prescribed.back()->state(0.) :
                                        PrescribedState{p.position,
                                                        p.velocity,
                                                        p.orientation,
                                                        p.angular_velocity}));
        }
      // the parts after every parent has its start
      r.hinged.resize(particles.size());
      for (unsigned int i = 0; i < particles.size(); ++i)
        if (particles[i].motion == ParticleMotion::hinged)
          {
            const BodyStart      &parent = r.starts[particles[i].hinge.parent];
            const PrescribedState parent_state{parent.position,
                                               parent.velocity,
                                               parent.orientation,
                                               parent.angular_velocity};
            r.hinged[i] = std::make_unique<HingedMotion<dim>>(
              particles[i],
              parent_state,
              parameters.flow.time.end_time);
            r.starts[i] = start_of(r.hinged[i]->state(0., parent_state));
          }
      r.any_prescribed = parameters.particles.any(ParticleMotion::prescribed)
                         || parameters.particles.any(ParticleMotion::hinged);
      const auto parts = hinged_parts(particles);
      for (unsigned int i = 0; i < particles.size(); ++i)
        {
          const unsigned int head = assembly_head(particles, i);
          r.joint_of_body.push_back(
            parts[head].empty() ? -1 : static_cast<int>(head));
        }
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::pose_hinged_parts(const double time)
    {
      Run &r = *run_;
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        if (r.hinged[i])
          {
            const rigid::RigidBody &parent = r.world->body(
              r.ids[parameters.particles.bodies[i].hinge.parent]);
            const PrescribedState s
              = r.hinged[i]->state(time,
                                   {parent.position,
                                    parent.linear_velocity,
                                    parent.orientation,
                                    parent.angular_velocity});
            rigid::RigidBody &b = r.world->body(r.ids[i]);
            b.position          = s.position;
            b.linear_velocity   = s.velocity;
            b.orientation       = s.orientation;
            b.angular_velocity  = s.angular_velocity;
          }
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::mark_covered_nodes()
    {
      Run &r = *run_;
      r.interface->classify(r.interface_bodies);
      const auto &joints = r.joint_of_body;
      if (parameters.particles.part_films == PartFilms::cover
          && std::any_of(joints.begin(), joints.end(), [](const int j) {
               return j >= 0;
             }))
        r.interface->cover_films(r.interface_bodies, joints);
    }



    template <int dim>
    std::vector<dealii::types::global_dof_index>
    ParticulateFlowSimulation<dim>::joint_dofs() const
    {
      // a scan of every cell's node pairs: only where there are joints
      const auto &joints = run_->joint_of_body;
      if (std::none_of(joints.begin(), joints.end(), [](const int j) {
            return j >= 0;
          }))
        return {};
      return run_->interface->joint_dofs(joints);
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::create_mesh()
    {
      Run        &r          = *run_;
      const auto &particle_p = parameters.particles;
      r.create_mesh();
      const auto [box_lower, box_upper]
        = core::global_bounding_box(r.tria, communicator);
      Eigen::Vector3d lower = Eigen::Vector3d::Zero(),
                      upper = Eigen::Vector3d::Zero();
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = box_lower[d];
          upper[d] = box_upper[d];
        }
      r.domain
        = make_domain_box(parameters.flow.mesh, particle_p, lower, upper, dim);
      check_inside_domain(particle_p.bodies, r.domain);
      check_on_mirror_planes(particle_p.bodies,
                             lower,
                             upper,
                             particle_p.symmetry_planes,
                             dim);
      for (unsigned int f = 0; f < 2 * dim; ++f)
        if (particle_p.symmetry_planes[f])
          r.n_images *= 2;
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::adapt_mesh_to_bodies()
    {
      // r-adaptivity: the mesh resolves the bodies where they start
      Run &r = *run_;
      if (parameters.deformation.method
            == deformation::DeformationParameters::Method::none
          && parameters.deformation.following
               != deformation::DeformationParameters::Following::
                 carry_neighbourhood)
        return;
      TimerOutput::Scope scope(r.timer, "mesh deformation");
      std::vector<std::shared_ptr<const geometry::Shape>> shapes;
      for (const ParticleDescription &p : parameters.particles.bodies)
        shapes.push_back(p.shape);
      r.adapted_mesh
        = std::make_unique<BodyAdaptedMesh<dim>>(parameters.flow.mesh,
                                                 parameters.deformation,
                                                 shapes,
                                                 r.tria);
      std::vector<geometry::Pose> poses;
      for (unsigned int i = 0; i < shapes.size(); ++i)
        poses.emplace_back(r.starts[i].orientation, r.starts[i].position);
      r.initial_report   = r.adapted_mesh->adapt(poses);
      const auto &report = r.initial_report;
      r.pcout << "Mesh deformation: " << r.adapted_mesh->mesh().method_name()
              << ", min scaled Jacobian " << report.quality.min_scaled_jacobian
              << ", largest aspect ratio " << report.quality.max_aspect_ratio
              << std::endl;
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::add_bodies()
    {
      Run               &r          = *run_;
      const auto        &particle_p = parameters.particles;
      ParticleWorldFrame frame;
      frame.domain         = r.domain;
      frame.contact_offset = particle_p.contact_distance ?
                               *particle_p.contact_distance :
                               core::smallest_cell_edge(r.tria, communicator);
      // the weight enters as (rho_p - rho_f) V g through RigidBodyUpdate;
      // the engine integrates a free particle with the added mass m + m_a
      frame.gravity       = Eigen::Vector3d::Zero();
      frame.added_density = particle_p.added_mass_coefficient
                            * parameters.flow.fluid.properties.density;
      ParticleWorld built = build_particle_world(particle_p, r.starts, frame);
      r.world             = std::move(built.world);
      r.ids               = std::move(built.ids);
      r.guard             = std::make_unique<BodyStateGuard>(frame.domain,
                                                 r.ids,
                                                 frame.contact_offset,
                                                 particle_motions(particle_p));
      r.energy
        = std::make_unique<EnergyBalance>(free_body_ids(particle_p, r.ids));
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::set_up_interface()
    {
      Run        &r          = *run_;
      const auto &particle_p = parameters.particles;
      r.interface = std::make_unique<FictitiousBoundary<dim>>(*r.flow);
      r.interface->set_marking(marking_of<dim>(particle_p.covered_nodes));
      r.interface->setup();
      // the engine marks the nodes inside spheres, disks and surface
      // meshes only: 'auto' keeps the hash grid for other markings and
      // shapes (checked for 'cuda' when parsing)
      const bool engine_takes_all_shapes
        = std::all_of(particle_p.bodies.begin(),
                      particle_p.bodies.end(),
                      [](const ParticleDescription &p) {
                        return containment_engine_takes(*p.shape, dim);
                      });
      if (particle_p.containment_backend == ContainmentBackend::cuda
          || (particle_p.containment_backend == ContainmentBackend::automatic
              && particle_p.covered_nodes == CoveredNodes::inside
              && engine_takes_all_shapes
              && cuda::ContainmentEngine::cuda_device_available()))
        r.interface->use_containment_engine(cuda::Backend::cuda);
      for (const auto id : r.ids)
        r.interface_bodies.push_back({&r.world->body(id)});

      r.pcout << r.size_line(*r.flow) << "; " << particle_p.n_particles()
              << " particle(s); contact distance "
              << r.world->parameters().contact_offset << " m\nVelocity solver: "
              << r.flow->velocity_solver_description()
              << "\nContainment: " << r.interface->containment_method()
              << std::endl;
      warn_about_set_up();
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::report_surface_resolution_at_start() const
    {
      const Run                  &r = *run_;
      std::vector<geometry::Pose> poses;
      for (const auto &start : r.starts)
        poses.emplace_back(start.orientation, start.position);
      r.pcout << report_surface_resolution(r.tria,
                                           parameters.particles.bodies,
                                           poses,
                                           r.output.directory(),
                                           communicator)
              << std::flush;
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::warn_about_set_up() const
    {
      const Run   &r         = *run_;
      const auto  &particles = parameters.particles;
      const double rho_f     = parameters.flow.fluid.properties.density;
      const std::vector<double> cell_sizes = cell_sizes_at_particles();
      std::vector<double>       sizes, density_ratios, cells_at_free;
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        {
          sizes.push_back(body_size(r.world->body(r.ids[i]), dim));
          if (particles.bodies[i].motion == ParticleMotion::free)
            {
              density_ratios.push_back(particles.bodies[i].density / rho_f);
              cells_at_free.push_back(cell_sizes[i]);
            }
        }
      for (const std::string &warning :
           {set_up_warnings::resolution(sizes, cell_sizes),
            set_up_warnings::coupling_stability(
              density_ratios,
              particles.added_mass_coefficient,
              dim),
            set_up_warnings::contact_distance(
              r.world->parameters().contact_offset,
              cells_at_free),
            set_up_warnings::thin_surface_meshes(particles.bodies)})
        if (!warning.empty())
          r.pcout << warning << std::endl;
    }



    template <int dim>
    std::vector<double>
    ParticulateFlowSimulation<dim>::cell_sizes_at_particles() const
    {
      const Run                  &r = *run_;
      const GridTools::Cache<dim> cache(r.tria, r.flow->get_mapping());
      std::vector<double>         h(r.ids.size(), 0.);
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        {
          const Eigen::Vector3d &x = r.world->body(r.ids[i]).position;
          Point<dim>             p;
          for (unsigned int d = 0; d < dim; ++d)
            p[d] = x[d];
          try
            {
              const auto cell
                = GridTools::find_active_cell_around_point(cache, p).first;
              if (cell.state() == IteratorState::valid
                  && cell->is_locally_owned())
                h[i] = cell->minimum_vertex_distance();
            }
          catch (const std::exception &)
            {
              // not in this rank's part of the mesh
            }
        }
      std::vector<double> largest(h.size());
      Utilities::MPI::max(make_array_view(std::as_const(h)),
                          communicator,
                          make_array_view(largest));
      return largest;
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::write_checkpoint()
    {
      // Everything the next step reads; the rest (mesh, constraints,
      // covered nodes) follows from the case file and the bodies.
      Run               &r = *run_;
      TimerOutput::Scope scope(r.timer, "checkpoint");
      r.checkpoint.save(
        [&](std::ostream &out) {
          core::write_binary(out, t);
          core::write_binary(out, dt);
          core::write_binary<unsigned long>(out, step);
          save_coupling_states(out, r.states);
          r.flow->save_state(out);
          r.world->save_state(out);
          if (r.adapted_mesh)
            r.adapted_mesh->save(out);
          r.output.save(out);
        },
        t,
        step);
      // the continued run rebuilds its preconditioners here, as a
      // restarted one must: both then compute the same numbers
      r.flow->reset_preconditioners();
      r.last_checkpoint = r.elapsed_seconds();
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::read_checkpoint()
    {
      Run        &r      = *run_;
      const auto &time_p = parameters.flow.time;
      if (time_p.scheme == core::TimeParameters::Scheme::steady)
        throw std::runtime_error(
          parameter_file
          + ": --restart continues time-dependent runs; this case is "
            "steady.");
      r.checkpoint.load([&](std::istream &in) {
        t    = core::read_binary<double>(in);
        dt   = core::read_binary<double>(in);
        step = core::read_binary<unsigned long>(in);
        load_coupling_states(in, r.states);
        r.flow->load_state(in);
        r.world->load_state(in);
        if (r.adapted_mesh)
          {
            // the mesh velocity this sets is replaced before the next
            // step uses one; the geometric matrices are what counts
            r.flow->move_mesh([&]() { r.adapted_mesh->load(in); }, dt);
            // V-cycles for the loaded positions, as the continued run
            // has them after its checkpoint ('keep' would otherwise go
            // on with those of the undeformed mesh)
            r.flow->reset_preconditioners();
            r.interface->setup();
          }
        r.output.load(in);
      });
      r.pcout << "Restarting from " << r.checkpoint.directory()
              << " at t = " << t << " s (step " << step << ")" << std::endl;
      // A fixed step comes from the parameter file: the checkpoint's may
      // be a last step shortened to meet the old 'End time', and a user
      // may have changed 'Time step' on purpose. An adaptive step goes
      // on from where it was.
      if (!time_p.adaptive && dt != time_p.time_step)
        {
          r.pcout << "Time step: " << time_p.time_step << " s from "
                  << parameter_file
                  << " (the checkpointed run's last step: " << dt << " s)"
                  << std::endl;
          dt = time_p.time_step;
        }
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::record(const double k)
    {
      Run                             &r = *run_;
      TimerOutput::Scope               scope(r.timer, "diagnostics");
      const std::vector<unsigned long> nodes_inside
        = r.interface->n_nodes_inside(r.ids.size());
      std::vector<BodyRecord> rows;
      double                  particles_energy = 0.;
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        {
          BodyRecord row;
          row.body = &r.world->body(r.ids[i]);
          row.load = r.states[i].fluid_load;
          if (t > 0.)
            for (const auto &f : r.world->contact_forces(r.ids[i]))
              row.contact_force += f.force;
          row.kinetic_energy = r.rigid_update->kinetic_energy(i, *row.body);
          row.nodes_inside   = nodes_inside[i];
          particles_energy += row.kinetic_energy;
          r.states[i].record_speed(row.body->linear_velocity.norm(), t);
          rows.push_back(row);
        }
      r.output.record_bodies(t, rows);
      r.output.record_flow(t,
                           r.n_images * fluid::kinetic_energy(*r.flow),
                           particles_energy,
                           r.statistics,
                           k,
                           r.world->max_penetration());
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::record_imposed()
    {
      Run &r = *run_;
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        {
          const rigid::RigidBody &b    = r.world->body(r.ids[i]);
          r.states[i].imposed_velocity = b.linear_velocity;
          r.states[i].imposed_angular  = b.angular_velocity;
        }
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::impose_body_velocities()
    {
      Run &r = *run_;
      if (!r.keep_covered_nodes)
        {
          TimerOutput::Scope scope(r.timer, "fbm: containment");
          mark_covered_nodes();
        }
      TimerOutput::Scope scope(r.timer, "fbm: constraints");
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        r.states[i].load_centre = r.world->body(r.ids[i]).position;
      record_imposed();
      r.flow->set_fictitious_boundary_values(
        r.interface->constraint_values(r.interface_bodies),
        joint_dofs(),
        step_start_constraint_values(body_motions()));
    }



    template <int dim>
    std::vector<double>
    ParticulateFlowSimulation<dim>::step_start_constraint_values(
      const std::vector<BodyMotion> &step_start)
    {
      Run                          &r       = *run_;
      const std::vector<BodyMotion> current = body_motions();
      bool                          any     = false;
      const bool                    ramp_free
        = parameters.particles.interpolate_free_stage_velocities;
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        if (r.prescribed[i])
          {
            rigid::RigidBody &b = r.world->body(r.ids[i]);
            b.linear_velocity   = r.states[i].solved_velocity;
            b.angular_velocity  = r.states[i].solved_angular;
            any                 = true;
          }
        else if (ramp_free
                 && parameters.particles.bodies[i].motion
                      == ParticleMotion::free)
          {
            // a body not predicted (marked where it is) starts where it
            // ends: nothing to interpolate
            rigid::RigidBody &b = r.world->body(r.ids[i]);
            if (b.linear_velocity == step_start[i].velocity
                && b.angular_velocity == step_start[i].angular_velocity)
              continue;
            b.linear_velocity  = step_start[i].velocity;
            b.angular_velocity = step_start[i].angular_velocity;
            any                = true;
          }
      std::vector<double> start;
      if (!any)
        return start;
      const auto values = r.interface->constraint_values(r.interface_bodies);
      restore_bodies(current);
      start.reserve(values.size());
      for (const auto &entry : values)
        start.push_back(entry.second);
      return start;
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::impose_predicted_interface(const double k)
    {
      // It replaces the marking at X_n made at the end of the previous step
      // (which the output at t_n shows); at the start of the step because
      // only then is the step size k known. The loads are then taken about
      // the centres that were marked.
      Run                    &r = *run_;
      std::vector<BodyMotion> current;
      {
        TimerOutput::Scope scope(r.timer, "fbm: constraints");
        current = move_free_bodies_to_prediction(k);
      }
      if (parameters.particles.midpoint_interface_position
          && !r.keep_covered_nodes)
        {
          TimerOutput::Scope scope(r.timer, "fbm: containment");
          mark_covered_nodes();
        }
      TimerOutput::Scope scope(r.timer, "fbm: constraints");
      auto values = r.interface->constraint_values(r.interface_bodies);
      auto joints = joint_dofs();
      record_imposed();
      auto start = step_start_constraint_values(current);
      restore_bodies(current);
      r.flow->set_fictitious_boundary_values(std::move(values),
                                             std::move(joints),
                                             std::move(start));
    }



    template <int dim>
    std::vector<typename ParticulateFlowSimulation<dim>::BodyMotion>
    ParticulateFlowSimulation<dim>::move_free_bodies_to_prediction(
      const double k)
    {
      Run                          &r          = *run_;
      const auto                   &particle_p = parameters.particles;
      const std::vector<BodyMotion> current    = body_motions();
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        {
          rigid::RigidBody        &b = r.world->body(r.ids[i]);
          const BodyCouplingState &s = r.states[i];
          // only free bodies are predicted; the others are where and how
          // they move over the step
          if (particle_p.bodies[i].motion != ParticleMotion::free)
            continue;
          if (particle_p.midpoint_interface_position)
            {
              // halfway to the pose predicted for t_n+1 with the last
              // step's accelerations: moved and turned
              b.position
                += 0.5 * k * (b.linear_velocity + 0.5 * k * s.acceleration);
              const Eigen::Vector3d turn
                = 0.5 * k
                  * (b.angular_velocity + 0.5 * k * s.angular_acceleration);
              if (turn.squaredNorm() > 0.)
                b.orientation
                  = (Eigen::Quaterniond(
                       Eigen::AngleAxisd(turn.norm(), turn.normalized()))
                     * b.orientation)
                      .normalized();
            }
          if (particle_p.extrapolate_constraint_velocity)
            {
              b.linear_velocity += k * s.acceleration;
              b.angular_velocity += k * s.angular_acceleration;
            }
          r.states[i].load_centre = b.position;
        }
      // the parts ride on their predicted heads
      pose_hinged_parts(t + k);
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        if (r.hinged[i])
          r.states[i].load_centre = r.world->body(r.ids[i]).position;
      return current;
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::restore_bodies(
      const std::vector<BodyMotion> &states)
    {
      Run &r = *run_;
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        {
          rigid::RigidBody &b = r.world->body(r.ids[i]);
          b.position          = states[i].position;
          b.orientation       = states[i].orientation;
          b.linear_velocity   = states[i].velocity;
          b.angular_velocity  = states[i].angular_velocity;
        }
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::move_mesh(const double k)
    {
      Run         &r     = *run_;
      const double t_new = t + k;
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        if (r.prescribed[i])
          {
            rigid::RigidBody     &b = r.world->body(r.ids[i]);
            const PrescribedState s = r.prescribed[i]->state(t_new);
            b.position              = s.position;
            b.linear_velocity       = s.velocity;
            b.orientation           = s.orientation;
            b.angular_velocity      = s.angular_velocity;
          }
      pose_hinged_parts(t_new);
      if (!r.mesh_follows)
        return;
      deformation::DeformationReport report;
      {
        TimerOutput::Scope scope(r.timer, "mesh deformation");
        report = r.adapted_mesh->follow(poses_marked_over_step(k), *r.flow, k);
      }
      r.output.record_mesh(t_new, report);
      TimerOutput::Scope scope(r.timer, "fbm: containment");
      r.interface->setup();
    }



    template <int dim>
    std::vector<geometry::Pose>
    ParticulateFlowSimulation<dim>::poses_marked_over_step(const double k)
    {
      // The mesh is carried to where the bodies are marked over the step:
      // free bodies predicted to the midpoint are marked there, so the
      // adapted zone sits on the marked body and the covered nodes do not
      // lead it by half a step's travel.
      Run                    &r = *run_;
      std::vector<BodyMotion> current;
      const bool              predicted
        = r.predict_interface
          && parameters.particles.midpoint_interface_position;
      if (predicted)
        current = move_free_bodies_to_prediction(k);
      std::vector<geometry::Pose> poses;
      for (const auto id : r.ids)
        poses.emplace_back(r.world->body(id).orientation,
                           r.world->body(id).position);
      if (predicted)
        restore_bodies(current);
      return poses;
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::impose_interface(const double k)
    {
      // bodies that moved before the step (prescribed, or carrying the
      // mesh) are marked where the step starts; the others were marked at
      // the end of the step before
      if (run_->any_prescribed || run_->mesh_follows)
        impose_body_velocities();
      if (run_->predict_interface)
        impose_predicted_interface(k);
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::advance_fluid(const double k)
    {
      Run &r = *run_;
      if (parameters.particles.force_includes_fluid_inertia)
        r.step_start = r.flow->get_solution();
      const StepConditions conditions = measure_step_conditions(k);
      try
        {
          r.statistics = r.flow->advance(t, k, parameters.flow.time.scheme);
        }
      catch (const fluid::SolverFailure &failure)
        {
          StepConditions measured = conditions;
          measured.smallest_cell  = smallest_cell_size();
          throw std::runtime_error(diagnose_solver_failure(failure, measured));
        }
      r.summary.nonlinear_iterations += r.statistics.nonlinear_iterations;
      r.summary.linear_iterations += r.statistics.linear_iterations;
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::compute_loads(const double k)
    {
      // from the new flow field, with the interface the fluid saw over the
      // step, completed across mirror planes
      Run                         &r = *run_;
      TimerOutput::Scope           scope(r.timer, "fbm: forces");
      const unsigned int           n = r.ids.size();
      std::vector<Eigen::Vector3d> centres;
      for (const auto &s : r.states)
        centres.push_back(s.load_centre);
      std::vector<HydrodynamicLoad> loads
        = hydrodynamic_loads(*r.flow, *r.interface, centres);
      if (parameters.particles.force_includes_fluid_inertia)
        {
          std::vector<RigidStepMotion> motion(n);
          for (unsigned int i = 0; i < n; ++i)
            {
              const BodyCouplingState &s = r.states[i];
              motion[i].centre           = s.load_centre;
              motion[i].angular_velocity = s.imposed_angular;
              if (k > 0.)
                {
                  motion[i].acceleration
                    = (s.imposed_velocity - s.solved_velocity) / k;
                  motion[i].angular_acceleration
                    = (s.imposed_angular - s.solved_angular) / k;
                }
            }
          const auto inertia
            = fluid_inertia_loads(*r.flow,
                                  *r.interface,
                                  k > 0. ? *r.step_start :
                                           r.flow->get_solution(),
                                  k,
                                  motion);
          for (unsigned int i = 0; i < n; ++i)
            {
              loads[i].force += inertia[i].force;
              loads[i].torque += inertia[i].torque;
            }
        }
      add_mirror_images(loads, parameters.particles.symmetry_planes);
      for (unsigned int i = 0; i < n; ++i)
        {
          r.states[i].fluid_load = loads[i];
          r.states[i].mark_solved();
        }
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::advance_bodies(const double k)
    {
      Run &r = *run_;
      r.guard->start_step(*r.world);
      move_bodies(k);
      r.guard->check_step(*r.world, t + k, k);
      end_step(k);
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::iterate_coupled_step(const double k)
    {
      Run &r = *run_;
      // what an iterate changes, as the step found it
      const auto                           flow_start   = r.flow->step_start();
      const std::vector<BodyMotion>        bodies_start = body_motions();
      const std::vector<BodyCouplingState> states_start = r.states;
      const EnergyBalance                  energy_start = *r.energy;
      fluid::SolveStatistics               statistics;
      r.guard->start_step(*r.world);
      r.coupling->start_step();
      for (;;)
        {
          impose_interface(k);
          advance_fluid(k);
          statistics += r.statistics;
          compute_loads(k);
          const Eigen::VectorXd given = free_velocities(Velocities::given);
          move_bodies(k);
          if (r.coupling->record(given,
                                 free_velocities(Velocities::reached),
                                 free_bodies_speed()))
            break;
          if (r.coupling->exhausted())
            throw std::runtime_error(
              unconverged_coupling(t,
                                   *r.coupling,
                                   parameters.particles.coupling_tolerance));
          const Eigen::VectorXd next = r.coupling->next_given();
          r.flow->return_to(flow_start);
          restore_bodies(bodies_start);
          r.states  = states_start;
          *r.energy = energy_start;
          predict_free_velocities(next, k);
          r.keep_covered_nodes = true;
        }
      r.keep_covered_nodes = false;
      r.statistics         = statistics;
      r.guard->check_step(*r.world, t + k, k);
      end_step(k);
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::move_bodies(const double k)
    {
      Run               &r = *run_;
      TimerOutput::Scope scope(r.timer, "rigid bodies");
      r.rigid_update
        ->advance(*r.world, r.ids, r.states, k, t + k, r.energy.get());
    }



    template <int dim>
    std::vector<typename ParticulateFlowSimulation<dim>::BodyMotion>
    ParticulateFlowSimulation<dim>::body_motions() const
    {
      std::vector<BodyMotion> motions;
      for (const rigid::BodyId id : run_->ids)
        {
          const rigid::RigidBody &b = run_->world->body(id);
          motions.push_back(
            {b.position, b.orientation, b.linear_velocity, b.angular_velocity});
        }
      return motions;
    }



    template <int dim>
    Eigen::VectorXd
    ParticulateFlowSimulation<dim>::free_velocities(
      const Velocities which) const
    {
      const Run                   &r = *run_;
      std::vector<Eigen::Vector3d> entries;
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        if (parameters.particles.bodies[i].motion == ParticleMotion::free)
          {
            const rigid::RigidBody &b     = r.world->body(r.ids[i]);
            const double            R     = b.bounding_radius();
            const bool              given = which == Velocities::given;
            entries.push_back(given ? r.states[i].imposed_velocity :
                                      b.linear_velocity);
            entries.push_back(
              R * (given ? r.states[i].imposed_angular : b.angular_velocity));
          }
      Eigen::VectorXd stacked(3 * entries.size());
      for (unsigned int j = 0; j < entries.size(); ++j)
        stacked.segment<3>(3 * j) = entries[j];
      return stacked;
    }



    template <int dim>
    double
    ParticulateFlowSimulation<dim>::free_bodies_speed() const
    {
      double speed = 0.;
      for (unsigned int i = 0; i < run_->ids.size(); ++i)
        if (parameters.particles.bodies[i].motion == ParticleMotion::free)
          speed = std::max(speed, run_->states[i].max_speed);
      return speed;
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::predict_free_velocities(
      const Eigen::VectorXd &next,
      const double           k)
    {
      Run         &r = *run_;
      unsigned int j = 0;
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        if (parameters.particles.bodies[i].motion == ParticleMotion::free)
          {
            const rigid::RigidBody &b = r.world->body(r.ids[i]);
            const double            R = b.bounding_radius();
            r.states[i].acceleration
              = (next.segment<3>(6 * j) - b.linear_velocity) / k;
            r.states[i].angular_acceleration
              = (next.segment<3>(6 * j + 3) / R - b.angular_velocity) / k;
            ++j;
          }
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::end_step(const double k)
    {
      Run              &r       = *run_;
      const std::string warning = r.energy->warning(t + k);
      if (!warning.empty())
        r.pcout << warning << std::endl;
      t += k;
      ++step;
      // the parts where their heads now are, for the output at t_n+1
      pose_hinged_parts(t);
      r.guard->check_given_motions(*r.world, t);
      // bodies that do not move before a step are marked where it ends:
      // the interface of the next step, which the output at t_n+1 shows
      if (!(r.any_prescribed || r.mesh_follows))
        impose_body_velocities();
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::write_output(const double k)
    {
      Run &r = *run_;
      record(k);
      if (r.fields_due(step, t))
        {
          TimerOutput::Scope scope(r.timer, "output");
          r.output.write_fields(*r.flow, *r.world, step, t);
        }
      r.report_step(step, t, k, r.statistics, progress_details());
    }



    template <int dim>
    bool
    ParticulateFlowSimulation<dim>::checkpoint_due() const
    {
      const auto &checkpoint_p = parameters.checkpoint;
      if (!checkpoint_p.enabled())
        return false;
      // rank 0's clock decides, so that all ranks agree
      const double minutes
        = Utilities::MPI::broadcast(communicator,
                                    run_->elapsed_seconds()
                                      - run_->last_checkpoint,
                                    0)
          / 60.;
      return at_end_time()
             || (checkpoint_p.step_interval > 0
                 && step % checkpoint_p.step_interval == 0)
             || (checkpoint_p.wall_time_step(step)
                 && minutes >= checkpoint_p.wall_minutes);
    }



    template <int dim>
    bool
    ParticulateFlowSimulation<dim>::at_end_time() const
    {
      return run_->at_end_time(t);
    }



    template <int dim>
    StepConditions
    ParticulateFlowSimulation<dim>::measure_step_conditions(
      const double k) const
    {
      const Run     &r = *run_;
      StepConditions c;
      c.time_step        = k;
      c.cfl              = r.flow->cfl_number(k);
      c.contact_distance = r.world->parameters().contact_offset;
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        {
          const double speed = r.world->body(r.ids[i]).linear_velocity.norm();
          if (speed > c.fastest_speed)
            {
              c.fastest_speed    = speed;
              c.fastest_particle = i;
            }
        }
      for (const rigid::ContactEdge &edge : r.world->contact_graph().edges())
        for (const rigid::ContactPoint &p : edge.manifold.points)
          if (p.distance <= 0.)
            {
              ++c.n_contacts;
              break;
            }
      c.deepest_overlap = r.world->max_penetration();
      return c;
    }



    template <int dim>
    double
    ParticulateFlowSimulation<dim>::smallest_cell_size() const
    {
      double h = std::numeric_limits<double>::max();
      for (const auto &cell :
           run_->flow->get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          h = std::min(h, cell->minimum_vertex_distance());
      return Utilities::MPI::min(h, communicator);
    }



    template <int dim>
    std::string
    ParticulateFlowSimulation<dim>::progress_details() const
    {
      char                   buffer[128];
      const Eigen::Vector3d &u
        = run_->world->body(run_->ids[0]).linear_velocity;
      const unsigned int pockets = run_->flow->n_enclosed_pockets();
      int                n
        = std::snprintf(buffer, sizeof(buffer), "  |U_0| %.5g m/s", u.norm());
      if (run_->coupling)
        n += std::snprintf(buffer + n,
                           sizeof(buffer) - n,
                           "  coupling %u",
                           run_->coupling->n_iterations());
      if (pockets > 0)
        std::snprintf(buffer + n,
                      sizeof(buffer) - n,
                      "  enclosed fluid pockets %u",
                      pockets);
      return std::string(buffer);
    }



    template <int dim>
    void
    ParticulateFlowSimulation<dim>::solve_steady()
    {
      // fixed obstacles in steady flow: one nonlinear solve
      Run &r = *run_;
      r.statistics
        = r.flow->advance(0., 0., core::TimeParameters::Scheme::steady);
      compute_loads(0.);
      step = 1;
      record(0.);
      {
        TimerOutput::Scope scope(r.timer, "output");
        r.output.write_fields(*r.flow, *r.world, 1, 0.);
      }
      r.report_step(1, 1., 0., r.statistics, progress_details());
    }



    template <int dim>
    ParticulateFlowSummary
    ParticulateFlowSimulation<dim>::summarise()
    {
      Run                    &r       = *run_;
      ParticulateFlowSummary &summary = r.summary;
      summary.n_steps                 = step;
      summary.end_time                = t;
      MPI_Allreduce(MPI_IN_PLACE,
                    summary.step_seconds.data(),
                    static_cast<int>(summary.step_seconds.size()),
                    MPI_DOUBLE,
                    MPI_MAX,
                    communicator);
      for (unsigned int i = 0; i < r.ids.size(); ++i)
        {
          const rigid::RigidBody &b = r.world->body(r.ids[i]);
          summary.position.push_back(b.position);
          summary.velocity.push_back(b.linear_velocity);
          summary.force.push_back(r.states[i].fluid_load.force);
          summary.torque.push_back(r.states[i].fluid_load.torque);
          summary.max_speed.push_back(r.states[i].max_speed);
          summary.time_of_max_speed.push_back(r.states[i].time_of_max_speed);
        }
      r.pcout << "\nFinal: particle 0 at (" << summary.position[0].transpose()
              << ") m, velocity (" << summary.velocity[0].transpose()
              << ") m/s, fluid force (" << summary.force[0].transpose()
              << ") N\nResults are in " << r.output.directory()
              << "/ (flow.pvd, particles.pvd, particle_*.dat, flow.dat)"
              << std::endl;
      r.finish(*r.flow, summary);
      if (flow_inspector)
        flow_inspector(*r.flow);
      return summary;
    }

    template <int dim>
    const rigid::World &
    ParticulateFlowSimulation<dim>::world() const
    {
      return *run_->world;
    }



    template <int dim>
    const std::vector<unsigned int> &
    ParticulateFlowSimulation<dim>::body_ids() const
    {
      return run_->ids;
    }



    template <int dim>
    const std::vector<BodyCouplingState> &
    ParticulateFlowSimulation<dim>::coupling_states() const
    {
      return run_->states;
    }



    template <int dim>
    std::vector<unsigned long>
    ParticulateFlowSimulation<dim>::n_covered_nodes() const
    {
      return run_->interface->n_nodes_inside(run_->ids.size());
    }



    template <int dim>
    double
    ParticulateFlowSimulation<dim>::fluid_kinetic_energy() const
    {
      return fluid::kinetic_energy(*run_->flow);
    }

    template class ParticulateFlowSimulation<2>;
    template class ParticulateFlowSimulation<3>;
  } // namespace fbm
} // namespace particulate
