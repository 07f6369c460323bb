#include <particulate/fbm/hydrodynamic_forces.h>
#include <particulate/fluid/flow_diagnostics.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace particulate {
  namespace fbm {
    using namespace dealii;

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
                                | update_quadrature_points | update_JxW_values);
      const unsigned int          n_q = quadrature.size();
      std::vector<Tensor<2, dim>> sigma(n_q);
      std::vector<Tensor<1, dim>> grad_alpha(n_q);

      // cell-local index of the x-velocity DoF at each velocity node
      const unsigned int        n_nodes = interface.nodes_per_cell();
      std::vector<unsigned int> x_dof(n_nodes);
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const auto base = fe.system_to_base_index(i);
          if (base.first.first == 0 && base.first.second == 0)
            x_dof[base.second] = i;
        }

      std::vector<int> bodies_here;
      const auto      &cells = interface.owned_cells();
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          const unsigned int *nodes = interface.cell_nodes(c);
          bodies_here.clear();
          bool has_outside_node = false;
          for (unsigned int k = 0; k < n_nodes; ++k)
            {
              const int b = interface.body_of_node(nodes[k]);
              if (b < 0)
                has_outside_node = true;
              else if (std::find(bodies_here.begin(), bodies_here.end(), b)
                       == bodies_here.end())
                bodies_here.push_back(b);
            }
          // a cut cell of body b has nodes of b and nodes not of b
          if (bodies_here.empty()
              || (!has_outside_node && bodies_here.size() == 1))
            continue;

          fe_values.reinit(cells[c]);
          fluid::cauchy_stress(flow, fe_values, sigma);
          for (const int b : bodies_here)
            {
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  grad_alpha[q] = 0;
                  for (unsigned int k = 0; k < n_nodes; ++k)
                    if (interface.body_of_node(nodes[k]) == b)
                      grad_alpha[q]
                        += fe_values.shape_grad_component(x_dof[k], q, 0);
                }
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  const Tensor<1, dim> f
                    = -(sigma[q] * grad_alpha[q]) * fe_values.JxW(q);
                  Eigen::Vector3d f3  = Eigen::Vector3d::Zero(),
                                  r3  = Eigen::Vector3d::Zero();
                  const Point<dim> &x = fe_values.quadrature_point(q);
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      f3[d] = f[d];
                      r3[d] = x[d] - centres[b][d];
                    }
                  const Eigen::Vector3d t3 = r3.cross(f3);
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      sums[6 * b + d] += f3[d];
                      sums[6 * b + 3 + d] += t3[d];
                    }
                }
            }
        }

      Utilities::MPI::sum(sums, flow.get_communicator(), sums);
      std::vector<HydrodynamicLoad> loads(n_bodies);
      for (unsigned int b = 0; b < n_bodies; ++b)
        for (unsigned int d = 0; d < 3; ++d)
          {
            loads[b].force[d]  = sums[6 * b + d];
            loads[b].torque[d] = sums[6 * b + 3 + d];
          }
      return loads;
    }

    template std::vector<HydrodynamicLoad>
    hydrodynamic_loads(const fluid::NavierStokes<2> &,
                       const FictitiousBoundary<2> &,
                       const std::vector<Eigen::Vector3d> &);
    template std::vector<HydrodynamicLoad>
    hydrodynamic_loads(const fluid::NavierStokes<3> &,
                       const FictitiousBoundary<3> &,
                       const std::vector<Eigen::Vector3d> &);

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
