#include <particulate/core/checkpoint.h>
#include <particulate/core/mesh.h>
#include <particulate/core/progress_reporter.h>
#include <particulate/core/time_series_writer.h>
#include <particulate/fbm/body_adapted_mesh.h>
#include <particulate/fbm/fictitious_boundary.h>
#include <particulate/fbm/hydrodynamic_forces.h>
#include <particulate/fbm/particle_shape.h>
#include <particulate/fbm/particulate_flow_simulation.h>
#include <particulate/fluid/flow_diagnostics.h>
#include <particulate/fluid/flow_output.h>
#include <particulate/fluid/navier_stokes.h>
#include <particulate/geometry/half_space.h>
#include <particulate/rigid/vtp_writer.h>
#include <particulate/rigid/world.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

namespace particulate {
  namespace fbm {
    using namespace dealii;

    namespace {
      /** Shortest cell edge of the whole mesh (all ranks). */
      template <int dim>
      double
      smallest_cell_edge(const Triangulation<dim> &tria, MPI_Comm comm)
      {
        double h = std::numeric_limits<double>::max();
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
            h = std::min(h, cell->minimum_vertex_distance());
        return Utilities::MPI::min(h, comm);
      }

      /** The marking named by 'Covered nodes' (a validated selection). */
      template <int dim>
      typename FictitiousBoundary<dim>::Marking
      marking_from_name(const std::string &name)
      {
        using Marking = typename FictitiousBoundary<dim>::Marking;
        if (name == "nearest")
          return Marking::nearest;
        if (name == "halfway")
          return Marking::halfway;
        return Marking::inside;
      }
    } // namespace

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
    ParticulateFlowSummary
    ParticulateFlowSimulation<dim>::run()
    {
      ConditionalOStream pcout(std::cout,
                               Utilities::MPI::this_mpi_process(communicator)
                                 == 0);
      TimerOutput        timer(communicator,
                        pcout,
                        TimerOutput::never,
                        TimerOutput::wall_times);
      const auto        &flow_p     = parameters.flow;
      const auto        &particle_p = parameters.particles;
      const auto        &time_p     = flow_p.time;
      if (time_p.scheme == core::TimeParameters::Scheme::steady
          && particle_p.motion != ParticleParameters::Motion::fixed)
        throw std::runtime_error(
          parameter_file
          + ": moving particles need a time-dependent scheme: set 'Scheme' "
            "in subsection 'Time' to 'fractional-step theta' (or set 'Motion "
            "= fixed' in subsection 'Particles').");
      if (particle_p.n_particles() == 0)
        throw std::runtime_error(
          parameter_file
          + ": a 'particulate flow' run needs at least one particle: set "
            "'Positions' in subsection 'Particles'.");

      parallel::fullydistributed::Triangulation<dim> tria(communicator);
      {
        TimerOutput::Scope scope(timer, "mesh");
        core::create_mesh(flow_p.mesh, tria);
      }
      flow_p.fluid.boundary_conditions.check(core::global_boundary_ids(tria),
                                             parameter_file);
      const auto [box_lower, box_upper]
        = core::global_bounding_box(tria, communicator);
      for (unsigned int i = 0; i < particle_p.n_particles(); ++i)
        for (unsigned int d = 0; d < dim; ++d)
          if (particle_p.positions[i][d] < box_lower[d]
              || particle_p.positions[i][d] > box_upper[d])
            throw std::runtime_error(
              parameter_file
              + ": subsection 'Particles', entry 'Positions': " + "particle "
              + std::to_string(i) + " lies outside the mesh's bounding box.");
      // mirror planes: the centres lie on them
      unsigned int n_images = 1;
      for (unsigned int f = 0; f < 2 * dim; ++f)
        if (particle_p.symmetry_planes[f])
          {
            n_images *= 2;
            const unsigned int a     = f / 2;
            const double       plane = f % 2 ? box_upper[a] : box_lower[a];
            for (unsigned int i = 0; i < particle_p.n_particles(); ++i)
              if (std::abs(particle_p.positions[i][a] - plane)
                  > 1e-9 * (box_upper[a] - box_lower[a]))
                throw std::runtime_error(
                  parameter_file
                  + ": subsection 'Particles', entry 'Symmetry planes': "
                    "particle "
                  + std::to_string(i) + " does not lie on the mirror plane "
                  + "xyz"[a] + " = " + std::to_string(plane)
                  + "; put its centre there or remove the plane.");
          }

      const bool prescribed
        = particle_p.motion == ParticleParameters::Motion::prescribed;
      const std::unique_ptr<Function<dim>> displacement
        = prescribed ? particle_p.prescribed_displacement.template create<dim>(
            dim,
            "Particles / Prescribed displacement") :
                       nullptr;
      // where a prescribed particle is at time @p t, and how fast it moves
      // (central difference of the displacement: the expression is smooth)
      const auto prescribed_state
        = [&](const Eigen::Vector3d &start, const double t) {
            const double    h = 1e-6 * std::max(1., time_p.end_time);
            Eigen::Vector3d x = start, v = Eigen::Vector3d::Zero();
            for (unsigned int d = 0; d < dim; ++d)
              {
                displacement->set_time(t);
                x[d] += displacement->value(Point<dim>(), d);
                displacement->set_time(t + h);
                v[d] = displacement->value(Point<dim>(), d);
                displacement->set_time(t - h);
                v[d] = (v[d] - displacement->value(Point<dim>(), d)) / (2. * h);
              }
            return std::make_pair(x, v);
          };
      std::vector<Eigen::Vector3d> initial_centres = particle_p.positions;
      if (prescribed)
        for (auto &c : initial_centres)
          c = prescribed_state(c, 0.).first;

      // r-adaptivity: the mesh resolves the particles where they start
      // the one shape every body's description produces: the rigid body,
      // the interface and the mesh deformation all read it
      const std::shared_ptr<const geometry::Shape> shape
        = make_particle_shape(particle_p);
      std::vector<geometry::Pose> initial_poses;
      for (const auto &c : initial_centres)
        initial_poses.emplace_back(Eigen::Matrix3d::Identity(), c);
      std::unique_ptr<BodyAdaptedMesh<dim>> adapted_mesh;
      deformation::DeformationReport        initial_report;
      const bool                            deforming
        = parameters.deformation.method
            != deformation::DeformationParameters::Method::none
          || parameters.deformation.following
               == deformation::DeformationParameters::Following::
                 carry_neighbourhood;
      if (deforming)
        {
          TimerOutput::Scope scope(timer, "mesh deformation");
          adapted_mesh = std::make_unique<BodyAdaptedMesh<dim>>(
            flow_p.mesh,
            parameters.deformation,
            std::vector<std::shared_ptr<const geometry::Shape>>(
              initial_poses.size(),
              shape),
            tria);
          initial_report     = adapted_mesh->adapt(initial_poses);
          const auto &report = initial_report;
          pcout << "Mesh deformation: " << adapted_mesh->mesh().method_name()
                << ", min scaled Jacobian "
                << report.quality.min_scaled_jacobian
                << ", largest aspect ratio " << report.quality.max_aspect_ratio
                << std::endl;
        }

      fluid::NavierStokes<dim> flow(flow_p.fluid, tria, timer);
      flow.setup_dofs();
      flow.set_initial_condition(0.);

      // --- rigid bodies ------------------------------------------------
      const double rho_f = flow_p.fluid.properties.density;
      const double rho_p = particle_p.density;
      const bool   free = particle_p.motion == ParticleParameters::Motion::free;
      const double volume = shape->volume();
      // Added-mass correction: the engine integrates the particle with mass
      // m + m_a (density rho_p + C rho_f); the force gets + m_a a_old.
      const double rho_engine
        = rho_p + particle_p.added_mass_coefficient * rho_f;

      rigid::WorldParameters world_p;
      world_p.gravity = Eigen::Vector3d::Zero(); // applied as (dM) g below
      world_p.contact_solver
        = rigid::contact_solver_type_from_string(particle_p.contact_solver);
      world_p.substeps       = particle_p.substeps;
      world_p.contact_offset = particle_p.contact_distance ?
                                 *particle_p.contact_distance :
                                 smallest_cell_edge(tria, communicator);
      rigid::World    world(world_p);
      rigid::Material material;
      material.name            = "particle";
      material.density         = rho_engine;
      material.restitution     = particle_p.restitution;
      material.static_friction = material.dynamic_friction
        = particle_p.friction;
      const unsigned int particle_material = world.add_material(material);
      rigid::Material    wall_material     = material;
      wall_material.name                   = "wall";
      const unsigned int wall_material_id  = world.add_material(wall_material);

      std::vector<rigid::BodyId> ids;
      for (unsigned int i = 0; i < particle_p.n_particles(); ++i)
        {
          ids.push_back(world.add_body(shape,
                                       particle_material,
                                       initial_centres[i],
                                       Eigen::Quaterniond::Identity(),
                                       !free));
          // locked inside the engine, so that contacts cannot spend their
          // impulse on a rotation the coupling would discard
          world.body(ids.back()).lock_rotation(particle_p.locked_rotation);
          if (free && !particle_p.velocities.empty())
            world.body(ids.back()).linear_velocity = particle_p.velocities[i];
          if (prescribed)
            world.body(ids.back()).linear_velocity
              = prescribed_state(particle_p.positions[i], 0.).second;
        }
      for (unsigned int d = 0; d < dim; ++d)
        {
          Eigen::Vector3d n = Eigen::Vector3d::Zero();
          n[d]              = 1.;
          // half-space {n.p <= offset}; n points into the fluid
          if (particle_p.walls[2 * d])
            world.add_body(std::make_shared<geometry::HalfSpace>(n,
                                                                 box_lower[d]),
                           wall_material_id,
                           Eigen::Vector3d::Zero(),
                           Eigen::Quaterniond::Identity(),
                           true);
          if (particle_p.walls[2 * d + 1])
            world.add_body(std::make_shared<geometry::HalfSpace>(-n,
                                                                 -box_upper[d]),
                           wall_material_id,
                           Eigen::Vector3d::Zero(),
                           Eigen::Quaterniond::Identity(),
                           true);
        }

      FictitiousBoundary<dim> interface(flow);
      interface.set_marking(marking_from_name<dim>(particle_p.covered_nodes));
      interface.setup();
      // the engine marks the nodes inside only: 'auto' keeps the hash grid
      // for the other markings (checked for 'cuda' when parsing)
      if (particle_p.containment_backend == "cuda"
          || (particle_p.containment_backend == "auto"
              && particle_p.covered_nodes == "inside"
              && particle_p.shape != ParticleParameters::Shape::cylinder
              && cuda::ContainmentEngine::cuda_device_available()))
        interface.use_containment_engine(cuda::Backend::cuda);
      std::vector<typename FictitiousBoundary<dim>::Body> interface_bodies;
      for (const auto id : ids)
        interface_bodies.push_back({&world.body(id)});

      pcout << "Mesh: " << tria.n_global_active_cells() << " cells, "
            << flow.n_dofs() << " DoFs (" << flow.n_velocity_dofs()
            << " velocity + " << flow.n_dofs() - flow.n_velocity_dofs()
            << " pressure) on " << Utilities::MPI::n_mpi_processes(communicator)
            << " rank(s); " << particle_p.n_particles()
            << " particle(s); contact distance " << world_p.contact_offset
            << " m\nContainment: " << interface.containment_method()
            << std::endl;

      // --- state ---------------------------------------------------------
      const unsigned int n = ids.size();
      // the rigid velocities the covered nodes were last given, and those
      // of the previous step's solve (what the flow holds there at the
      // start of a step): their difference is the rigid acceleration that
      // the fluid inside a body saw ('Force integral = stress and inertia')
      std::vector<Eigen::Vector3d> imposed_velocity(n), imposed_angular(n);
      std::vector<Eigen::Vector3d> solved_velocity(n), solved_angular(n);
      std::vector<Eigen::Vector3d> acceleration(n, Eigen::Vector3d::Zero()),
        angular_acceleration(n, Eigen::Vector3d::Zero());
      std::vector<HydrodynamicLoad> loads(n);
      ParticulateFlowSummary        summary;
      summary.n_dofs = flow.n_dofs();
      summary.max_speed.assign(n, 0.);
      summary.time_of_max_speed.assign(n, 0.);
      double       t    = 0.;
      double       dt   = time_p.time_step;
      unsigned int step = 0;

      const std::string     &dir = flow_p.output.directory;
      fluid::FlowOutput<dim> flow_output(dir, "flow");
      rigid::VtpWriter       body_output(dir + "/particles");
      const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;

      // --- checkpoint ----------------------------------------------------
      // Everything the next step reads; the rest (mesh, constraints,
      // covered nodes) follows from the case file and the bodies.
      const core::Checkpoint checkpoint(dir, communicator);
      const auto             save_checkpoint = [&]() {
        TimerOutput::Scope scope(timer, "checkpoint");
        checkpoint.save(
          [&](std::ostream &out) {
            core::write_binary(out, t);
            core::write_binary(out, dt);
            core::write_binary<unsigned long>(out, step);
            core::write_binary<unsigned long>(out, n);
            for (unsigned int i = 0; i < n; ++i)
              {
                core::write_binary(out, acceleration[i]);
                core::write_binary(out, angular_acceleration[i]);
                core::write_binary(out, loads[i].force);
                core::write_binary(out, loads[i].torque);
                core::write_binary(out, summary.max_speed[i]);
                core::write_binary(out, summary.time_of_max_speed[i]);
                core::write_binary(out, solved_velocity[i]);
                core::write_binary(out, solved_angular[i]);
              }
            flow.save_state(out);
            world.save_state(out);
            if (adapted_mesh)
              adapted_mesh->save(out);
            core::write_binary_series(out, flow_output.written());
            core::write_binary_series(out, body_output.written());
          },
          t,
          step);
        // the continued run rebuilds its preconditioners here, as a
        // restarted one must: both then compute the same numbers
        flow.reset_preconditioners();
      };
      if (parameters.restart)
        {
          if (time_p.scheme == core::TimeParameters::Scheme::steady)
            throw std::runtime_error(
              parameter_file
              + ": --restart continues time-dependent runs; this case is "
                "steady.");
          checkpoint.load([&](std::istream &in) {
            t    = core::read_binary<double>(in);
            dt   = core::read_binary<double>(in);
            step = core::read_binary<unsigned long>(in);
            if (core::read_binary<unsigned long>(in) != n)
              throw std::runtime_error(
                "it has another number of particles than 'Positions'");
            for (unsigned int i = 0; i < n; ++i)
              {
                acceleration[i] = core::read_binary<Eigen::Vector3d>(in);
                angular_acceleration[i]
                  = core::read_binary<Eigen::Vector3d>(in);
                loads[i].force       = core::read_binary<Eigen::Vector3d>(in);
                loads[i].torque      = core::read_binary<Eigen::Vector3d>(in);
                summary.max_speed[i] = core::read_binary<double>(in);
                summary.time_of_max_speed[i] = core::read_binary<double>(in);
                solved_velocity[i] = core::read_binary<Eigen::Vector3d>(in);
                solved_angular[i]  = core::read_binary<Eigen::Vector3d>(in);
              }
            flow.load_state(in);
            world.load_state(in);
            if (adapted_mesh)
              {
                // the mesh velocity this sets is replaced before the next
                // step uses one; the geometric matrices are what counts
                flow.move_mesh([&]() { adapted_mesh->load(in); }, dt);
                // V-cycles for the loaded positions, as the continued run
                // has them after its checkpoint ('keep' would otherwise go
                // on with those of the undeformed mesh)
                flow.reset_preconditioners();
                interface.setup();
              }
            flow_output.resume(core::read_binary_series(in));
            body_output.resume(core::read_binary_series(in));
          });
          pcout << "Restarting from " << checkpoint.directory()
                << " at t = " << t << " s (step " << step << ")" << std::endl;
          // A fixed step comes from the parameter file: the checkpoint's may
          // be a last step shortened to meet the old 'End time', and a user
          // may have changed 'Time step' on purpose. An adaptive step goes
          // on from where it was.
          if (!time_p.adaptive && dt != time_p.time_step)
            {
              pcout << "Time step: " << time_p.time_step << " s from "
                    << parameter_file
                    << " (the checkpointed run's last step: " << dt << " s)"
                    << std::endl;
              dt = time_p.time_step;
            }
        }

      // --- output --------------------------------------------------------
      // a restart continues the series, without the rows that the cut-off
      // run wrote after its checkpoint
      const auto series_file = [&](const std::string &name) {
        const std::string file = dir + "/" + name + ".dat";
        if (parameters.restart && root)
          core::truncate_time_series(file, t);
        return file;
      };
      std::vector<std::unique_ptr<core::TimeSeriesWriter>> particle_series;
      for (unsigned int i = 0; i < ids.size(); ++i)
        particle_series.push_back(std::make_unique<core::TimeSeriesWriter>(
          series_file("particle_" + std::to_string(i)),
          std::vector<std::string>{
            "time",        "x",    "y",       "z",       "u",
            "v",           "w",    "omega_x", "omega_y", "omega_z",
            "F_x",         "F_y",  "F_z",     "T_x",     "T_y",
            "T_z",         "Fc_x", "Fc_y",    "Fc_z",    "kinetic_energy",
            "nodes_inside"},
          communicator,
          parameters.restart));
      // mesh deformation: how good the adapted mesh is, every step
      std::unique_ptr<core::TimeSeriesWriter> mesh_series;
      if (adapted_mesh)
        mesh_series = std::make_unique<core::TimeSeriesWriter>(
          series_file("mesh"),
          std::vector<std::string>{"time",
                                   "min_scaled_jacobian",
                                   "mean_scaled_jacobian",
                                   "max_aspect_ratio",
                                   "held_back_vertices",
                                   "projected_vertices",
                                   "adaptation_steps",
                                   "readapted",
                                   "max_vertex_move"},
          communicator,
          parameters.restart);
      const auto record_mesh
        = [&](const double t, const deformation::DeformationReport &r) {
            if (mesh_series)
              mesh_series->write_row({t,
                                      r.quality.min_scaled_jacobian,
                                      r.quality.mean_scaled_jacobian,
                                      r.quality.max_aspect_ratio,
                                      double(r.held_back_vertices),
                                      double(r.projected_vertices),
                                      double(r.steps),
                                      double(r.readapted),
                                      r.max_vertex_move});
          };
      core::TimeSeriesWriter flow_series(series_file("flow"),
                                         {"time",
                                          "fluid_kinetic_energy",
                                          "particle_kinetic_energy",
                                          "nonlinear_iterations",
                                          "linear_iterations",
                                          "time_step"},
                                         communicator,
                                         parameters.restart);

      // from the shape, not the engine's body: a fixed or prescribed
      // particle is an immovable body of infinite inertia in the engine
      const auto true_inertia_world = [&](const rigid::RigidBody &b) {
        const Eigen::Matrix3d R = b.rotation();
        return Eigen::Matrix3d(R * (rho_p * b.shape().unit_inertia())
                               * R.transpose());
      };
      const auto particle_energy = [&](const rigid::RigidBody &b) {
        return 0.5 * rho_p * volume * b.linear_velocity.squaredNorm()
               + 0.5
                   * b.angular_velocity.dot(true_inertia_world(b)
                                            * b.angular_velocity);
      };

      const auto record = [&](const double                  t,
                              const double                  dt,
                              const fluid::SolveStatistics &stats) {
        TimerOutput::Scope               scope(timer, "diagnostics");
        double                           particles_energy = 0.;
        const std::vector<unsigned long> nodes_inside
          = interface.n_nodes_inside(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            const rigid::RigidBody &b       = world.body(ids[i]);
            Eigen::Vector3d         contact = Eigen::Vector3d::Zero();
            if (t > 0.)
              for (const auto &f : world.contact_forces(ids[i]))
                contact += f.force;
            const double e = particle_energy(b);
            particles_energy += e;
            std::vector<double>                          row{t};
            const std::array<const Eigen::Vector3d *, 6> columns{
              {&b.position,
               &b.linear_velocity,
               &b.angular_velocity,
               &loads[i].force,
               &loads[i].torque,
               &contact}};
            for (const Eigen::Vector3d *v : columns)
              for (unsigned int d = 0; d < 3; ++d)
                row.push_back((*v)[d]);
            row.push_back(e);
            row.push_back(double(nodes_inside[i]));
            particle_series[i]->write_row(row);
            if (b.linear_velocity.norm() > summary.max_speed[i])
              {
                summary.max_speed[i]         = b.linear_velocity.norm();
                summary.time_of_max_speed[i] = t;
              }
          }
        flow_series.write_row({t,
                               n_images * fluid::kinetic_energy(flow),
                               particles_energy,
                               double(stats.nonlinear_iterations),
                               double(stats.linear_iterations),
                               dt});
      };
      const auto write_fields = [&](const unsigned int step, const double t) {
        if (!flow_p.output.write_vtu)
          return;
        TimerOutput::Scope scope(timer, "output");
        flow_output.write(flow, step, t);
        if (root)
          body_output.write(world);
      };
      // fluid loads on the bodies, completed across mirror planes
      // centres the interface was last marked around
      std::vector<Eigen::Vector3d> load_centres(n);
      const auto                   record_imposed = [&]() {
        for (unsigned int i = 0; i < n; ++i)
          {
            imposed_velocity[i] = world.body(ids[i]).linear_velocity;
            imposed_angular[i] = world.body(ids[i]).angular_velocity;
          }
      };
      // 'Force integral = stress and inertia': the flow at the start of the
      // step, and the bodies' rigid accelerations over it
      std::optional<typename fluid::NavierStokes<dim>::BlockVector> step_start;
      const auto update_loads = [&](const double k) {
        TimerOutput::Scope scope(timer, "fbm: forces");
        loads = hydrodynamic_loads(flow, interface, load_centres);
        if (particle_p.force_includes_fluid_inertia)
          {
            std::vector<RigidStepMotion> motion(n);
            for (unsigned int i = 0; i < n; ++i)
              {
                motion[i].centre           = load_centres[i];
                motion[i].angular_velocity = imposed_angular[i];
                if (k > 0.)
                  {
                    motion[i].acceleration
                      = (imposed_velocity[i] - solved_velocity[i]) / k;
                    motion[i].angular_acceleration
                      = (imposed_angular[i] - solved_angular[i]) / k;
                  }
              }
            const auto inertia
              = fluid_inertia_loads(flow,
                                    interface,
                                    k > 0. ? *step_start : flow.get_solution(),
                                    k,
                                    motion);
            for (unsigned int i = 0; i < n; ++i)
              {
                loads[i].force += inertia[i].force;
                loads[i].torque += inertia[i].torque;
              }
          }
        add_mirror_images(loads, particle_p.symmetry_planes);
      };
      const auto impose_particle_velocities = [&]() {
        TimerOutput::Scope scope(timer, "fbm: containment and constraints");
        for (unsigned int i = 0; i < n; ++i)
          load_centres[i] = world.body(ids[i]).position;
        record_imposed();
        interface.classify(interface_bodies);
        flow.set_fictitious_boundary_values(
          interface.constraint_values(interface_bodies));
      };

      // The interface a free particle shows the fluid over a step:
      // 'Constraint velocity = extrapolated' gives the covered nodes
      // U_n + k a_n, 'Interface position = midpoint' marks them around
      // X_n + k/2 (U_n + k/2 a_n); the bodies themselves keep their state.
      // The loads are then taken about the centres that were marked. It
      // replaces the marking at X_n made at the end of the previous step
      // (which the output at t_n shows); at the start of the step because
      // only then is the step size k known.
      const bool predict_interface
        = free && !prescribed
          && (particle_p.extrapolate_constraint_velocity
              || particle_p.midpoint_interface_position);
      const auto impose_predicted_interface = [&](const double k) {
        TimerOutput::Scope scope(timer, "fbm: containment and constraints");
        std::vector<
          std::tuple<Eigen::Vector3d, Eigen::Vector3d, Eigen::Vector3d>>
          current;
        for (unsigned int i = 0; i < n; ++i)
          {
            rigid::RigidBody &b = world.body(ids[i]);
            current.emplace_back(b.position,
                                 b.linear_velocity,
                                 b.angular_velocity);
            if (particle_p.midpoint_interface_position)
              b.position
                += 0.5 * k * (b.linear_velocity + 0.5 * k * acceleration[i]);
            if (particle_p.extrapolate_constraint_velocity)
              {
                b.linear_velocity += k * acceleration[i];
                b.angular_velocity += k * angular_acceleration[i];
              }
            load_centres[i] = b.position;
          }
        if (particle_p.midpoint_interface_position)
          interface.classify(interface_bodies);
        auto values = interface.constraint_values(interface_bodies);
        record_imposed();
        for (unsigned int i = 0; i < n; ++i)
          {
            rigid::RigidBody &b = world.body(ids[i]);
            std::tie(b.position, b.linear_velocity, b.angular_velocity)
              = current[i];
          }
        flow.set_fictitious_boundary_values(std::move(values));
      };

      core::ProgressReporter progress(
        pcout.get_stream(),
        t,
        time_p.scheme == core::TimeParameters::Scheme::steady ?
          1. :
          time_p.end_time);
      const auto counts = [&](const fluid::SolveStatistics &s) {
        char                   buffer[160];
        const Eigen::Vector3d &u = world.body(ids[0]).linear_velocity;
        std::snprintf(buffer,
                      sizeof(buffer),
                      "nonlinear %2u%s linear %4u  |U_0| %.5g m/s",
                      s.nonlinear_iterations,
                      s.used_fixed_point ? "*" : " ",
                      s.linear_iterations,
                      u.norm());
        return std::string(buffer);
      };

      // Moving particles on an adapted mesh, and prescribed motion: the
      // mesh and the interface are updated at the start of each step.
      const bool mesh_follows = adapted_mesh && !particle_p.motion_is_fixed();
      // The start of every step: bodies at t_n (free) or t_n+1
      // (prescribed) -> adapted mesh and its velocity -> interface.
      const auto move_with_bodies = [&](const double t_new, const double k) {
        if (prescribed)
          for (unsigned int i = 0; i < n; ++i)
            {
              rigid::RigidBody &b = world.body(ids[i]);
              std::tie(b.position, b.linear_velocity)
                = prescribed_state(particle_p.positions[i], t_new);
            }
        if (mesh_follows)
          {
            deformation::DeformationReport report;
            {
              TimerOutput::Scope          scope(timer, "mesh deformation");
              std::vector<geometry::Pose> poses;
              for (const auto id : ids)
                poses.emplace_back(world.body(id).orientation,
                                   world.body(id).position);
              report = adapted_mesh->follow(poses, flow, k);
            }
            record_mesh(t_new, report);
            TimerOutput::Scope scope(timer, "fbm: containment and constraints");
            interface.setup();
          }
        if (prescribed || mesh_follows)
          impose_particle_velocities();
      };

      impose_particle_velocities();
      if (!parameters.restart)
        {
          solved_velocity = imposed_velocity;
          solved_angular  = imposed_angular;
          record_mesh(0., initial_report);
          record(0., dt, fluid::SolveStatistics());
          write_fields(0, 0.);
        }
      const auto &checkpoint_p    = parameters.checkpoint;
      double      last_checkpoint = 0.; // wall seconds
      const auto  checkpoint_due  = [&](const bool last) {
        if (!checkpoint_p.enabled())
          return false;
        // rank 0's clock decides, so that all ranks agree
        const double minutes
          = Utilities::MPI::broadcast(communicator,
                                      progress.elapsed_seconds()
                                        - last_checkpoint,
                                      0)
            / 60.;
        return last
               || (checkpoint_p.step_interval > 0
                   && step % checkpoint_p.step_interval == 0)
               || (checkpoint_p.wall_minutes > 0.
                   && minutes >= checkpoint_p.wall_minutes);
      };

      if (time_p.scheme == core::TimeParameters::Scheme::steady)
        {
          // fixed obstacles in steady flow: one nonlinear solve
          const auto stats
            = flow.advance(0., 0., core::TimeParameters::Scheme::steady);
          update_loads(0.);
          step = 1;
          record(0., 0., stats);
          write_fields(1, 0.);
          if (pcout.is_active())
            progress.report(1, 1., 0., counts(stats));
        }
      else
        {
          const double eps = 1e-12 * std::max(1., time_p.end_time);
          while (t < time_p.end_time - eps)
            {
              dt = std::min(dt, time_p.end_time - t);
              // everything of a step but output and diagnostics
              std::optional<TimerOutput::Scope> step_scope;
              step_scope.emplace(timer, "coupled step (total)");
              const auto step_start_time = std::chrono::steady_clock::now();
              move_with_bodies(t + dt, dt);
              if (predict_interface)
                impose_predicted_interface(dt);
              if (particle_p.force_includes_fluid_inertia)
                step_start = flow.get_solution();
              // 1.-2. fluid with the particles' interface of this step
              const fluid::SolveStatistics stats
                = flow.advance(t, dt, time_p.scheme);
              summary.nonlinear_iterations += stats.nonlinear_iterations;
              summary.linear_iterations += stats.linear_iterations;
              // 3. loads from the new flow field, with the interface the
              //    fluid saw over the step
              update_loads(dt);
              solved_velocity = imposed_velocity;
              solved_angular  = imposed_angular;
              // 4. rigid bodies
              {
                TimerOutput::Scope           scope(timer, "rigid bodies");
                std::vector<Eigen::Vector3d> old_velocity(n),
                  old_angular_velocity(n), old_position(n);
                std::vector<Eigen::Quaterniond> old_orientation(n);
                for (unsigned int i = 0; i < n; ++i)
                  {
                    rigid::RigidBody &b     = world.body(ids[i]);
                    old_velocity[i]         = b.linear_velocity;
                    old_angular_velocity[i] = b.angular_velocity;
                    old_position[i]         = b.position;
                    old_orientation[i]      = b.orientation;
                    if (!free)
                      continue;
                    const double    m_true = rho_p * volume;
                    const double    m_a    = b.mass() - m_true;
                    Eigen::Vector3d force
                      = loads[i].force
                        + (rho_p - rho_f) * volume * particle_p.gravity
                        + m_a * acceleration[i];
                    const Eigen::Matrix3d I_a
                      = b.inertia_world() - true_inertia_world(b);
                    Eigen::Vector3d torque
                      = loads[i].torque + I_a * angular_acceleration[i];
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        if (particle_p.locked_translation[d])
                          force[d] = 0.;
                        if (particle_p.locked_rotation[d])
                          torque[d] = 0.;
                      }
                    world.set_external_force_and_torque(ids[i], force, torque);
                  }
                world.step(dt);
                for (unsigned int i = 0; i < n && free; ++i)
                  {
                    rigid::RigidBody &b = world.body(ids[i]);
                    // symmetry and planar motion: undo what contacts or
                    // rounding did along the locked axes
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        if (particle_p.locked_translation[d])
                          {
                            b.linear_velocity[d] = 0.;
                            b.position[d]        = old_position[i][d];
                          }
                        if (particle_p.locked_rotation[d])
                          b.angular_velocity[d] = 0.;
                      }
                    if (particle_p.locked_rotation[0]
                        && particle_p.locked_rotation[1]
                        && particle_p.locked_rotation[2])
                      b.orientation = old_orientation[i];
                    if (!b.linear_velocity.allFinite()
                        || !b.position.allFinite())
                      throw std::runtime_error(
                        "Particle " + std::to_string(i)
                        + " has a non-finite velocity at t = "
                        + std::to_string(t + dt)
                        + " s: the coupling diverged. Reduce 'Time step' in "
                          "subsection 'Time' or raise 'Added mass "
                          "coefficient' in subsection 'Particles'.");
                    acceleration[i]
                      = (b.linear_velocity - old_velocity[i]) / dt;
                    angular_acceleration[i]
                      = (b.angular_velocity - old_angular_velocity[i]) / dt;
                    // A contact that stops the particle stops its added
                    // mass too. Fed back as m_a a_old, that deceleration
                    // would throw the particle off the wall next step (a
                    // bounce at restitution 0): the lag keeps no
                    // acceleration away from a touching surface.
                    for (const auto &f : world.contact_forces(ids[i]))
                      if (f.force.norm() > 0.)
                        {
                          const Eigen::Vector3d n = f.force.normalized();
                          const double          a = acceleration[i].dot(n);
                          if (a > 0.)
                            acceleration[i] -= a * n;
                        }
                  }
              }
              t += dt;
              ++step;
              // 1. (next step) the interface at t_n+1
              if (!(prescribed || mesh_follows))
                impose_particle_velocities();
              step_scope.reset();
              summary.step_seconds.push_back(
                std::chrono::duration<double>(std::chrono::steady_clock::now()
                                              - step_start_time)
                  .count());
              record(t, dt, stats);
              const bool last = t >= time_p.end_time - eps;
              if ((flow_p.output.interval > 0
                   && step % flow_p.output.interval == 0)
                  || last)
                write_fields(step, t);
              if (pcout.is_active())
                progress.report(step, t, dt, counts(stats));
              if (time_p.adaptive)
                dt = time_p.next_time_step(dt, flow.cfl_number(dt));
              if (checkpoint_due(last))
                {
                  save_checkpoint();
                  last_checkpoint = progress.elapsed_seconds();
                }
            }
        }

