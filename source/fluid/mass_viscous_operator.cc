#include "mass_viscous_operator.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/matrix_free/tools.h>

#include <cmath>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::initialize(
      std::shared_ptr<const MatrixFree> matrix_free)
    {
      data = std::move(matrix_free);
      identity_rows.clear();
      for (const unsigned int i : data->get_constrained_dofs())
        identity_rows.push_back(i);
      masked_rows.clear();
      viscosity.reinit(0, 0);
      viscosity_per_point = false;

      // The two geometric diagonals, each from the kernel with one unit
      // coefficient and the other zero (deal.II 9.4's compute_diagonal
      // expects a sized vector).
      const auto unit_diagonal =
        [this](const Number mass, const Number viscous, VectorType &diagonal) {
          mass_coefficient   = mass;
          viscosity_constant = viscous;
          data->initialize_dof_vector(diagonal);
          MatrixFreeTools::compute_diagonal(*data,
                                            diagonal,
                                            &MassViscousOperator::cell_kernel,
                                            this);
        };
      unit_diagonal(1., 0., mass_diagonal);
      unit_diagonal(0., 1., viscous_diagonal);
      viscosity_constant = 0.;
      inverse_diagonal   = std::make_shared<DiagonalMatrix<VectorType>>();
      data->initialize_dof_vector(inverse_diagonal->get_vector());
    }



    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::set_coefficients(
      const VectorType     &velocity_in,
      const double          mass,
      const double          theta_implicit,
      const ViscosityModel &viscosity_model)
    {
      mass_coefficient    = mass;
      viscosity_per_point = viscosity_model.depends_on_shear_rate();
      viscosity_constant
        = theta_implicit * viscosity_model.reference_viscosity();
      update_inverse_diagonal();
      if (!viscosity_per_point)
        {
          viscosity.reinit(0, 0);
          return;
        }

      VectorType velocity;
      data->initialize_dof_vector(velocity);
      velocity.copy_locally_owned_data_from(velocity_in);
      velocity.update_ghost_values();
      Integrator phi(*data);
      viscosity.reinit(data->n_cell_batches(), phi.n_q_points);
      for (unsigned int cell = 0; cell < data->n_cell_batches(); ++cell)
        {
          phi.reinit(cell);
          phi.read_dof_values_plain(velocity);
          phi.evaluate(EvaluationFlags::gradients);
          for (unsigned int q = 0; q < phi.n_q_points; ++q)
            {
              const auto D = phi.get_symmetric_gradient(q);
              for (unsigned int lane = 0; lane < VectorizedArray::size();
                   ++lane)
                {
                  double DD = 0.;
                  for (unsigned int c = 0; c < dim; ++c)
                    for (unsigned int d = 0; d < dim; ++d)
                      DD += D[c][d][lane] * D[c][d][lane];
                  viscosity(cell, q)[lane]
                    = theta_implicit
                      * viscosity_model.viscosity(std::sqrt(2. * DD));
                }
            }
        }
    }



    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::set_masked_dofs(
      const std::vector<types::global_dof_index> &dofs)
    {
      const auto &partitioner = *data->get_vector_partitioner();
      masked_rows.clear();
      masked_rows.reserve(dofs.size());
      for (const auto dof : dofs)
        masked_rows.push_back(partitioner.global_to_local(dof));
      update_inverse_diagonal();
    }



    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::update_inverse_diagonal()
    {
      VectorType &inverse = inverse_diagonal->get_vector();
      for (unsigned int i = 0; i < inverse.locally_owned_size(); ++i)
        {
          const Number d
            = mass_coefficient * mass_diagonal.local_element(i)
              + viscosity_constant * viscous_diagonal.local_element(i);
          inverse.local_element(i) = d > Number(0.) ? Number(1.) / d : 1.;
        }
      for (const unsigned int i : identity_rows)
        inverse.local_element(i) = 1.;
      for (const unsigned int i : masked_rows)
        inverse.local_element(i) = 1.;
    }



    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::quadrature_point_operation(
      Integrator        &phi,
      const unsigned int cell) const
    {
      // nu (grad u + grad u^T) : grad v = 2 nu eps(u) : eps(v); the
      // symmetric-gradient access transforms 6 (3D) instead of 9 entries
      for (unsigned int q = 0; q < phi.n_q_points; ++q)
        {
          const VectorizedArray two_nu
            = Number(2.)
              * (viscosity_per_point ? viscosity(cell, q) :
                                       VectorizedArray(viscosity_constant));
          phi.submit_value(mass_coefficient * phi.get_value(q), q);
          phi.submit_symmetric_gradient(two_nu * phi.get_symmetric_gradient(q),
                                        q);
        }
    }



    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::cell_kernel(Integrator &phi) const
    {
      phi.evaluate(EvaluationFlags::values | EvaluationFlags::gradients);
      quadrature_point_operation(phi, phi.get_current_cell_index());
      phi.integrate(EvaluationFlags::values | EvaluationFlags::gradients);
    }



    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::local_apply(
      const MatrixFree                            &matrix_free,
      VectorType                                  &dst,
      const VectorType                            &src,
      const std::pair<unsigned int, unsigned int> &range) const
    {
      Integrator phi(matrix_free);
      for (unsigned int cell = range.first; cell < range.second; ++cell)
        {
          phi.reinit(cell);
          phi.gather_evaluate(src,
                              EvaluationFlags::values
                                | EvaluationFlags::gradients);
          quadrature_point_operation(phi, cell);
          phi.integrate_scatter(EvaluationFlags::values
                                  | EvaluationFlags::gradients,
                                dst);
        }
    }



    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::vmult_add(VectorType       &dst,
                                                const VectorType &src) const
    {
      // Constrained and masked rows and columns act as the identity: the
      // masked source values take no part in the cell integrals (the
      // constrained ones are skipped by the matrix-free loop itself), and
      // what the integrals add to those rows is replaced afterwards.
      auto &source = const_cast<VectorType &>(src);
      kept_source.resize(masked_rows.size());
      for (unsigned int i = 0; i < masked_rows.size(); ++i)
        {
          kept_source[i] = source.local_element(masked_rows[i]);
          source.local_element(masked_rows[i]) = 0.;
        }
      kept_destination.clear();
      for (const auto *rows : {&identity_rows, &masked_rows})
        for (const unsigned int i : *rows)
          kept_destination.push_back(dst.local_element(i));

      data->cell_loop(&MassViscousOperator::local_apply, this, dst, src, false);

      for (unsigned int i = 0; i < masked_rows.size(); ++i)
        source.local_element(masked_rows[i]) = kept_source[i];
      unsigned int n = 0;
      for (const auto *rows : {&identity_rows, &masked_rows})
        for (const unsigned int i : *rows)
          dst.local_element(i) = kept_destination[n++] + src.local_element(i);
    }



    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::vmult(VectorType       &dst,
                                            const VectorType &src) const
    {
      dst = 0.;
      vmult_add(dst, src);
    }



    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::Tvmult(VectorType       &dst,
                                             const VectorType &src) const
    {
      vmult(dst, src); // symmetric
    }



    template <int dim, typename Number>
    void
    MassViscousOperator<dim, Number>::Tvmult_add(VectorType       &dst,
                                                 const VectorType &src) const
    {
      vmult_add(dst, src);
    }



    template <int dim, typename Number>
    std::size_t
    MassViscousOperator<dim, Number>::memory_consumption() const
    {
      return mass_diagonal.memory_consumption()
             + viscous_diagonal.memory_consumption()
             + inverse_diagonal->get_vector().memory_consumption()
             + viscosity.memory_consumption() + data->memory_consumption();
    }

    template class MassViscousOperator<2, float>;
    template class MassViscousOperator<3, float>;
  } // namespace fluid
} // namespace particulate
