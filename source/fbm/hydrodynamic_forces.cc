#include <particulate/fbm/hydrodynamic_forces.h>
#include <particulate/fluid/flow_diagnostics.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace particulate {
  namespace fbm {
    using namespace dealii;

    namespace {
      /** Cell-local index of the x-velocity DoF at each of the @p n_nodes
       *  velocity nodes of a cell (the order of FictitiousBoundary's
       *  cell_nodes()). */
      template <int dim>
      std::vector<unsigned int>
      x_dof_of_nodes(const FESystem<dim> &fe, const unsigned int n_nodes)
      {
        std::vector<unsigned int> x_dof(n_nodes);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const auto base = fe.system_to_base_index(i);
            if (base.first.first == 0 && base.first.second == 0)
              x_dof[base.second] = i;
          }
        return x_dof;
      }

      /** The bodies that mark nodes of cell @p c of @p interface, into
       *  @p bodies (each once); returns whether the cell also has a node
       *  outside every body. */
      template <int dim>
      bool
      bodies_of_cell(const FictitiousBoundary<dim> &interface,
                     const unsigned int             c,
                     std::vector<int>              &bodies)
      {
        const unsigned int *nodes = interface.cell_nodes(c);
        bodies.clear();
        bool has_outside_node = false;
        for (unsigned int k = 0; k < interface.nodes_per_cell(); ++k)
          {
            const int b = interface.body_of_node(nodes[k]);
            if (b < 0)
              has_outside_node = true;
            else if (std::find(bodies.begin(), bodies.end(), b) == bodies.end())
              bodies.push_back(b);
          }
        return has_outside_node;
      }

      /** Add force @p f acting at arm @p r to body @p b's entries of
       *  @p sums (force, then torque: 6 per body). */
      void
      add_load(std::vector<double>   &sums,
               const int              b,
               const Eigen::Vector3d &f,
               const Eigen::Vector3d &r)
      {
        const Eigen::Vector3d t = r.cross(f);
        for (unsigned int d = 0; d < 3; ++d)
          {
            sums[6 * b + d] += f[d];
            sums[6 * b + 3 + d] += t[d];
          }
      }

      /** The loads of all bodies from their sums over all ranks. */
      std::vector<HydrodynamicLoad>
      summed_loads(std::vector<double> &sums, const MPI_Comm communicator)
      {
        Utilities::MPI::sum(sums, communicator, sums);
        std::vector<HydrodynamicLoad> loads(sums.size() / 6);
        for (unsigned int b = 0; b < loads.size(); ++b)
          for (unsigned int d = 0; d < 3; ++d)
            {
              loads[b].force[d]  = sums[6 * b + d];
              loads[b].torque[d] = sums[6 * b + 3 + d];
            }
        return loads;
      }
    } // namespace



    template <int dim>
    std::vector<HydrodynamicLoad>
    hydrodynamic_loads(const fluid::NavierStokes<dim>     &flow,
                       const FictitiousBoundary<dim>      &interface,
                       const std::vector<Eigen::Vector3d> &centres)
    {
      const unsigned int  n_bodies = centres.size();
      std::vector<double> sums(6 * n_bodies, 0.);
      if (n_bodies == 0)
        return {};

      const FESystem<dim>        &fe = flow.get_fe();
      const QGauss<dim>           quadrature(3);
      FEValues<dim>               fe_values(flow.get_mapping(),
                              fe,
                              quadrature,
                              update_values | update_gradients
                                | update_JxW_values);
      const unsigned int          n_q = quadrature.size();
      std::vector<Tensor<2, dim>> sigma(n_q);

      const unsigned int              n_nodes = interface.nodes_per_cell();
      const std::vector<unsigned int> x_dof   = x_dof_of_nodes(fe, n_nodes);

      std::vector<int> bodies_here;
      const auto      &cells = interface.owned_cells();
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          const unsigned int *nodes = interface.cell_nodes(c);
          const bool          has_outside_node
            = bodies_of_cell(interface, c, bodies_here);
          // a cut cell of body b has nodes of b and nodes not of b
          if (bodies_here.empty()
              || (!has_outside_node && bodies_here.size() == 1))
            continue;

          fe_values.reinit(cells[c]);
          fluid::cauchy_stress(flow, fe_values, sigma);
          for (unsigned int k = 0; k < n_nodes; ++k)
            {
              const int b = interface.body_of_node(nodes[k]);
              if (b < 0)
                continue;
              // the share of covered node k: -int sigma . grad phi_k
              Tensor<1, dim> share;
              for (unsigned int q = 0; q < n_q; ++q)
                share
                  -= (sigma[q] * fe_values.shape_grad_component(x_dof[k], q, 0))
                     * fe_values.JxW(q);
              Eigen::Vector3d f3 = Eigen::Vector3d::Zero(),
                              r3
                              = interface.node_position(nodes[k]) - centres[b];
              for (unsigned int d = 0; d < dim; ++d)
                f3[d] = share[d];
              if (dim == 2)
                r3[2] = 0.;
              add_load(sums, b, f3, r3);
            }
        }

      return summed_loads(sums, flow.get_communicator());
    }

    template std::vector<HydrodynamicLoad>
    hydrodynamic_loads(const fluid::NavierStokes<2> &,
                       const FictitiousBoundary<2> &,
                       const std::vector<Eigen::Vector3d> &);
    template std::vector<HydrodynamicLoad>
    hydrodynamic_loads(const fluid::NavierStokes<3> &,
                       const FictitiousBoundary<3> &,
                       const std::vector<Eigen::Vector3d> &);

    template <int dim>
    std::vector<HydrodynamicLoad>
    fluid_inertia_loads(
      const fluid::NavierStokes<dim>                       &flow,
      const FictitiousBoundary<dim>                        &interface,
      const typename fluid::NavierStokes<dim>::BlockVector &step_start,
      const double                                          time_step,
      const std::vector<RigidStepMotion>                   &motion)
    {
      const unsigned int n_bodies = motion.size();
      if (n_bodies == 0)
        return {};
      std::vector<double> sums(6 * n_bodies, 0.);

      const FESystem<dim>             &fe = flow.get_fe();
      const QGauss<dim>                quadrature(3);
      FEValues<dim>                    fe_values(flow.get_mapping(),
                              fe,
                              quadrature,
                              update_values | update_gradients
                                | update_quadrature_points | update_JxW_values);
      const unsigned int               n_q = quadrature.size();
      const FEValuesExtractors::Vector velocities(0);
      std::vector<Tensor<1, dim>>      u(n_q), u_start(n_q), w(n_q);
      std::vector<Tensor<2, dim>>      grad_u(n_q);
      std::vector<double>              alpha(n_q);
      const auto *const                mesh_velocity = flow.get_mesh_velocity();
      const double rho = flow.get_parameters().properties.density;

      const unsigned int              n_nodes = interface.nodes_per_cell();
      const std::vector<unsigned int> x_dof   = x_dof_of_nodes(fe, n_nodes);

      std::vector<int> bodies_here;
      const auto      &cells = interface.owned_cells();
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          const unsigned int *nodes = interface.cell_nodes(c);
          bodies_of_cell(interface, c, bodies_here);
          // Every cell with a covered node: the nodes covered during the
          // step may lie in cells that are now entirely inside.
          if (bodies_here.empty())
            continue;

          fe_values.reinit(cells[c]);
          fe_values[velocities].get_function_values(flow.get_solution(), u);
          fe_values[velocities].get_function_values(step_start, u_start);
          fe_values[velocities].get_function_gradients(flow.get_solution(),
                                                       grad_u);
          if (mesh_velocity)
            fe_values[velocities].get_function_values(*mesh_velocity, w);
          for (const int b : bodies_here)
            {
              const RigidStepMotion &m = motion[b];
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  double a = 0.;
                  for (unsigned int k = 0; k < n_nodes; ++k)
                    if (interface.body_of_node(nodes[k]) == b)
                      a += fe_values.shape_value_component(x_dof[k], q, 0);
                  alpha[q] = a;
                }
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  if (alpha[q] == 0.)
                    continue;
                  const Tensor<1, dim> convecting
                    = mesh_velocity ? u[q] - w[q] : u[q];
                  Tensor<1, dim> material = grad_u[q] * convecting;
                  if (time_step > 0.)
                    material += (u[q] - u_start[q]) / time_step;
                  Eigen::Vector3d Du  = Eigen::Vector3d::Zero(),
                                  r   = Eigen::Vector3d::Zero();
                  const Point<dim> &x = fe_values.quadrature_point(q);
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      Du[d] = material[d];
                      r[d]  = x[d] - m.centre[d];
                    }
                  const Eigen::Vector3d rigid
                    = m.acceleration + m.angular_acceleration.cross(r)
                      + m.angular_velocity.cross(m.angular_velocity.cross(r));
                  const Eigen::Vector3d f
                    = -rho * (Du - rigid) * alpha[q] * fe_values.JxW(q);
                  add_load(sums, b, f, r);
                }
            }
        }

      return summed_loads(sums, flow.get_communicator());
    }

    template std::vector<HydrodynamicLoad>
    fluid_inertia_loads(const fluid::NavierStokes<2> &,
                        const FictitiousBoundary<2> &,
                        const fluid::NavierStokes<2>::BlockVector &,
                        const double,
                        const std::vector<RigidStepMotion> &);
    template std::vector<HydrodynamicLoad>
    fluid_inertia_loads(const fluid::NavierStokes<3> &,
                        const FictitiousBoundary<3> &,
                        const fluid::NavierStokes<3>::BlockVector &,
                        const double,
                        const std::vector<RigidStepMotion> &);

    void
    add_mirror_images(std::vector<HydrodynamicLoad> &loads,
                      const std::array<bool, 6>     &mirror_planes)
    {
      for (unsigned int f = 0; f < 6; ++f)
        if (mirror_planes[f])
          for (auto &load : loads)
            {
              const unsigned int a       = f / 2;
              Eigen::Vector3d    image_f = load.force;
              image_f[a]                 = -image_f[a];
              Eigen::Vector3d image_t    = -load.torque;
              image_t[a]                 = load.torque[a];
              load.force += image_f;
              load.torque += image_t;
            }
    }
  } // namespace fbm
} // namespace particulate
