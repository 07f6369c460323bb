#include <particulate/core/mesh.h>
#include <particulate/core/progress_reporter.h>
#include <particulate/fbm/body_state_guard.h>
#include <particulate/fbm/particle_set_checks.h>
#include <particulate/fbm/particle_world.h>
#include <particulate/fbm/particulate_flow_output.h>
#include <particulate/fbm/prescribed_motion.h>
#include <particulate/fbm/rigid_bodies_simulation.h>
#include <particulate/fbm/set_up_warnings.h>
#include <particulate/fluid/run_frame.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <utility>

namespace particulate {
  namespace fbm {
    template <int dim>
    struct RigidBodiesSimulation<dim>::Run : fluid::RunFrame<dim>
    {
      Run(const ParticulateFlowParameters &parameters,
          const std::string               &parameter_file,
          MPI_Comm                         comm)
        : fluid::RunFrame<dim>(parameters.flow, parameter_file, comm)
        , output(parameters.flow.output, comm)
      {}

      DomainBox                                           domain;
      std::vector<std::unique_ptr<PrescribedMotion<dim>>> prescribed;
      ParticleWorld                                       engine;
      std::unique_ptr<BodyStateGuard>                     guard;
      ParticulateFlowOutput<dim>                          output;
      std::unique_ptr<core::ProgressReporter>             progress;
      RigidBodiesSummary                                  summary;
      double                                              t    = 0.;
      unsigned int                                        step = 0;
    };



    template <int dim>
    RigidBodiesSimulation<dim>::RigidBodiesSimulation(
      const ParticulateFlowParameters &parameters,
      const std::string               &parameter_file,
      MPI_Comm                         comm)
      : parameters(parameters)
      , parameter_file(parameter_file)
      , communicator(comm)
    {}



    template <int dim>
    RigidBodiesSimulation<dim>::~RigidBodiesSimulation() = default;



    template <int dim>
    RigidBodiesSummary
    RigidBodiesSimulation<dim>::run()
    {
      set_up();
      Run         &r         = *run_;
      const double time_step = parameters.flow.time.time_step;
      const auto   wall0     = std::chrono::steady_clock::now();
      try
        {
          while (!r.at_end_time(r.t))
            {
              const double k
                = std::min(time_step, parameters.flow.time.end_time - r.t);
              advance(k);
              record(k);
              if (r.fields_due(r.step, r.t))
                write_fields();
            }
        }
      catch (const std::exception &e)
        {
          r.output.note_stop(r.t, e.what());
          throw;
        }
      return summarise(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0)
          .count());
    }



    template <int dim>
    RigidBodiesSummary
    RigidBodiesSimulation<dim>::summarise(const double wall_seconds)
    {
      Run                &r = *run_;
      RigidBodiesSummary &s = r.summary;
      s.n_steps             = r.step;
      s.end_time            = r.t;
      s.wall_seconds        = wall_seconds;
      for (const rigid::BodyId id : r.engine.ids)
        {
          const rigid::RigidBody &b = r.engine.world->body(id);
          s.position.push_back(b.position);
          s.velocity.push_back(b.linear_velocity);
        }
      s.kinetic_energy = r.engine.world->kinetic_energy();
      r.pcout << "Rigid bodies: " << s.n_steps << " steps to t = " << r.t
              << " s in " << core::format_duration(s.wall_seconds)
              << "; deepest overlap " << s.max_penetration
              << " m (contact distance "
              << r.engine.world->parameters().contact_offset << " m)"
              << std::endl;
      return s;
    }



    template <int dim>
    void
    RigidBodiesSimulation<dim>::set_up()
    {
      const ParticleParameters &particles = parameters.particles;
      const double              end_time  = parameters.flow.time.end_time;
      run_   = std::make_unique<Run>(parameters, parameter_file, communicator);
      Run &r = *run_;
      // the mesh gives the box and the contact distance; the fluid's
      // boundary conditions are not checked against it
      core::create_mesh(parameters.flow.mesh, r.tria);
      const auto [lower, upper]
        = core::global_bounding_box(r.tria, communicator);
      Eigen::Vector3d box_lower = Eigen::Vector3d::Zero(),
                      box_upper = Eigen::Vector3d::Zero();
      for (unsigned int d = 0; d < dim; ++d)
        {
          box_lower[d] = lower[d];
          box_upper[d] = upper[d];
        }
      r.domain = make_domain_box(parameters.flow.mesh,
                                 particles,
                                 box_lower,
                                 box_upper,
                                 dim);
      check_inside_domain(particles.bodies, r.domain);

      std::vector<BodyStart> starts;
      for (const ParticleDescription &p : particles.bodies)
        {
          r.prescribed.push_back(
            p.motion == ParticleMotion::prescribed ?
              std::make_unique<PrescribedMotion<dim>>(p, end_time) :
              nullptr);
          const PrescribedState s = r.prescribed.back() ?
                                      r.prescribed.back()->state(0.) :
                                      PrescribedState{p.position,
                                                      p.velocity,
                                                      p.orientation,
                                                      p.angular_velocity};
          starts.push_back(
            {s.position, s.orientation, s.velocity, s.angular_velocity});
        }
      ParticleWorldFrame frame;
      frame.domain         = r.domain;
      frame.contact_offset = particles.contact_distance ?
                               *particles.contact_distance :
                               core::smallest_cell_edge(r.tria, communicator);
      frame.gravity        = particles.gravity;
      frame.added_density  = 0.;
      r.engine             = build_particle_world(particles, starts, frame);
      r.guard              = std::make_unique<BodyStateGuard>(r.domain,
                                                 r.engine.ids,
                                                 frame.contact_offset,
                                                 particle_motions(particles));
      r.guard->check_given_motions(*r.engine.world, 0.);
      check_contact_clearance(*r.engine.world,
                              r.engine.ids,
                              particles.bodies,
                              frame.contact_offset);

      r.pcout << "Rigid bodies without a fluid: " << particles.n_particles()
              << " particle(s); contact distance " << frame.contact_offset
              << " m; time step " << parameters.flow.time.time_step << " s"
              << std::endl;
      say_what_is_not_used();
      const std::string warning
        = set_up_warnings::thin_surface_meshes(particles.bodies);
      if (!warning.empty())
        r.pcout << warning << std::endl;

      r.output.open_time_series(r.engine.ids.size(), false, false, 0.);
      r.output.write_particle_table(particles.bodies);
      r.progress
        = std::make_unique<core::ProgressReporter>(r.pcout.get_stream(),
                                                   0.,
                                                   end_time);
      record(parameters.flow.time.time_step);
      write_fields();
    }



