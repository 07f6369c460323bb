#include <particulate/fluid/cell_block_insertion.h>
#include <particulate/fluid/flow_discretisation.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <tuple>

#include "momentum_operator.h"
#include "velocity_jacobian_kernel.h"
#include "viscous_newton_term.h"
#include <Epetra_CrsMatrix.h>
#include <Epetra_Vector.h>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    /*
     * Residual and Jacobian of one stage (see Stage). With test functions
     * (v, q) the residual is
     *
     *   R_u(v) = rho/k (u - u_old, v)
     *          + theta_i [ (2 mu D(u), D(v)) + rho ((u - w).grad u, v)
     *                      - rho (f_new, v) ]
     *          + theta_e [ (2 mu D(u_old), D(v)) + rho ((u_old - w).grad
     *                      u_old, v) - rho (f_old, v) ]
     *          - (p, div v)
     *   R_p(q) = -(div u, q)
     *
     * and the right-hand side is -R. The terms rho (du.grad u, v) and mu's
     * derivative through the shear rate (ViscousNewtonTerm) are the Newton
     * parts that the fixed-point (Oseen) iteration omits.
     */
    template <int dim>
    void
    FlowDiscretisation<dim>::assemble(const Stage         &stage,
                                      const AssemblyTarget target,
                                      const bool           newton)
    {
      const bool assemble_matrix   = target != AssemblyTarget::residual;
      const bool assemble_residual = target != AssemblyTarget::jacobian;
      if (momentum_operator)
        {
          // nothing to assemble: the residual comes from the matrix-free
          // form, and the operator takes the iterate instead of a Jacobian
          if (assemble_residual)
            assemble_residual_matrix_free(stage);
          if (assemble_matrix)
            linearise_momentum_operator(stage, newton);
          return;
        }
      TimerOutput::Scope scope(timer,
                               assemble_matrix ? "fluid: assemble matrix" :
                                                 "fluid: assemble residual");
      if (assemble_matrix)
        {
          system_matrix = 0;
        }
      if (assemble_residual)
        system_rhs = 0;

      const double rho         = parameters.properties.density;
      const bool   steady      = stage.time_step == 0.;
      const double mass_coeff  = steady ? 0. : rho / stage.time_step;
      const double ti          = stage.theta_implicit;
      const double te          = steady ? 0. : stage.theta_explicit;
      const bool   variable_mu = viscosity_model->depends_on_shear_rate();

      const bool has_body_force
        = dynamic_cast<const Functions::ZeroFunction<dim> *>(body_force.get())
          == nullptr;

      // FEValues of the scalar Q2 element only: the velocity space is its
      // dim copies, and the cell's velocity and pressure are evaluated
      // from the cell's DoF values below. FEValues of the whole FESystem
      // would map the gradients of all dim * n_s + n_p shape functions
      // (3x the work in 3D) and look every vector entry up once per
      // get_function_*() call.
      const QGauss<dim>  quadrature(3);
      const auto        &velocity_fe = fe.base_element(0);
      const auto        &pressure_fe = fe.base_element(1);
      FEValues<dim>      fe_values(mapping,
                              velocity_fe,
                              quadrature,
                              update_gradients | update_JxW_values
                                | (has_body_force ? update_quadrature_points :
                                                         update_default));
      const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
      const unsigned int n_q           = quadrature.size();

      FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
      Vector<double>     cell_rhs(dofs_per_cell);
      std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
      std::vector<double>                  local_solution(dofs_per_cell),
        local_old_solution(dofs_per_cell), local_mesh_velocity(dofs_per_cell);

      std::vector<Tensor<1, dim>> u(n_q), u_old(n_q), w(n_q);
      std::vector<Tensor<2, dim>> grad_u(n_q), grad_u_old(n_q);
      std::vector<double>         p(n_q), div_u(n_q);
      std::vector<Vector<double>> f_new(n_q, Vector<double>(dim)),
        f_old(n_q, Vector<double>(dim));

      // The velocity space is Q2^dim: every velocity shape function is a
      // scalar Q2 function phi_a times a unit vector e_c. The kernel works
      // on the n_s scalar functions and fills the dim x dim blocks of the
      // cell matrix from them, which costs ~(n_s/dofs_per_cell)^2 of the
      // generic vector-valued loop (15x fewer operations in 3D).
      const unsigned int n_s = fe.base_element(0).n_dofs_per_cell();
      const unsigned int n_p = fe.base_element(1).n_dofs_per_cell();
      std::vector<std::array<unsigned int, dim>> velocity_index(n_s);
      std::vector<unsigned int>                  pressure_index(n_p);
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          const auto [component, index] = fe.system_to_component_index(i);
          if (component < dim)
            velocity_index[index][component] = i;
          else
            pressure_index[index] = i;
        }
      // shape values of Q2 and P1disc are those of the reference cell on
      // every cell (no mapping acts on them)
      std::vector<std::vector<double>> phi_at(n_q, std::vector<double>(n_s)),
        psi_at(n_q, std::vector<double>(n_p));
      for (unsigned int q = 0; q < n_q; ++q)
        {
          for (unsigned int a = 0; a < n_s; ++a)
            phi_at[q][a] = velocity_fe.shape_value(a, quadrature.point(q));
          for (unsigned int k = 0; k < n_p; ++k)
            psi_at[q][k] = pressure_fe.shape_value(k, quadrature.point(q));
        }
      // velocity values (and gradients) at the quadrature points from a
      // cell's DoF values
      const auto evaluate_velocity
        = [&](const std::vector<double>   &local,
              std::vector<Tensor<1, dim>> &values,
              std::vector<Tensor<2, dim>> *gradients) {
            for (unsigned int q = 0; q < n_q; ++q)
              {
                Tensor<1, dim> value;
                Tensor<2, dim> gradient;
                for (unsigned int a = 0; a < n_s; ++a)
                  for (unsigned int c = 0; c < dim; ++c)
                    {
                      const double coefficient = local[velocity_index[a][c]];
                      value[c] += coefficient * phi_at[q][a];
                      if (gradients)
                        gradient[c] += coefficient * fe_values.shape_grad(a, q);
                    }
                values[q] = value;
                if (gradients)
                  (*gradients)[q] = gradient;
              }
          };
      std::array<std::vector<double>, dim> grad_phi_by_component;
      grad_phi_by_component.fill(std::vector<double>(n_s));
      std::vector<Tensor<1, dim>>     grad_phi(n_s);
      std::array<const double *, dim> gradient_rows;
      for (unsigned int d = 0; d < dim; ++d)
        gradient_rows[d] = grad_phi_by_component[d].data();
      // the local matrix by blocks: (c, d) velocity components
      AssertThrow(n_s == VelocityJacobianKernel<dim>::n_s,
                  ExcMessage("The Jacobian kernel is written for Q2 "
                             "velocities."));
      VelocityJacobianKernel<dim> jacobian_kernel(n_q);
      // Newton with a shear-rate dependent viscosity adds mu's derivative
      const bool viscous_newton = newton && variable_mu && assemble_matrix;
      ViscousNewtonTerm<dim> viscous_newton_term(viscous_newton ? n_s : 0);
      const auto             uu
        = [&](unsigned int c, unsigned int d, unsigned int a, unsigned int b) {
            return viscous_newton ? jacobian_kernel(c, d, a, b)
                                      + viscous_newton_term(c, d, a, b) :
                                    jacobian_kernel(c, d, a, b);
          };
      // B: (pressure k, component d, scalar b) -> -(psi_k, d_d phi_b)
      std::vector<double> block_pu(n_p * dim * n_s);

      // The blocks go straight into the matrix (CellBlockInsertion) unless
      // a constraint couples DoFs (hanging nodes, a slip plane that is not
      // a coordinate plane) or holds a pressure: those need
      // AffineConstraints.
      const types::global_dof_index n_velocity_dofs = dofs_per_block[0];
      const bool                    direct_insertion
        = assemble_matrix
          && CellBlockInsertion::applicable(system_matrix,
                                            zero_constraints,
                                            n_velocity_dofs);
      CellBlockInsertion insertion;
      // velocity i = dim * a + c is phi_a e_c; pressures that no equation
      // determines are invalid_dof_index
      std::vector<types::global_dof_index> velocity_dofs(dim * n_s),
        pressure_dofs(n_p);
      const auto insert_directly = [&]() {
        for (unsigned int a = 0; a < n_s; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            velocity_dofs[dim * a + c] = dof_indices[velocity_index[a][c]];
        insertion.add_saddle_point_cell(
          system_matrix,
          zero_constraints,
          velocity_dofs,
          pressure_dofs,
          n_velocity_dofs,
          [&](const unsigned int i, const unsigned int j) {
            return uu(i % dim, j % dim, i / dim, j / dim);
          },
          [&](const unsigned int k, const unsigned int j) {
            return block_pu[(k * dim + j % dim) * n_s + j / dim];
          },
          dofs_per_cell);
      };

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(
              static_cast<typename Triangulation<dim>::cell_iterator>(cell));
            cell_rhs = 0;
            if (assemble_matrix)
              std::fill(block_pu.begin(), block_pu.end(), 0.);
            if (viscous_newton)
              viscous_newton_term.reset();

            // each vector's cell values read once: every element read from
            // a Trilinos vector is a hash-table lookup of its index
            cell->get_dof_values(solution,
                                 local_solution.begin(),
                                 local_solution.end());
            evaluate_velocity(local_solution, u, &grad_u);
            for (unsigned int q = 0; q < n_q; ++q)
              {
                div_u[q] = trace(grad_u[q]);
                p[q]     = 0.;
                for (unsigned int k = 0; k < n_p; ++k)
                  p[q] += psi_at[q][k] * local_solution[pressure_index[k]];
              }
            if (!steady && assemble_residual)
              {
                cell->get_dof_values(old_solution,
                                     local_old_solution.begin(),
                                     local_old_solution.end());
                evaluate_velocity(local_old_solution, u_old, &grad_u_old);
              }
            if (has_mesh_velocity)
              {
                cell->get_dof_values(mesh_velocity,
                                     local_mesh_velocity.begin(),
                                     local_mesh_velocity.end());
                evaluate_velocity(local_mesh_velocity, w, nullptr);
              }
            if (has_body_force && assemble_residual)
              {
                body_force->set_time(stage.time_new);
                body_force->vector_value_list(fe_values.get_quadrature_points(),
                                              f_new);
                body_force->set_time(stage.time_old);
                body_force->vector_value_list(fe_values.get_quadrature_points(),
                                              f_old);
              }

            for (unsigned int q = 0; q < n_q; ++q)
              {
                const double               JxW = fe_values.JxW(q);
                const std::vector<double> &phi = phi_at[q];
                const std::vector<double> &psi = psi_at[q];
                for (unsigned int a = 0; a < n_s; ++a)
                  grad_phi[a] = fe_values.shape_grad(a, q);

                const SymmetricTensor<2, dim> D = symmetrize(grad_u[q]);
                const double                  shear_rate
                  = variable_mu ? std::sqrt(2. * D * D) : 0.;
                const double   mu = viscosity_model->viscosity(shear_rate);
                Tensor<1, dim> advecting = u[q];
                if (has_mesh_velocity)
                  advecting -= w[q];

                if (assemble_residual)
                  {
                    // the residual's strong-form parts: (a, v) + (S, D(v))
                    Tensor<1, dim> vector_part
                      = ti * rho * (grad_u[q] * advecting);
                    SymmetricTensor<2, dim> tensor_part = ti * 2. * mu * D;
                    if (!steady)
                      {
                        vector_part += mass_coeff * (u[q] - u_old[q]);
                        if (te != 0.)
                          {
                            const SymmetricTensor<2, dim> D_old
                              = symmetrize(grad_u_old[q]);
                            const double mu_old = viscosity_model->viscosity(
                              variable_mu ? std::sqrt(2. * D_old * D_old) : 0.);
                            Tensor<1, dim> advecting_old = u_old[q];
                            if (has_mesh_velocity)
                              advecting_old -= w[q];
                            vector_part
                              += te * rho * (grad_u_old[q] * advecting_old);
                            tensor_part += te * 2. * mu_old * D_old;
                          }
                      }
                    if (has_body_force)
                      for (unsigned int d = 0; d < dim; ++d)
                        vector_part[d]
                          -= rho * (ti * f_new[q][d] + te * f_old[q][d]);

                    // right-hand side -R: (a, v) + (S, D(v)) - (p, div v) for
                    // v = phi_a e_c, and -(div u, q) for q = psi_k
                    for (unsigned int a = 0; a < n_s; ++a)
                      {
                        const Tensor<1, dim> S_grad = tensor_part * grad_phi[a];
                        for (unsigned int c = 0; c < dim; ++c)
                          cell_rhs(velocity_index[a][c])
                            -= (vector_part[c] * phi[a] + S_grad[c]
                                - p[q] * grad_phi[a][c])
                               * JxW;
                      }
                    for (unsigned int k = 0; k < n_p; ++k)
                      cell_rhs(pressure_index[k]) += div_u[q] * psi[k] * JxW;
                  }

                if (!assemble_matrix)
                  continue;
                // Jacobian (see VelocityJacobianKernel), for trial phi_b
                // e_d and test phi_a e_c:
                //   delta_cd [rho/k phi_a phi_b + ti mu grad phi_a.grad phi_b
                //             + ti rho phi_a (advecting.grad phi_b)]
                //   + ti mu d_d phi_a d_c phi_b   (the transpose in D(u))
                //   + ti rho d_d u_c phi_a phi_b  (Newton only)
                for (unsigned int b = 0; b < n_s; ++b)
                  for (unsigned int d = 0; d < dim; ++d)
                    grad_phi_by_component[d][b] = grad_phi[b][d];
                const double newton_weight = newton ? ti * rho * JxW : 0.;
                std::array<double, dim>       advection;
                std::array<double, dim * dim> newton_term;
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    advection[c] = ti * rho * advecting[c] * JxW;
                    for (unsigned int d = 0; d < dim; ++d)
                      newton_term[c * dim + d]
                        = newton_weight * grad_u[q][c][d];
                  }
                if (viscous_newton)
                  viscous_newton_term.add(
                    ti * 4. * viscosity_model->slope_over_shear_rate(shear_rate)
                      * JxW,
                    D,
                    grad_phi);
                jacobian_kernel.set_quadrature_point(q,
                                                     phi.data(),
                                                     gradient_rows.data(),
                                                     mass_coeff * JxW,
                                                     ti * mu * JxW,
                                                     advection.data(),
                                                     newton_term.data());
                for (unsigned int k = 0; k < n_p; ++k)
                  for (unsigned int d = 0; d < dim; ++d)
                    for (unsigned int b = 0; b < n_s; ++b)
                      block_pu[(k * dim + d) * n_s + b]
                        -= psi[k] * grad_phi[b][d] * JxW;
              }

            if (assemble_matrix)
              jacobian_kernel.compute();
            cell->get_dof_indices(dof_indices);
            // undetermined pressure modes (see decoupled_pressure_dofs)
            // leave the equations: no row, no column (invalid_dof_index)
            for (unsigned int k = 0; k < n_p; ++k)
              {
                const types::global_dof_index dof
                  = dof_indices[pressure_index[k]];
                pressure_dofs[k]
                  = std::binary_search(decoupled_pressure_dofs.begin(),
                                       decoupled_pressure_dofs.end(),
                                       dof) ?
                      numbers::invalid_dof_index :
                      dof;
              }
            if (direct_insertion)
              insert_directly();
            else if (assemble_matrix)
              {
                cell_matrix = 0;
                for (unsigned int c = 0; c < dim; ++c)
                  for (unsigned int d = 0; d < dim; ++d)
                    for (unsigned int a = 0; a < n_s; ++a)
                      for (unsigned int b = 0; b < n_s; ++b)
                        cell_matrix(velocity_index[a][c], velocity_index[b][d])
                          = uu(c, d, a, b);
                // B (continuity rows) and B^T (pressure gradient columns)
                for (unsigned int k = 0; k < n_p; ++k)
                  for (unsigned int d = 0; d < dim; ++d)
                    for (unsigned int b = 0; b < n_s; ++b)
                      {
                        const double value = block_pu[(k * dim + d) * n_s + b];
                        cell_matrix(pressure_index[k], velocity_index[b][d])
                          = value;
                        cell_matrix(velocity_index[b][d], pressure_index[k])
                          = value;
                      }
              }

            for (unsigned int k = 0; k < n_p; ++k)
              if (pressure_dofs[k] == numbers::invalid_dof_index)
                {
                  const unsigned int row = pressure_index[k];
                  cell_rhs(row)          = 0.;
                  if (assemble_matrix && !direct_insertion)
                    for (unsigned int i = 0; i < cell_matrix.m(); ++i)
                      {
                        cell_matrix(row, i) = 0.;
                        cell_matrix(i, row) = 0.;
                      }
                }
            if (assemble_matrix && !direct_insertion && assemble_residual)
              zero_constraints.distribute_local_to_global(cell_matrix,
                                                          cell_rhs,
                                                          dof_indices,
                                                          system_matrix,
                                                          system_rhs);
            else if (assemble_matrix && !direct_insertion)
              zero_constraints.distribute_local_to_global(cell_matrix,
                                                          dof_indices,
                                                          system_matrix);
            else if (assemble_residual)
              zero_constraints.distribute_local_to_global(cell_rhs,
                                                          dof_indices,
                                                          system_rhs);
          }
      if (assemble_matrix)
        system_matrix.compress(VectorOperation::add);
      if (assemble_residual)
        {
          system_rhs.compress(VectorOperation::add);
          remove_net_flux_from_residual();
        }
    }



    namespace {
      /** The locally owned entries of a ghosted vector, as the matrix-free
       *  operator reads them (by position in the owned range). */
      TrilinosWrappers::MPI::Vector
      owned_part(const TrilinosWrappers::MPI::Vector &ghosted,
                 const IndexSet                      &owned,
                 const MPI_Comm                       communicator)
      {
        TrilinosWrappers::MPI::Vector result(owned, communicator);
        result = ghosted;
        return result;
      }

    } // namespace



    template <int dim>
    void
    FlowDiscretisation<dim>::linearise_momentum_operator(const Stage &stage,
                                                         const bool   newton)
    {
      TimerOutput::Scope scope(timer, "fluid: linearise velocity operator");
      TrilinosWrappers::MPI::Vector velocity(owned_partitioning[0],
                                             communicator);
      velocity = solution.block(0);
      TrilinosWrappers::MPI::Vector w;
      if (has_mesh_velocity)
        w = owned_part(mesh_velocity.block(0),
                       owned_partitioning[0],
                       communicator);
      const double rho = parameters.properties.density;
      momentum_operator->set_linearisation(velocity,
                                           has_mesh_velocity ? &w : nullptr,
                                           stage.mass_coefficient(rho),
                                           stage.theta_implicit,
                                           rho,
                                           newton,
                                           *viscosity_model);
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::compute_explicit_residual(const Stage &stage)
    {
      TimerOutput::Scope scope(timer, "fluid: assemble residual");
      explicit_residual.reinit(owned_partitioning[0], communicator);
      const double                  rho    = parameters.properties.density;
      const bool                    steady = stage.time_step == 0.;
      const double                  te     = steady ? 0. : stage.theta_explicit;
      TrilinosWrappers::MPI::Vector w;
      if (has_mesh_velocity)
        w = owned_part(mesh_velocity.block(0),
                       owned_partitioning[0],
                       communicator);
      if (!steady)
        {
          // -rho/k (u_old, v) + theta_e N(u_old) u_old
          TrilinosWrappers::MPI::Vector u_old(owned_partitioning[0],
                                              communicator);
          u_old = old_solution.block(0);
          momentum_operator->apply_nonlinear_form(explicit_residual,
                                                  u_old,
                                                  has_mesh_velocity ? &w :
                                                                      nullptr,
                                                  -rho / stage.time_step,
                                                  te,
                                                  rho,
                                                  *viscosity_model);
        }
      if (dynamic_cast<const Functions::ZeroFunction<dim> *>(body_force.get())
          != nullptr)
        return;
      // - rho (theta_i f_new + theta_e f_old, v)
      const QGauss<dim>           quadrature(3);
      FEValues<dim>               fe_values(mapping,
                              fe,
                              quadrature,
                              update_values | update_quadrature_points
                                | update_JxW_values);
      const unsigned int          n_q = quadrature.size();
      std::vector<Vector<double>> f_new(n_q, Vector<double>(dim)),
        f_old(n_q, Vector<double>(dim));
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell()),
        rows;
      std::vector<double> values;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(
              static_cast<typename Triangulation<dim>::cell_iterator>(cell));
            body_force->set_time(stage.time_new);
            body_force->vector_value_list(fe_values.get_quadrature_points(),
                                          f_new);
            body_force->set_time(stage.time_old);
            body_force->vector_value_list(fe_values.get_quadrature_points(),
                                          f_old);
            cell->get_dof_indices(dof_indices);
            rows.clear();
            values.clear();
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                if (c == dim)
                  continue;
                double load = 0.;
                for (unsigned int q = 0; q < n_q; ++q)
                  load
                    -= rho
                       * (stage.theta_implicit * f_new[q](c) + te * f_old[q](c))
                       * fe_values.shape_value(i, q) * fe_values.JxW(q);
                rows.push_back(dof_indices[i]);
                values.push_back(load);
              }
            explicit_residual.add(rows, values);
          }
      explicit_residual.compress(VectorOperation::add);
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::assemble_residual_matrix_free(const Stage &stage)
    {
      TimerOutput::Scope            scope(timer, "fluid: assemble residual");
      const double                  rho = parameters.properties.density;
      TrilinosWrappers::MPI::Vector u(owned_partitioning[0], communicator),
        p(owned_partitioning[1], communicator), w;
      u = solution.block(0);
      p = solution.block(1);
      if (has_mesh_velocity)
        w = owned_part(mesh_velocity.block(0),
                       owned_partitioning[0],
                       communicator);
      // R_u = rho/k (u, v) + theta_i N(u) u + [explicit part] - (p, div v)
      momentum_operator->apply_nonlinear_form(system_rhs.block(0),
                                              u,
                                              has_mesh_velocity ? &w : nullptr,
                                              stage.mass_coefficient(rho),
                                              stage.theta_implicit,
                                              rho,
                                              *viscosity_model);
      system_rhs.block(0) += explicit_residual;
      gradient_matrix.vmult_add(system_rhs.block(0), p);
      // R_p = -(div u, q)
      gradient_matrix.Tvmult(system_rhs.block(1), u);
      system_rhs *= -1.;
      // what the constraints make of the assembled right-hand side
      for (const auto dof : constrained_velocity_dofs)
        system_rhs(dof) = 0.;
      for (const auto dof : decoupled_pressure_dofs)
        system_rhs(dof) = 0.;
      system_rhs.compress(VectorOperation::insert);
      remove_net_flux_from_residual();
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::remove_net_flux_from_residual()
    {
      if (parameters.boundary_conditions.pressure_is_determined())
        return;
      // the orthogonal projection: the smallest change that leaves a
      // residual the Newton update can remove
      double along[2] = {0., 0.}; // z . R, z . z
      for (const auto &[dof, z] : enclosed_pressure_mode)
        {
          along[0] += z * system_rhs(dof);
          along[1] += z * z;
        }
      Utilities::MPI::sum(along, communicator, along);
      if (along[1] == 0.)
        return;
      const double share = along[0] / along[1];
      for (const auto &[dof, z] : enclosed_pressure_mode)
        system_rhs(dof) -= share * z;
      system_rhs.compress(VectorOperation::insert);
    }



    template <int dim>
    dealii::TrilinosWrappers::MPI::Vector
    FlowDiscretisation<dim>::free_pressure_mask() const
    {
      TrilinosWrappers::MPI::Vector free_pressure(owned_partitioning[1],
                                                  communicator);
      free_pressure = 1.;
      for (const auto dof : decoupled_pressure_dofs)
        free_pressure(dof - dofs_per_block[0]) = 0.;
      free_pressure.compress(VectorOperation::insert);
      return free_pressure;
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::constrain_gradient()
    {
      if (!momentum_operator)
        return;
      // B^T of the outer operator: rows of constrained velocities and
      // columns of decoupled pressures zero (diagonal scalings by 0/1
      // masks)
      TrilinosWrappers::MPI::Vector free_velocity(owned_partitioning[0],
                                                  communicator);
      free_velocity = 1.;
      for (const auto dof : constrained_velocity_dofs)
        free_velocity(dof) = 0.;
      free_velocity.compress(VectorOperation::insert);
      const TrilinosWrappers::MPI::Vector free_pressure = free_pressure_mask();
      constrained_gradient.copy_from(gradient_matrix);
      // deal.II 9.4 hands out the Epetra matrix as const only; scaling
      // its values keeps its structure, which is all the wrapper keeps
      // of it
      auto &epetra = const_cast<Epetra_CrsMatrix &>(
        constrained_gradient.trilinos_matrix());
      AssertThrow(epetra.LeftScale(*free_velocity.trilinos_vector()(0)) == 0
                    && epetra.RightScale(*free_pressure.trilinos_vector()(0))
                         == 0,
                  ExcMessage("Epetra could not scale B^T."));
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::build_pressure_laplacian()
    {
      // L_p = B diag(M_u)^{-1} B^T from the divergence blocks of the current
      // matrix (they do not depend on the iterate, only on mesh and
      // constraints). The sign convention B = -div makes L_p positive.
      types::global_dof_index flow_row;
      if (momentum_operator)
        {
          // constrained velocities split into those of the boundary
          // conditions (mesh quantities, also where a body covers them) and
          // those that only bodies constrain
          std::vector<types::global_dof_index> mesh_fixed, covered;
          for (const auto dof : constrained_velocity_dofs)
            (std::binary_search(body_constrained_dofs.begin(),
                                body_constrained_dofs.end(),
                                dof) ?
               covered :
               mesh_fixed)
              .push_back(dof);
          const TrilinosWrappers::MPI::Vector free_pressure
            = free_pressure_mask();
          flow_row = pressure_laplacian_update.update(pressure_laplacian,
                                                      gradient_matrix,
                                                      inverse_lumped_mass,
                                                      mesh_fixed,
                                                      covered,
                                                      free_pressure);
        }
      else
        {
          system_matrix.block(1, 0).mmult(pressure_laplacian,
                                          system_matrix.block(0, 1),
                                          inverse_lumped_mass);
          regularise_empty_pressure_rows(pressure_laplacian, flow_row);
        }
      if (!parameters.boundary_conditions.pressure_is_determined())
        {
          // Enclosed flow: L_p is singular (constant pressures). Pinning one
          // pressure value makes the multigrid solve well posed; the
          // preconditioner only needs the action on mean-free data. The
          // pinned pressure must belong to the flow: that of a cell inside
          // a body is decoupled already, and pinning it left L_p singular.
          if (flow_row != numbers::invalid_dof_index
              && owned_partitioning[1].is_element(flow_row))
            pressure_laplacian.add(flow_row,
                                   flow_row,
                                   pressure_laplacian.diag_element(flow_row));
          pressure_laplacian.compress(VectorOperation::add);
        }
    }

    template void
    FlowDiscretisation<2>::constrain_gradient();
    template void
    FlowDiscretisation<3>::constrain_gradient();
    template void
    FlowDiscretisation<2>::assemble(const Stage &,
                                    const AssemblyTarget,
                                    const bool);
    template void
    FlowDiscretisation<3>::assemble(const Stage &,
                                    const AssemblyTarget,
                                    const bool);
    template void
    FlowDiscretisation<2>::linearise_momentum_operator(const Stage &,
                                                       const bool);
    template void
    FlowDiscretisation<3>::linearise_momentum_operator(const Stage &,
                                                       const bool);
    template void
    FlowDiscretisation<2>::compute_explicit_residual(const Stage &);
    template void
    FlowDiscretisation<3>::compute_explicit_residual(const Stage &);
    template void
    FlowDiscretisation<2>::assemble_residual_matrix_free(const Stage &);
    template void
    FlowDiscretisation<3>::assemble_residual_matrix_free(const Stage &);
    template void
    FlowDiscretisation<2>::build_pressure_laplacian();
    template void
    FlowDiscretisation<3>::build_pressure_laplacian();
  } // namespace fluid
} // namespace particulate
