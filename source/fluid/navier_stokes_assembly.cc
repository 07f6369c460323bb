#include <particulate/fluid/cell_block_insertion.h>
#include <particulate/fluid/navier_stokes.h>

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
#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Vector.h>
#include <Teuchos_ParameterList.hpp>

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
     * and the right-hand side is -R. The Jacobian freezes mu at the current
     * iterate; the term rho (du.grad u, v) is the Newton part that the
     * fixed-point (Oseen) iteration omits.
     */
    template <int dim>
    void
    NavierStokes<dim>::assemble(const Stage &stage,
                                const bool   assemble_matrix,
                                const bool   newton)
    {
      if (momentum_operator)
        {
          // nothing to assemble: the residual comes from the matrix-free
          // form, and the operator takes the iterate instead of a Jacobian
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
          velocity_chebyshev.reset(); // built from the matrix it approximates
          velocity_multigrid_is_current = false;
        }
      system_rhs = 0;

      const double rho         = parameters.properties.density;
      const bool   steady      = stage.time_step == 0.;
      const double mass_coeff  = steady ? 0. : rho / stage.time_step;
      const double ti          = stage.theta_implicit;
      const double te          = steady ? 0. : stage.theta_explicit;
      const bool   variable_mu = viscosity_model->depends_on_shear_rate();

      const QGauss<dim>                quadrature(3);
      FEValues<dim>                    fe_values(mapping,
                              fe,
                              quadrature,
                              update_values | update_gradients
                                | update_quadrature_points | update_JxW_values);
      const unsigned int               dofs_per_cell = fe.n_dofs_per_cell();
      const unsigned int               n_q           = quadrature.size();
      const FEValuesExtractors::Vector velocities(0);
      const FEValuesExtractors::Scalar pressure(dim);

      FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
      Vector<double>     cell_rhs(dofs_per_cell);
      std::vector<types::global_dof_index> dof_indices(dofs_per_cell);

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
      std::vector<unsigned int>                  scalar_representative(n_s);
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          const auto [component, index] = fe.system_to_component_index(i);
          if (component < dim)
            {
              velocity_index[index][component] = i;
              if (component == 0)
                scalar_representative[index] = i;
            }
          else
            pressure_index[index] = i;
        }
      std::vector<double> phi(n_s), advect_phi(n_s), psi(n_p), diagonal(n_s);
      std::array<std::vector<double>, dim> grad_phi_by_component;
      grad_phi_by_component.fill(std::vector<double>(n_s));
      std::vector<Tensor<1, dim>> grad_phi(n_s);
      // the local matrix by blocks: (c, d) velocity components
      std::vector<double> block_uu(dim * dim * n_s * n_s);
      const auto          uu
        = [&](unsigned int c, unsigned int d, unsigned int a, unsigned int b)
        -> double & { return block_uu[((c * dim + d) * n_s + a) * n_s + b]; };
      // B: (pressure k, component d, scalar b) -> -(psi_k, d_d phi_b)
      std::vector<double> block_pu(n_p * dim * n_s);

      const bool has_body_force
        = dynamic_cast<const Functions::ZeroFunction<dim> *>(body_force.get())
          == nullptr;

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
            fe_values.reinit(cell);
            cell_rhs = 0;
            if (assemble_matrix)
              {
                std::fill(block_uu.begin(), block_uu.end(), 0.);
                std::fill(block_pu.begin(), block_pu.end(), 0.);
              }

            fe_values[velocities].get_function_values(solution, u);
            fe_values[velocities].get_function_gradients(solution, grad_u);
            fe_values[velocities].get_function_divergences(solution, div_u);
            fe_values[pressure].get_function_values(solution, p);
            if (!steady)
              {
                fe_values[velocities].get_function_values(old_solution, u_old);
                fe_values[velocities].get_function_gradients(old_solution,
                                                             grad_u_old);
              }
            if (has_mesh_velocity)
              fe_values[velocities].get_function_values(mesh_velocity, w);
            if (has_body_force)
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
                const double JxW = fe_values.JxW(q);
                for (unsigned int a = 0; a < n_s; ++a)
                  {
                    phi[a] = fe_values.shape_value(scalar_representative[a], q);
                    grad_phi[a]
                      = fe_values.shape_grad(scalar_representative[a], q);
                  }
                for (unsigned int k = 0; k < n_p; ++k)
                  psi[k] = fe_values.shape_value(pressure_index[k], q);

                const SymmetricTensor<2, dim> D  = symmetrize(grad_u[q]);
                const double                  mu = viscosity_model->viscosity(
                  variable_mu ? std::sqrt(2. * D * D) : 0.);
                Tensor<1, dim> advecting = u[q];
                if (has_mesh_velocity)
                  advecting -= w[q];

                // strong-form vector parts of the residual: (a, v) + (S, D(v))
                Tensor<1, dim> vector_part = ti * rho * (grad_u[q] * advecting);
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

                if (!assemble_matrix)
                  continue;
                // Jacobian, for trial phi_b e_d and test phi_a e_c:
                //   delta_cd [rho/k phi_a phi_b + ti mu grad phi_a.grad phi_b
                //             + ti rho phi_a (advecting.grad phi_b)]
                //   + ti mu d_d phi_a d_c phi_b   (the transpose in D(u))
                //   + ti rho d_d u_c phi_a phi_b  (Newton only)
                // The loops run over b innermost on contiguous rows of the
                // blocks (grad_phi stored by component); the pointers are
                // declared free of aliasing, without which GCC keeps these
                // loops scalar (a profile showed them at one double per
                // instruction).
                const double viscous       = ti * mu * JxW;
                const double newton_weight = newton ? ti * rho * JxW : 0.;
                for (unsigned int b = 0; b < n_s; ++b)
                  {
                    advect_phi[b] = ti * rho * (advecting * grad_phi[b]) * JxW;
                    for (unsigned int d = 0; d < dim; ++d)
                      grad_phi_by_component[d][b] = grad_phi[b][d];
                  }
                const double *__restrict const phi_b    = phi.data();
                const double *__restrict const advect_b = advect_phi.data();
                double *__restrict const diag           = diagonal.data();
                for (unsigned int a = 0; a < n_s; ++a)
                  {
                    const double mass_a = mass_coeff * phi[a] * JxW;
                    const double phi_a  = phi[a];
                    for (unsigned int b = 0; b < n_s; ++b)
                      diag[b] = mass_a * phi_b[b] + phi_a * advect_b[b];
                    for (unsigned int e = 0; e < dim; ++e)
                      {
                        const double *__restrict const grad_e
                          = grad_phi_by_component[e].data();
                        const double weight = viscous * grad_phi[a][e];
                        for (unsigned int b = 0; b < n_s; ++b)
                          diag[b] += weight * grad_e[b];
                      }
                    for (unsigned int c = 0; c < dim; ++c)
                      for (unsigned int d = 0; d < dim; ++d)
                        {
                          double *__restrict const row = &uu(c, d, a, 0);
                          const double *__restrict const grad_c
                            = grad_phi_by_component[c].data();
                          const double transposed = viscous * grad_phi[a][d];
                          const double convective
                            = newton_weight * phi_a * grad_u[q][c][d];
                          if (c == d)
                            for (unsigned int b = 0; b < n_s; ++b)
                              row[b] += transposed * grad_c[b]
                                        + convective * phi_b[b] + diag[b];
                          else
                            for (unsigned int b = 0; b < n_s; ++b)
                              row[b] += transposed * grad_c[b]
                                        + convective * phi_b[b];
                        }
                  }
                for (unsigned int k = 0; k < n_p; ++k)
                  for (unsigned int d = 0; d < dim; ++d)
                    for (unsigned int b = 0; b < n_s; ++b)
                      block_pu[(k * dim + d) * n_s + b]
                        -= psi[k] * grad_phi[b][d] * JxW;
              }

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
            if (assemble_matrix && !direct_insertion)
              zero_constraints.distribute_local_to_global(cell_matrix,
                                                          cell_rhs,
                                                          dof_indices,
                                                          system_matrix,
                                                          system_rhs);
            else
              zero_constraints.distribute_local_to_global(cell_rhs,
                                                          dof_indices,
                                                          system_rhs);
          }
      if (assemble_matrix)
        system_matrix.compress(VectorOperation::add);
      system_rhs.compress(VectorOperation::add);
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

      /** rho/k of a stage's time derivative, 0 for the steady problem. */
      double
      mass_coefficient(const Stage &stage, const double density)
      {
        return stage.time_step == 0. ? 0. : density / stage.time_step;
      }
    } // namespace



    template <int dim>
    void
    NavierStokes<dim>::linearise_momentum_operator(const Stage &stage,
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
                                           mass_coefficient(stage, rho),
                                           stage.theta_implicit,
                                           rho,
                                           newton,
                                           *viscosity_model);
      velocity_multigrid_is_current = false;
    }



    template <int dim>
    void
    NavierStokes<dim>::compute_explicit_residual(const Stage &stage)
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
            fe_values.reinit(cell);
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
    NavierStokes<dim>::assemble_residual_matrix_free(const Stage &stage)
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
                                              mass_coefficient(stage, rho),
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
    }



    template <int dim>
    void
    NavierStokes<dim>::build_schur_complement_approximation()
    {
      TimerOutput::Scope scope(timer, "fluid: Schur approximation");
      timer.enter_subsection("fluid: Schur approximation: L_p");
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

          // B^T of the outer operator: rows of constrained velocities and
          // columns of decoupled pressures zero (diagonal scalings by 0/1
          // masks)
          TrilinosWrappers::MPI::Vector free_velocity(owned_partitioning[0],
                                                      communicator);
          free_velocity = 1.;
          for (const auto dof : constrained_velocity_dofs)
            free_velocity(dof) = 0.;
          free_velocity.compress(VectorOperation::insert);
          TrilinosWrappers::MPI::Vector free_pressure(owned_partitioning[1],
                                                      communicator);
          free_pressure = 1.;
          for (const auto dof : decoupled_pressure_dofs)
            free_pressure(dof - dofs_per_block[0]) = 0.;
          free_pressure.compress(VectorOperation::insert);
          constrained_gradient.copy_from(gradient_matrix);
          // deal.II 9.4 hands out the Epetra matrix as const only; scaling
          // its values keeps its structure, which is all the wrapper keeps
          // of it
          auto &epetra = const_cast<Epetra_CrsMatrix &>(
            constrained_gradient.trilinos_matrix());
          AssertThrow(
            epetra.LeftScale(*free_velocity.trilinos_vector()(0)) == 0
              && epetra.RightScale(*free_pressure.trilinos_vector()(0)) == 0,
            ExcMessage("Epetra could not scale B^T."));

          // ML's ILU smoothers ask the matrix for its communicator when
          // destroyed: the old V-cycle goes before its matrix changes
          laplace_amg.reset();
          flow_row = pressure_laplacian_update.update(pressure_laplacian,
                                                      gradient_matrix,
                                                      inverse_lumped_mass,
                                                      mesh_fixed,
                                                      covered,
                                                      free_pressure);
        }
      else
        {
          laplace_amg.reset();
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
      timer.leave_subsection("fluid: Schur approximation: L_p");

      TimerOutput::Scope amg_scope(timer,
                                   "fluid: Schur approximation: AMG set-up");
      if (!mass_ilu) // M_p changes with the mesh only
        {
          mass_ilu = std::make_unique<TrilinosWrappers::PreconditionILU>();
          mass_ilu->initialize(pressure_mass.block(1, 1));
        }
      // A new V-cycle for every new L_p (the old one went above). Two
      // ways to save its set-up did not pay at ten Cate level 2 (issue 8
      // item 12 in doc/performance.md): recomputing it on its aggregates
      // (PreconditionAMG::reinit) cost as much as a new build (0.95 s
      // against 0.84 s; the ILU factorisations and Galerkin products
      // dominate, not the aggregation), and keeping the old V-cycle for
      // the updated L_p tripled the CG iterations (6.3 -> 18.7 per solve):
      // a pressure freed by the body was an isolated row in the old one.
      // Near-null space for ML. L_p's is the constant pressure, i.e. the
      // constant mode's DoF of every cell (1) and none of the linear modes
      // (0). Given alone, an aggregate of linear-mode DoFs only (left where
      // a cut cell's constant mode is decoupled, see
      // decoupled_pressure_dofs) has a zero null space, its tentative
      // prolongator is singular and the V-cycle returns NaN (ten Cate E4
      // full box, nearest marking, t = 0.445 s). So the aggregation works
      // on cells: ML's "PDE equations" = dim + 1 blocks the dim + 1
      // pressure DoFs of a cell, which the numbering keeps consecutive
      // (checked here), and every aggregate holds a constant mode.
      // Where the numbering does not, one 0/1 vector per mode is the
      // fall-back; its coarse levels are dim + 1 times larger (with it the
      // Schur complement solves took twice as long on the 3D channel and
      // ten Cate E4, doc/performance.md).
      const IndexSet                &owned_pressures = owned_partitioning[1];
      const types::global_dof_index  n_owned = owned_pressures.n_elements();
      std::vector<std::vector<bool>> pressure_modes(dim + 1,
                                                    std::vector<bool>(n_owned,
                                                                      false));
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      bool cells_are_blocks = n_owned % (dim + 1) == 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            types::global_dof_index block = numbers::invalid_dof_index;
            for (unsigned int i = 0; i < dof_indices.size(); ++i)
              {
                const auto [component, mode] = fe.system_to_component_index(i);
                if (component != dim)
                  continue;
                const auto local = owned_pressures.index_within_set(
                  dof_indices[i] - dofs_per_block[0]);
                pressure_modes[mode][local] = true;
                if (block == numbers::invalid_dof_index)
                  block = local / (dim + 1);
                cells_are_blocks &= local / (dim + 1) == block;
              }
          }
      cells_are_blocks
        = Utilities::MPI::min(cells_are_blocks ? 1 : 0, communicator) == 1;

      // Smoother ('Pressure Laplacian smoother'): by default one ILU(0)
      // sweep before and after the coarse correction. With the
      // Jacobi-Chebyshev smoother the inner CG needed 14.7 / 23.5
      // iterations per solve at ten Cate r = 1 / 2; at r = 1 its coarse
      // level is already solved exactly (two levels: a W-cycle gives the
      // same counts), and the counts fell only in proportion to the
      // Chebyshev degree: the smoother, not the coarse space, was what
      // limited. With ILU(0): 3.9 / 5.5 iterations. ILU(0) of the
      // symmetric L_p is symmetric, so the V-cycle stays a valid CG
      // preconditioner (doc/performance.md, "Pressure Laplacian: the AMG
      // smoother"). On the 3D DFG channel at level 2 Chebyshev is faster.
      TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
      amg_data.elliptic              = true;
      amg_data.higher_order_elements = false;
      if (parameters.linear_solver.pressure_laplacian_smoother == "ILU")
        {
          amg_data.smoother_type   = "ILU";
          amg_data.smoother_sweeps = 1;
        }
      else
        {
          amg_data.smoother_type   = "Chebyshev";
          amg_data.smoother_sweeps = 2;
        }
      amg_data.aggregation_threshold = 0.02;
      laplace_amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      if (cells_are_blocks)
        {
          amg_data.constant_modes = {pressure_modes[0]};
          Teuchos::ParameterList              ml_parameters;
          std::unique_ptr<Epetra_MultiVector> distributed_modes;
          amg_data.set_parameters(ml_parameters,
                                  distributed_modes,
                                  pressure_laplacian);
          ml_parameters.set("PDE equations", static_cast<int>(dim + 1));
          laplace_amg->initialize(pressure_laplacian, ml_parameters);
        }
      else
        {
          amg_data.constant_modes = pressure_modes;
          laplace_amg->initialize(pressure_laplacian, amg_data);
        }
      if (parameters.linear_solver.verbose)
        pcout << "      L_p AMG: "
              << (cells_are_blocks ? "aggregation by cells, constant mode" :
                                     "one near-null vector per pressure mode")
              << std::endl;
      schur_approximation_is_current = true;
    }

    template void
    NavierStokes<2>::assemble(const Stage &, const bool, const bool);
    template void
    NavierStokes<3>::assemble(const Stage &, const bool, const bool);
    template void
    NavierStokes<2>::linearise_momentum_operator(const Stage &, const bool);
    template void
    NavierStokes<3>::linearise_momentum_operator(const Stage &, const bool);
    template void
    NavierStokes<2>::compute_explicit_residual(const Stage &);
    template void
    NavierStokes<3>::compute_explicit_residual(const Stage &);
    template void
    NavierStokes<2>::assemble_residual_matrix_free(const Stage &);
    template void
    NavierStokes<3>::assemble_residual_matrix_free(const Stage &);
    template void
    NavierStokes<2>::build_schur_complement_approximation();
    template void
    NavierStokes<3>::build_schur_complement_approximation();
  } // namespace fluid
} // namespace particulate