    template <int dim>
    void
    RigidBodiesSimulation<dim>::say_what_is_not_used() const
    {
      std::vector<std::string> unused{"the fluid (subsections 'Fluid', "
                                      "'Boundary conditions', 'Initial "
                                      "condition')"};
      if (parameters.deformation.method
          != deformation::DeformationParameters::Method::none)
        unused.push_back("the mesh deformation");
      if (parameters.flow.time.adaptive)
        unused.push_back("the adaptive time step (the fixed 'Time step' is "
                         "used)");
      std::ostringstream line;
      line << "Not used without a fluid: ";
      for (unsigned int i = 0; i < unused.size(); ++i)
        line << (i > 0 ? "; " : "") << unused[i];
      run_->pcout << line.str() << '.' << std::endl;
    }



    template <int dim>
    void
    RigidBodiesSimulation<dim>::advance(const double k)
    {
      Run          &r     = *run_;
      rigid::World &world = *r.engine.world;
      const auto    start = std::chrono::steady_clock::now();
      move_prescribed_bodies(r.t + k);
      r.guard->start_step(world);
      std::vector<std::pair<Eigen::Vector3d, Eigen::Quaterniond>> before;
      for (const rigid::BodyId id : r.engine.ids)
        before.emplace_back(world.body(id).position,
                            world.body(id).orientation);
      world.step(k);
      const ParticleParameters &particles = parameters.particles;
      for (unsigned int i = 0; i < r.engine.ids.size(); ++i)
        if (particles.bodies[i].motion == ParticleMotion::free)
          restore_locked_axes(world.body(r.engine.ids[i]),
                              before[i].first,
                              before[i].second,
                              particles.locked_translation,
                              particles.locked_rotation);
      r.t += k;
      ++r.step;
      r.guard->check_step(world, r.t, k);
      r.guard->check_given_motions(world, r.t);
      r.summary.step_seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count());
      r.summary.max_penetration
        = std::max(r.summary.max_penetration, world.max_penetration());
    }



    template <int dim>
    void
    RigidBodiesSimulation<dim>::move_prescribed_bodies(const double t_new)
    {
      Run &r = *run_;
      for (unsigned int i = 0; i < r.engine.ids.size(); ++i)
        if (r.prescribed[i])
          {
            // an immovable body in the engine: where and how fast it moves
            // at the end of the step
            rigid::RigidBody     &b = r.engine.world->body(r.engine.ids[i]);
            const PrescribedState s = r.prescribed[i]->state(t_new);
            b.position              = s.position;
            b.linear_velocity       = s.velocity;
            b.orientation           = s.orientation;
            b.angular_velocity      = s.angular_velocity;
          }
    }



    template <int dim>
    void
    RigidBodiesSimulation<dim>::record(const double k)
    {
      Run                    &r     = *run_;
      const rigid::World     &world = *r.engine.world;
      std::vector<BodyRecord> rows;
      for (const rigid::BodyId id : r.engine.ids)
        {
          BodyRecord row;
          row.body = &world.body(id);
          if (r.t > 0.)
            for (const auto &f : world.contact_forces(id))
              row.contact_force += f.force;
          row.kinetic_energy = row.body->kinetic_energy();
          rows.push_back(row);
        }
      r.output.record_bodies(r.t, rows);
      r.output.record_flow(r.t,
                           0.,
                           world.kinetic_energy(),
                           {},
                           k,
                           world.max_penetration());
    }



    template <int dim>
    void
    RigidBodiesSimulation<dim>::write_fields()
    {
      Run &r = *run_;
      if (r.step > 0 && r.pcout.is_active())
        {
          std::ostringstream counts;
          counts << "contacts "
                 << r.engine.world->contact_graph().edges().size()
                 << ", overlap " << r.engine.world->max_penetration() << " m";
          r.progress->report(r.step,
                             r.t,
                             parameters.flow.time.time_step,
                             counts.str());
        }
      r.output.write_bodies(*r.engine.world);
    }

    template class RigidBodiesSimulation<2>;
    template class RigidBodiesSimulation<3>;
  } // namespace fbm
} // namespace particulate
