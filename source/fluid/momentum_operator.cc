// simd.h first: it must precede every deal.II header
// clang-format off
#include "simd.h"
// clang-format on

#include "momentum_operator.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/table.h>
#include <deal.II/base/vectorization.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>

#include <algorithm>
#include <cmath>
#include <functional>


namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /** The shear rate sqrt(2 D:D), D = (G + G^T)/2, of one SIMD lane of a
       *  velocity gradient G. */
      template <int dim>
      double
      shear_rate(const Tensor<2, dim, SimdArray<double>> &G,
                 const unsigned int                       lane)
      {
        double DD = 0.;
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double D = 0.5 * (G[c][d][lane] + G[d][c][lane]);
              DD += D * D;
            }
        return std::sqrt(2. * DD);
      }
    } // namespace



    template <int dim>
    struct MomentumOperator<dim>::Implementation
    {
      using VectorType      = LinearAlgebra::distributed::Vector<double>;
      using VectorizedArray = SimdArray<double>;
      using MatrixFree      = dealii::MatrixFree<dim, double, VectorizedArray>;
      using Integrator = FEEvaluation<dim, 2, 3, dim, double, VectorizedArray>;

      Implementation(const DoFHandler<dim> &dofs,
                     const IndexSet        &owned,
                     const Mapping<dim>    &mapping)
        : dofs(dofs)
        , owned(owned)
        , mapping(mapping)
      {
        build();
      }

      void
      build()
      {
        // No constraints in the matrix-free data: the constrained rows
        // change with the bodies every time step, and rebuilding this
        // object then would cost more than the products; they are masked
        // in vmult instead.
        AffineConstraints<double> none;
        none.close();
        typename MatrixFree::AdditionalData data;
        data.tasks_parallel_scheme = MatrixFree::AdditionalData::none;
        data.mapping_update_flags
          = update_values | update_gradients | update_JxW_values;
        matrix_free.reinit(mapping, dofs, none, QGauss<1>(3), data);
        matrix_free.initialize_dof_vector(source);
        matrix_free.initialize_dof_vector(destination);
        AssertThrow(source.locally_owned_size() == owned.n_elements(),
                    ExcMessage("MomentumOperator: the velocity DoF handler "
                               "does not own the velocity block's DoFs."));
        linearised = false;
      }

      /** Locally owned entries of a Trilinos vector into a ghosted
       *  matrix-free vector (the owned ranges coincide). */
      void
      copy_with_ghosts(const TrilinosWrappers::MPI::Vector &in,
                       VectorType                          &out) const
      {
        matrix_free.initialize_dof_vector(out);
        AssertDimension(in.locally_owned_size(), out.locally_owned_size());
        std::copy(in.begin(), in.end(), out.begin());
        out.update_ghost_values();
      }

      void
      local_apply(const MatrixFree                            &data,
                  VectorType                                  &dst,
                  const VectorType                            &src,
                  const std::pair<unsigned int, unsigned int> &range) const
      {
        Integrator            phi(data);
        const unsigned int    n_q = phi.n_q_points;
        const VectorizedArray mass(mass_coefficient);
        const VectorizedArray convective(convection_coefficient);
        const VectorizedArray nu_constant(viscosity_constant);
        for (unsigned int cell = range.first; cell < range.second; ++cell)
          {
            phi.reinit(cell);
            phi.gather_evaluate(src,
                                EvaluationFlags::values
                                  | EvaluationFlags::gradients);
            for (unsigned int q = 0; q < n_q; ++q)
              {
                const Tensor<1, dim, VectorizedArray> u = phi.get_value(q);
                const Tensor<2, dim, VectorizedArray> G = phi.get_gradient(q);
                // rho/k u + theta_i rho [(a.grad) u + (u.grad) u*]
                Tensor<1, dim, VectorizedArray> value
                  = mass * u + convective * (G * advecting(cell, q));
                if (newton)
                  value += convective * (iterate_gradient(cell, q) * u);
                // theta_i mu (grad u + grad u^T) : grad v = theta_i 2 mu
                // D(u) : D(v)
                const VectorizedArray nu
                  = viscosity_per_point ? viscosity(cell, q) : nu_constant;
                phi.submit_value(value, q);
                Tensor<2, dim, VectorizedArray> flux = nu * (G + transpose(G));
                // Newton: + theta_i 4 mu'/g (D*:D(u)) D*, D* = D(u*)
                if (newton && viscosity_per_point)
                  {
                    const Tensor<2, dim, VectorizedArray> &G_star
                      = iterate_gradient(cell, q);
                    const Tensor<2, dim, VectorizedArray> D_star
                      = VectorizedArray(0.5) * (G_star + transpose(G_star));
                    flux
                      += (viscosity_slope(cell, q) * scalar_product(D_star, G))
                         * D_star;
                  }
                phi.submit_gradient(flux, q);
              }
            phi.integrate_scatter(EvaluationFlags::values
                                    | EvaluationFlags::gradients,
                                  dst);
          }
      }

      const DoFHandler<dim> &dofs;
      const IndexSet         owned;
      const Mapping<dim>    &mapping;

      MatrixFree matrix_free;
      /// local indices of the constrained rows
      std::vector<unsigned int> constrained_rows;

      bool   linearised             = false;
      bool   newton                 = false;
      bool   viscosity_per_point    = false;
      double mass_coefficient       = 0.;
      double convection_coefficient = 0.; ///< theta_i rho
      double viscosity_constant     = 0.; ///< theta_i mu, constant mu
      /// u* - w per cell batch and quadrature point
      Table<2, Tensor<1, dim, VectorizedArray>> advecting;
      /// grad u* (Newton only)
      Table<2, Tensor<2, dim, VectorizedArray>> iterate_gradient;
      /// theta_i mu(shear rate of u*) (shear-rate dependent viscosity only)
      Table<2, VectorizedArray> viscosity;
      /// theta_i 4 mu'/g at the shear rate g of u* (shear-rate dependent
      /// viscosity with Newton only)
      Table<2, VectorizedArray> viscosity_slope;

      mutable VectorType source, destination;
    };



    template <int dim>
    MomentumOperator<dim>::MomentumOperator(const DoFHandler<dim> &dofs,
                                            const IndexSet        &owned,
                                            const Mapping<dim>    &mapping)
      : implementation(std::make_unique<Implementation>(dofs, owned, mapping))
    {}



    template <int dim>
    MomentumOperator<dim>::~MomentumOperator() = default;



    template <int dim>
    void
    MomentumOperator<dim>::update_geometry()
    {
      auto &m = *implementation;
      m.matrix_free.update_mapping(m.mapping);
      m.linearised = false;
    }



    template <int dim>
    void
    MomentumOperator<dim>::set_constrained_dofs(
      const std::vector<types::global_dof_index> &dofs)
    {
      auto &m = *implementation;
      m.constrained_rows.clear();
      m.constrained_rows.reserve(dofs.size());
      const auto &partitioner = *m.matrix_free.get_vector_partitioner();
      for (const auto dof : dofs)
        {
          AssertThrow(partitioner.in_local_range(dof),
                      ExcMessage("MomentumOperator: constrained DoFs must be "
                                 "locally owned."));
          m.constrained_rows.push_back(partitioner.global_to_local(dof));
        }
    }



    template <int dim>
    void
    MomentumOperator<dim>::set_linearisation(
      const TrilinosWrappers::MPI::Vector &velocity,
      const TrilinosWrappers::MPI::Vector *mesh_velocity,
      const double                         mass_coefficient,
      const double                         theta_implicit,
      const double                         density,
      const bool                           newton,
      const ViscosityModel                &viscosity_model)
    {
      auto &m                  = *implementation;
      using Integrator         = typename Implementation::Integrator;
      using VectorizedArray    = typename Implementation::VectorizedArray;
      m.mass_coefficient       = mass_coefficient;
      m.convection_coefficient = theta_implicit * density;
      m.viscosity_constant
        = theta_implicit * viscosity_model.reference_viscosity();
      m.newton              = newton;
      m.viscosity_per_point = viscosity_model.depends_on_shear_rate();

      typename Implementation::VectorType u, w;
      m.copy_with_ghosts(velocity, u);
      if (mesh_velocity != nullptr)
        m.copy_with_ghosts(*mesh_velocity, w);

      Integrator         phi(m.matrix_free), phi_w(m.matrix_free);
      const unsigned int n_cells = m.matrix_free.n_cell_batches();
      const unsigned int n_q     = phi.n_q_points;
      m.advecting.reinit(n_cells, n_q);
      m.iterate_gradient.reinit(newton ? n_cells : 0, newton ? n_q : 0);
      m.viscosity.reinit(m.viscosity_per_point ? n_cells : 0,
                         m.viscosity_per_point ? n_q : 0);
      const bool viscosity_slope = newton && m.viscosity_per_point;
      m.viscosity_slope.reinit(viscosity_slope ? n_cells : 0,
                               viscosity_slope ? n_q : 0);
      for (unsigned int cell = 0; cell < n_cells; ++cell)
        {
          phi.reinit(cell);
          phi.read_dof_values_plain(u);
          phi.evaluate(EvaluationFlags::values | EvaluationFlags::gradients);
          if (mesh_velocity != nullptr)
            {
              phi_w.reinit(cell);
              phi_w.read_dof_values_plain(w);
              phi_w.evaluate(EvaluationFlags::values);
            }
          for (unsigned int q = 0; q < n_q; ++q)
            {
              m.advecting(cell, q) = phi.get_value(q);
              if (mesh_velocity != nullptr)
                m.advecting(cell, q) -= phi_w.get_value(q);
              const Tensor<2, dim, VectorizedArray> G = phi.get_gradient(q);
              if (newton)
                m.iterate_gradient(cell, q) = G;
              if (m.viscosity_per_point)
                for (unsigned int lane = 0; lane < VectorizedArray::size();
                     ++lane)
                  {
                    const double g = shear_rate<dim>(G, lane);
                    m.viscosity(cell, q)[lane]
                      = theta_implicit * viscosity_model.viscosity(g);
                    if (viscosity_slope)
                      m.viscosity_slope(cell, q)[lane]
                        = theta_implicit * 4.
                          * viscosity_model.slope_over_shear_rate(g);
                  }
            }
        }
      m.linearised = true;
    }



    template <int dim>
    void
    MomentumOperator<dim>::vmult(TrilinosWrappers::MPI::Vector       &dst,
                                 const TrilinosWrappers::MPI::Vector &src) const
    {
      auto &m = *implementation;
      AssertThrow(m.linearised,
                  ExcMessage("MomentumOperator::vmult before "
                             "set_linearisation()"));
      AssertDimension(src.locally_owned_size(), m.source.locally_owned_size());
      std::copy(src.begin(), src.end(), m.source.begin());
      // constrained columns are zero: their source values take no part
      for (const unsigned int i : m.constrained_rows)
        m.source.local_element(i) = 0.;
      m.matrix_free.cell_loop(&Implementation::local_apply,
                              &m,
                              m.destination,
                              m.source,
                              true);
      std::copy(m.destination.begin(), m.destination.end(), dst.begin());
      // constrained rows are the identity
      for (const unsigned int i : m.constrained_rows)
        dst.begin()[i] = src.begin()[i];
    }



    template <int dim>
    void
    MomentumOperator<dim>::apply_nonlinear_form(
      TrilinosWrappers::MPI::Vector       &dst,
      const TrilinosWrappers::MPI::Vector &velocity,
      const TrilinosWrappers::MPI::Vector *mesh_velocity,
      const double                         mass_coefficient,
      const double                         theta,
      const double                         density,
      const ViscosityModel                &viscosity_model) const
    {
      auto &m               = *implementation;
      using Integrator      = typename Implementation::Integrator;
      using VectorType      = typename Implementation::VectorType;
      using VectorizedArray = typename Implementation::VectorizedArray;
      // fresh ghosted vectors: vmult() relies on m.source having no ghost
      // values set (the loop then exchanges them)
      VectorType u_ghosted, w;
      m.copy_with_ghosts(velocity, u_ghosted);
      if (mesh_velocity != nullptr)
        m.copy_with_ghosts(*mesh_velocity, w);
      const bool variable_mu = viscosity_model.depends_on_shear_rate();
      const VectorizedArray mass(mass_coefficient);
      const VectorizedArray convective(theta * density);
      const VectorizedArray nu_constant(
        theta * viscosity_model.reference_viscosity());

      using MatrixFree = typename Implementation::MatrixFree;
      const std::function<void(const MatrixFree &,
                               VectorType &,
                               const VectorType &,
                               const std::pair<unsigned int, unsigned int> &)>
        kernel = [&](const MatrixFree                            &data,
                     VectorType                                  &out,
                     const VectorType                            &u,
                     const std::pair<unsigned int, unsigned int> &range) {
          Integrator phi(data), phi_w(data);
          for (unsigned int cell = range.first; cell < range.second; ++cell)
            {
              phi.reinit(cell);
              phi.gather_evaluate(u,
                                  EvaluationFlags::values
                                    | EvaluationFlags::gradients);
              if (mesh_velocity != nullptr)
                {
                  phi_w.reinit(cell);
                  phi_w.gather_evaluate(w, EvaluationFlags::values);
                }
              for (unsigned int q = 0; q < phi.n_q_points; ++q)
                {
                  const Tensor<1, dim, VectorizedArray> value
                    = phi.get_value(q);
                  const Tensor<2, dim, VectorizedArray> G = phi.get_gradient(q);
                  Tensor<1, dim, VectorizedArray>       advecting = value;
                  if (mesh_velocity != nullptr)
                    advecting -= phi_w.get_value(q);
                  VectorizedArray nu = nu_constant;
                  if (variable_mu)
                    for (unsigned int lane = 0; lane < VectorizedArray::size();
                         ++lane)
                      nu[lane]
                        = theta
                          * viscosity_model.viscosity(shear_rate<dim>(G, lane));
                  phi.submit_value(mass * value + convective * (G * advecting),
                                   q);
                  phi.submit_gradient(nu * (G + transpose(G)), q);
                }
              phi.integrate_scatter(EvaluationFlags::values
                                      | EvaluationFlags::gradients,
                                    out);
            }
        };
      // u_ghosted has its ghost values: the loop uses them as they are
      m.matrix_free.cell_loop(kernel, m.destination, u_ghosted, true);
      std::copy(m.destination.begin(), m.destination.end(), dst.begin());
    }



    template <int dim>
    std::size_t
    MomentumOperator<dim>::memory_consumption() const
    {
      const auto &m = *implementation;
      return m.matrix_free.memory_consumption()
             + m.advecting.memory_consumption()
             + m.iterate_gradient.memory_consumption()
             + m.viscosity.memory_consumption()
             + m.viscosity_slope.memory_consumption()
             + m.source.memory_consumption()
             + m.destination.memory_consumption();
    }

    template class MomentumOperator<2>;
    template class MomentumOperator<3>;
  } // namespace fluid
} // namespace particulate