      summary.n_steps      = step;
      summary.end_time     = t;
      summary.wall_seconds = progress.elapsed_seconds();
      MPI_Allreduce(MPI_IN_PLACE,
                    summary.step_seconds.data(),
                    static_cast<int>(summary.step_seconds.size()),
                    MPI_DOUBLE,
                    MPI_MAX,
                    communicator);
      for (unsigned int i = 0; i < n; ++i)
        {
          const rigid::RigidBody &b = world.body(ids[i]);
          summary.position.push_back(b.position);
          summary.velocity.push_back(b.linear_velocity);
          summary.force.push_back(loads[i].force);
          summary.torque.push_back(loads[i].torque);
        }
      pcout << "\nFinal: particle 0 at (" << summary.position[0].transpose()
            << ") m, velocity (" << summary.velocity[0].transpose()
            << ") m/s, fluid force (" << summary.force[0].transpose()
            << ") N\nResults are in " << dir
            << "/ (flow.pvd, particles.pvd, particle_*.dat, flow.dat)"
            << std::endl;
      timer.print_wall_time_statistics(communicator);
      fluid::collect_run_profile(timer, flow, communicator, summary);
      if (flow_inspector)
        flow_inspector(flow);
      return summary;
    }

    template class ParticulateFlowSimulation<2>;
    template class ParticulateFlowSimulation<3>;
  } // namespace fbm
} // namespace particulate
