#include <particulate/fluid/flow_diagnostics.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <stdexcept>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    Tensor<1, dim>
    surface_force(const NavierStokes<dim>         &flow,
                  const std::vector<unsigned int> &boundary_ids)
    {
      const QGauss<dim - 1>            quadrature(4);
      FEFaceValues<dim>                fe_face_values(flow.get_mapping(),
                                       flow.get_fe(),
                                       quadrature,
                                       update_values | update_gradients
                                         | update_normal_vectors
                                         | update_JxW_values);
      const FEValuesExtractors::Vector velocities(0);
      const FEValuesExtractors::Scalar pressure(dim);
      std::vector<Tensor<2, dim>>      grad_u(quadrature.size());
      std::vector<double>              p(quadrature.size());
      const auto                      &viscosity = flow.get_viscosity_model();

      Tensor<1, dim> force;
      for (const auto &cell : flow.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() && cell->at_boundary())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary()
                && std::find(boundary_ids.begin(),
                             boundary_ids.end(),
                             cell->face(f)->boundary_id())
                     != boundary_ids.end())
              {
                fe_face_values.reinit(cell, f);
                fe_face_values[velocities]
                  .get_function_gradients(flow.get_solution(), grad_u);
                fe_face_values[pressure]
                  .get_function_values(flow.get_solution(), p);
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  {
                    const SymmetricTensor<2, dim> D = symmetrize(grad_u[q]);
                    const double                  mu
                      = viscosity.viscosity(std::sqrt(2. * D * D));
                    const Tensor<2, dim> sigma
                      = -p[q] * unit_symmetric_tensor<dim>() + 2. * mu * D;
                    force -= sigma * fe_face_values.normal_vector(q)
                             * fe_face_values.JxW(q);
                  }
              }
      for (unsigned int d = 0; d < dim; ++d)
        force[d] = Utilities::MPI::sum(force[d], flow.get_communicator());
      return force;
    }



    template <int dim>
    Tensor<1, dim>
    volume_force(const NavierStokes<dim>                       &flow,
                 const typename NavierStokes<dim>::BlockVector &indicator)
    {
      const QGauss<dim>                quadrature(3);
      FEValues<dim>                    fe_values(flow.get_mapping(),
                              flow.get_fe(),
                              quadrature,
                              update_values | update_gradients
                                | update_JxW_values);
      const FEValuesExtractors::Scalar alpha(0);
      const unsigned int               n_q = quadrature.size();
      std::vector<Tensor<2, dim>>      sigma(n_q);
      std::vector<Tensor<1, dim>>      grad_alpha(n_q);

      Tensor<1, dim> force;
      for (const auto &cell : flow.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[alpha].get_function_gradients(indicator, grad_alpha);
            double largest = 0.;
            for (const auto &g : grad_alpha)
              largest = std::max(largest, g.norm());
            if (largest == 0.)
              continue; // not a cut cell
            cauchy_stress(flow, fe_values, sigma);
            for (unsigned int q = 0; q < n_q; ++q)
              force -= sigma[q] * grad_alpha[q] * fe_values.JxW(q);
          }
      for (unsigned int d = 0; d < dim; ++d)
        force[d] = Utilities::MPI::sum(force[d], flow.get_communicator());
      return force;
    }



    template <int dim>
    void
    cauchy_stress(const NavierStokes<dim>     &flow,
                  const FEValues<dim>         &fe_values,
                  std::vector<Tensor<2, dim>> &sigma)
    {
      const unsigned int          n_q = fe_values.n_quadrature_points;
      std::vector<Tensor<2, dim>> grad_u(n_q);
      std::vector<double>         p(n_q);
      fe_values[FEValuesExtractors::Vector(0)]
        .get_function_gradients(flow.get_solution(), grad_u);
      fe_values[FEValuesExtractors::Scalar(dim)]
        .get_function_values(flow.get_solution(), p);
      const auto &viscosity = flow.get_viscosity_model();
      sigma.resize(n_q);
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const SymmetricTensor<2, dim> D = symmetrize(grad_u[q]);
          const double mu = viscosity.viscosity(std::sqrt(2. * D * D));
          sigma[q]        = -p[q] * unit_symmetric_tensor<dim>() + 2. * mu * D;
        }
    }



    template <int dim>
    typename NavierStokes<dim>::BlockVector
    boundary_indicator(const NavierStokes<dim>         &flow,
                       const std::vector<unsigned int> &boundary_ids)
    {
      const auto                          &dof_handler = flow.get_dof_handler();
      auto                                 owned = flow.make_owned_vector();
      std::vector<types::global_dof_index> face_dofs(
        flow.get_fe().n_dofs_per_face());
      const IndexSet owned_dofs = dof_handler.locally_owned_dofs();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && cell->at_boundary())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary()
                && std::find(boundary_ids.begin(),
                             boundary_ids.end(),
                             cell->face(f)->boundary_id())
                     != boundary_ids.end())
              {
                cell->face(f)->get_dof_indices(face_dofs);
                for (unsigned int i = 0; i < face_dofs.size(); ++i)
                  if (flow.get_fe().face_system_to_component_index(i).first == 0
                      && owned_dofs.is_element(face_dofs[i]))
                    owned(face_dofs[i]) = 1.;
              }
      owned.compress(VectorOperation::insert);
      auto ghosted = flow.make_ghosted_vector();
      ghosted      = owned;
      return ghosted;
    }



    template <int dim>
    double
    pressure_at(const NavierStokes<dim> &flow, const Point<dim> &point)
    {
      double value = 0., found = 0.;
      try
        {
          const auto cell_and_point
            = GridTools::find_active_cell_around_point(flow.get_mapping(),
                                                       flow.get_dof_handler(),
                                                       point);
          if (cell_and_point.first.state() == IteratorState::valid
              && cell_and_point.first->is_locally_owned())
            {
              const Quadrature<dim> quadrature(
                GeometryInfo<dim>::project_to_unit_cell(cell_and_point.second));
              FEValues<dim> fe_values(flow.get_mapping(),
                                      flow.get_fe(),
                                      quadrature,
                                      update_values);
              fe_values.reinit(cell_and_point.first);
              std::vector<double> p(1);
              fe_values[FEValuesExtractors::Scalar(dim)]
                .get_function_values(flow.get_solution(), p);
              value = p[0];
              found = 1.;
            }
        }
      catch (const ExceptionBase &)
        {
          // not in this rank's part of the mesh
        }
      const double n_found
        = Utilities::MPI::sum(found, flow.get_communicator());
      if (n_found == 0.)
        {
          std::ostringstream s;
          s << "The pressure point (" << point
            << ") is not inside the mesh. Check 'Pressure point A/B' in "
               "subsection 'Forces'.";
          throw std::runtime_error(s.str());
        }
      // a point on a partition boundary may be found by two ranks
      return Utilities::MPI::sum(value, flow.get_communicator()) / n_found;
    }



    template <int dim>
    double
    kinetic_energy(const NavierStokes<dim> &flow)
    {
      const QGauss<dim>           quadrature(3);
      FEValues<dim>               fe_values(flow.get_mapping(),
                              flow.get_fe(),
                              quadrature,
                              update_values | update_JxW_values);
      std::vector<Tensor<1, dim>> u(quadrature.size());
      double                      energy = 0.;
      for (const auto &cell : flow.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[FEValuesExtractors::Vector(0)]
              .get_function_values(flow.get_solution(), u);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              energy += u[q] * u[q] * fe_values.JxW(q);
          }
      return 0.5 * flow.get_parameters().properties.density
             * Utilities::MPI::sum(energy, flow.get_communicator());
    }

#define INSTANTIATE(dim)                                                      \
  template Tensor<1, dim> surface_force(const NavierStokes<dim> &,            \
                                        const std::vector<unsigned int> &);   \
  template Tensor<1, dim> volume_force(                                       \
    const NavierStokes<dim> &,                                                \
    const NavierStokes<dim>::BlockVector &);                                  \
  template void cauchy_stress(const NavierStokes<dim> &,                      \
                              const FEValues<dim> &,                          \
                              std::vector<Tensor<2, dim>> &);                 \
  template NavierStokes<dim>::BlockVector boundary_indicator(                 \
    const NavierStokes<dim> &,                                                \
    const std::vector<unsigned int> &);                                       \
  template double pressure_at(const NavierStokes<dim> &, const Point<dim> &); \
  template double kinetic_energy(const NavierStokes<dim> &);
    INSTANTIATE(2)
    INSTANTIATE(3)
#undef INSTANTIATE
  } // namespace fluid
} // namespace particulate
