#include <particulate/core/checkpoint.h>
#include <particulate/fbm/particulate_flow_output.h>

#include <deal.II/base/mpi.h>

#include <array>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace fbm {
    template <int dim>
    ParticulateFlowOutput<dim>::ParticulateFlowOutput(
      const core::OutputParameters &parameters,
      MPI_Comm                      comm)
      : parameters(parameters)
      , communicator(comm)
      , flow_output(parameters.directory, "flow")
      , body_output(parameters.directory + "/particles")
      , surface_output(parameters.directory + "/particle_surfaces")
    {}



    template <int dim>
    std::unique_ptr<core::TimeSeriesWriter>
    ParticulateFlowOutput<dim>::open_series(
      const std::string              &name,
      const std::vector<std::string> &columns,
      const bool                      restart,
      const double                    time) const
    {
      const std::string file = parameters.directory + "/" + name + ".dat";
      if (restart
          && dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
        core::truncate_time_series(file, time);
      return std::make_unique<core::TimeSeriesWriter>(file,
                                                      columns,
                                                      communicator,
                                                      restart);
    }



    template <int dim>
    void
    ParticulateFlowOutput<dim>::note_stop(const double       time,
                                          const std::string &reason)
    {
      std::ostringstream note;
      note << "run stopped after t = " << time << " s: " << reason;
      for (const auto &series : body_series)
        series->write_note(note.str());
      for (core::TimeSeriesWriter *series :
           {mesh_series.get(), flow_series.get()})
        if (series != nullptr)
          series->write_note(note.str());
    }



    template <int dim>
    void
    ParticulateFlowOutput<dim>::open_time_series(const unsigned int n_bodies,
                                                 const bool   adapted_mesh,
                                                 const bool   restart,
                                                 const double time)
    {
      shared_files = parameters.shares_particle_files(n_bodies);
      // the walls come after the particles in the engine
      body_output.leave_out_from(n_bodies);
      surface_output.leave_out_from(n_bodies);
      const std::vector<std::string> columns{"time",
                                             "x",
                                             "y",
                                             "z",
                                             "u",
                                             "v",
                                             "w",
                                             "omega_x",
                                             "omega_y",
                                             "omega_z",
                                             "F_x",
                                             "F_y",
                                             "F_z",
                                             "T_x",
                                             "T_y",
                                             "T_z",
                                             "Fc_x",
                                             "Fc_y",
                                             "Fc_z",
                                             "kinetic_energy",
                                             "nodes_inside",
                                             "q_w",
                                             "q_x",
                                             "q_y",
                                             "q_z"};
      if (shared_files)
        {
          std::vector<std::string> with_id = columns;
          with_id.insert(with_id.begin() + 1, "id");
          body_series.push_back(
            open_series("particles", with_id, restart, time));
          surface_output.set_layout(rigid::BodySurfaceWriter::Layout::one_file);
        }
      else
        for (unsigned int i = 0; i < n_bodies; ++i)
          body_series.push_back(open_series("particle_" + std::to_string(i),
                                            columns,
                                            restart,
                                            time));
      if (adapted_mesh)
        mesh_series = open_series("mesh",
                                  {"time",
                                   "min_scaled_jacobian",
                                   "mean_scaled_jacobian",
                                   "max_aspect_ratio",
                                   "held_back_vertices",
                                   "projected_vertices",
                                   "adaptation_steps",
                                   "readapted",
                                   "max_vertex_move"},
                                  restart,
                                  time);
      flow_series = open_series("flow",
                                {"time",
                                 "fluid_kinetic_energy",
                                 "particle_kinetic_energy",
                                 "nonlinear_iterations",
                                 "linear_iterations",
                                 "time_step",
                                 "max_penetration"},
                                restart,
                                time);
    }



    template <int dim>
    void
    ParticulateFlowOutput<dim>::record_mesh(
      const double                          time,
      const deformation::DeformationReport &r)
    {
      if (mesh_series)
        mesh_series->write_row({time,
                                r.quality.min_scaled_jacobian,
                                r.quality.mean_scaled_jacobian,
                                r.quality.max_aspect_ratio,
                                double(r.held_back_vertices),
                                double(r.projected_vertices),
                                double(r.steps),
                                double(r.readapted),
                                r.max_vertex_move});
    }



    template <int dim>
    void
    ParticulateFlowOutput<dim>::record_bodies(
      const double                   time,
      const std::vector<BodyRecord> &bodies)
    {
      AssertDimension(shared_files ? 1 : bodies.size(), body_series.size());
      std::vector<std::vector<double>> rows;
      for (unsigned int i = 0; i < bodies.size(); ++i)
        {
          const BodyRecord   &r = bodies[i];
          std::vector<double> row{time};
          if (shared_files)
            row.push_back(i);
          const std::array<const Eigen::Vector3d *, 6> columns{
            {&r.body->position,
             &r.body->linear_velocity,
             &r.body->angular_velocity,
             &r.load.force,
             &r.load.torque,
             &r.contact_force}};
          for (const Eigen::Vector3d *v : columns)
            for (unsigned int d = 0; d < 3; ++d)
              row.push_back((*v)[d]);
          row.push_back(r.kinetic_energy);
          row.push_back(double(r.nodes_inside));
          const Eigen::Quaterniond &q = r.body->orientation;
          for (const double c : {q.w(), q.x(), q.y(), q.z()})
            row.push_back(c);
          if (shared_files)
            rows.push_back(std::move(row));
          else
            body_series[i]->write_row(row);
        }
      if (shared_files)
        body_series.front()->write_rows(rows);
    }



    template <int dim>
    void
    ParticulateFlowOutput<dim>::record_flow(
      const double                  time,
      const double                  fluid_kinetic_energy,
      const double                  particle_kinetic_energy,
      const fluid::SolveStatistics &statistics,
      const double                  time_step,
      const double                  max_penetration)
    {
      flow_series->write_row({time,
                              fluid_kinetic_energy,
                              particle_kinetic_energy,
                              double(statistics.nonlinear_iterations),
                              double(statistics.linear_iterations),
                              time_step,
                              max_penetration});
    }



    template <int dim>
    void
    ParticulateFlowOutput<dim>::write_particle_table(
      const std::vector<ParticleDescription> &particles)
    {
      if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      const std::string name = parameters.directory + "/particle_set.csv";
      std::ofstream     out(name);
      out << "id,shape,motion,density,volume,mass,x,y,z\n"
          << std::setprecision(12);
      const char *const motions[] = {"free", "fixed", "prescribed", "hinged"};
      for (unsigned int i = 0; i < particles.size(); ++i)
        {
          const ParticleDescription &p      = particles[i];
          const double               volume = p.shape->volume();
          out << i << ',' << p.shape_name << ','
              << motions[static_cast<int>(p.motion)] << ',' << p.density << ','
              << volume << ',' << p.density * volume << ',' << p.position[0]
              << ',' << p.position[1] << ',' << p.position[2] << '\n';
        }
      if (!out)
        throw std::runtime_error("cannot write '" + name
                                 + "'; is the output folder writable?");
    }



    template <int dim>
    void
    ParticulateFlowOutput<dim>::write_fields(
      const fluid::NavierStokes<dim> &flow,
      const rigid::World             &world,
      const unsigned int              step,
      const double                    time)
    {
      if (!parameters.write_vtu)
        return;
      flow_output.write(flow, step, time);
      write_bodies(world);
    }



    template <int dim>
    void
    ParticulateFlowOutput<dim>::write_bodies(const rigid::World &world)
    {
      if (!parameters.write_vtu)
        return;
      if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          body_output.write(world);
          surface_output.write(world);
        }
    }



    template <int dim>
    void
    ParticulateFlowOutput<dim>::save(std::ostream &out) const
    {
      core::write_binary_series(out, flow_output.written());
      core::write_binary_series(out, body_output.written());
      core::write_binary_series(out, surface_output.written());
    }



    template <int dim>
    void
    ParticulateFlowOutput<dim>::load(std::istream &in)
    {
      flow_output.resume(core::read_binary_series(in));
      body_output.resume(core::read_binary_series(in));
      surface_output.resume(core::read_binary_series(in));
    }

    template class ParticulateFlowOutput<2>;
    template class ParticulateFlowOutput<3>;
  } // namespace fbm
} // namespace particulate
