#include <particulate/fluid/flow_discretisation.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <chrono>
#include <set>

#include "enclosed_fluid.h"
#include "flow_pressure_mode.h"
#include "geometric_cell_integrals.h"
#include "momentum_operator.h"
#include "undetermined_pressures.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /**
       * A velocity-only function seen as a (velocity, pressure) function with
       * zero pressure, so it can be used with the mixed element.
       */
      template <int dim>
      class VelocityWithPressure : public Function<dim>
      {
      public:
        explicit VelocityWithPressure(Function<dim> &velocity)
          : Function<dim>(dim + 1)
          , velocity(velocity)
        {}
        void
        set_time(const double t) override
        {
          Function<dim>::set_time(t);
          velocity.set_time(t);
        }
        double
        value(const Point<dim> &p, const unsigned int c) const override
        {
          return c < dim ? velocity.value(p, c) : 0.;
        }
        void
        vector_value(const Point<dim> &p, Vector<double> &v) const override
        {
          for (unsigned int c = 0; c < dim; ++c)
            v[c] = velocity.value(p, c);
          v[dim] = 0.;
        }

      private:
        Function<dim> &velocity;
      };
    } // namespace



    template <int dim>
    FlowDiscretisation<dim>::FlowDiscretisation(
      const FluidParameters                          &parameters,
      parallel::fullydistributed::Triangulation<dim> &tria,
      TimerOutput                                    &timer)
      : parameters(parameters)
      , communicator(tria.get_communicator())
      , timer(timer)
      , triangulation(tria)
      , fe(FE_Q<dim>(2), dim, FE_DGP<dim>(1), 1)
      , mapping(2)
      , dof_handler(tria)
      , viscosity_model(ViscosityModel::create(parameters.properties))
    {
      body_force = parameters.properties.body_force
                     .template create<dim>(dim, "Fluid / Body force");
      boundary_velocity
        = parameters.boundary_conditions.dirichlet_velocity
            .template create<dim>(dim, "Boundary conditions / Velocity");
    }



    template <int dim>
    FlowDiscretisation<dim>::~FlowDiscretisation() = default;



    template <int dim>
    void
    FlowDiscretisation<dim>::distribute_dofs()
    {
      TimerOutput::Scope scope(timer, "fluid: setup");
      dof_handler.distribute_dofs(fe);
      decoupled_pressures_searched_for.assign(1, numbers::invalid_dof_index);
      // Cuthill-McKee makes the ILU smoothers of the AMG more effective;
      // then velocity and pressure are put into separate blocks.
      DoFRenumbering::Cuthill_McKee(dof_handler);
      std::vector<unsigned int> block_component(dim + 1, 0);
      block_component[dim] = 1;
      DoFRenumbering::component_wise(dof_handler, block_component);

      dofs_per_block
        = DoFTools::count_dofs_per_fe_block(dof_handler, block_component);
      const IndexSet owned = dof_handler.locally_owned_dofs();
      owned_partitioning
        = {owned.get_view(0, dofs_per_block[0]),
           owned.get_view(dofs_per_block[0], dof_handler.n_dofs())};
      DoFTools::extract_locally_relevant_dofs(dof_handler,
                                              locally_relevant_dofs);
      relevant_partitioning
        = {locally_relevant_dofs.get_view(0, dofs_per_block[0]),
           locally_relevant_dofs.get_view(dofs_per_block[0],
                                          dof_handler.n_dofs())};
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::release_operator()
    {
      momentum_operator.reset();
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::setup_operator(
      const DoFHandler<dim> *velocity_dofs)
    {
      TimerOutput::Scope scope(timer, "fluid: setup");
      momentum_operator.reset();
      if (parameters.linear_solver.velocity_operator
          == VelocityOperator::matrix_free)
        {
          AssertThrow(velocity_dofs != nullptr,
                      ExcMessage("the matrix-free operator works on the "
                                 "velocity DoFs of the geometric multigrid"));
          momentum_operator
            = std::make_unique<MomentumOperator<dim>>(*velocity_dofs,
                                                      owned_partitioning[0],
                                                      mapping);
        }

      make_constraints(0.);
      setup_matrices();

      solution.reinit(owned_partitioning, relevant_partitioning, communicator);
      old_solution.reinit(solution);
      mesh_velocity.reinit(solution);
      system_rhs.reinit(owned_partitioning, communicator);
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::make_constraints(const double time)
    {
      const auto                      &bc = parameters.boundary_conditions;
      const FEValuesExtractors::Vector velocities(0);
      const ComponentMask velocity_mask = fe.component_mask(velocities);

      Functions::ZeroFunction<dim> zero(dim + 1);
      boundary_velocity->set_time(time);
      VelocityWithPressure<dim> dirichlet(*boundary_velocity);
      dirichlet.set_time(time);

      for (const bool homogeneous : {false, true})
        {
          AffineConstraints<double> &c
            = homogeneous ? zero_constraints : nonzero_constraints;
          c.clear();
          c.reinit(locally_relevant_dofs);
          DoFTools::make_hanging_node_constraints(dof_handler, c);
          for (const unsigned int id : bc.no_slip)
            VectorTools::interpolate_boundary_values(mapping,
                                                     dof_handler,
                                                     id,
                                                     zero,
                                                     c,
                                                     velocity_mask);
          for (const unsigned int id : bc.dirichlet)
            VectorTools::interpolate_boundary_values(
              mapping,
              dof_handler,
              id,
              homogeneous ? static_cast<Function<dim> &>(zero) : dirichlet,
              c,
              velocity_mask);
          if (!bc.free_slip.empty())
            {
              const std::set<types::boundary_id> ids(bc.free_slip.begin(),
                                                     bc.free_slip.end());
              VectorTools::compute_no_normal_flux_constraints(dof_handler,
                                                              0,
                                                              ids,
                                                              c,
                                                              mapping);
            }
          // Fictitious boundary (thesis eq. 5.17): u = U + omega x (x - X)
          // at the velocity nodes inside bodies. The boundary conditions
          // and hanging nodes come first and keep their rows.
          if (homogeneous)
            body_constrained_dofs.clear();
          for (std::size_t j = 0; j < fictitious_boundary_values.size(); ++j)
            {
              const auto dof = fictitious_boundary_values[j].first;
              if (c.can_store_line(dof) && !c.is_constrained(dof))
                {
                  c.add_line(dof);
                  if (!homogeneous)
                    c.set_inhomogeneity(dof,
                                        fictitious_boundary_value(j, time));
                  else
                    body_constrained_dofs.push_back(dof);
                }
            }
          if (homogeneous)
            std::sort(body_constrained_dofs.begin(),
                      body_constrained_dofs.end());
          c.close();
        }
      std::vector<types::global_dof_index> prescribed;
      prescribed.reserve(fictitious_boundary_values.size());
      for (const auto &entry : fictitious_boundary_values)
        prescribed.push_back(entry.first);
      std::sort(prescribed.begin(), prescribed.end());
      prescribed_velocity_dofs = prescribed;
      if (momentum_operator)
        {
          // The operator masks rows and columns: it can represent
          // constraints u_i = g, not u_i = sum_j c_ij u_j + g.
          constrained_velocity_dofs.clear();
          for (const auto &line : zero_constraints.get_lines())
            if (owned_partitioning[0].is_element(line.index))
              {
                if (!line.entries.empty())
                  throw std::runtime_error(
                    "'Velocity operator = matrix-free' (subsection 'Linear "
                    "solver') supports constraints of the form u_i = g "
                    "only, but velocity DoF "
                    + std::to_string(line.index)
                    + " depends on others (a hanging node, or a free-slip "
                      "boundary that is not a plane normal to a coordinate "
                      "axis). Use 'Velocity operator = assembled'.");
                constrained_velocity_dofs.push_back(line.index);
              }
          std::sort(constrained_velocity_dofs.begin(),
                    constrained_velocity_dofs.end());
          momentum_operator->set_constrained_dofs(constrained_velocity_dofs);
        }
      // The search depends on the covered nodes and the mesh only: the
      // stages of a time step (same bodies, new Dirichlet times) reuse it.
      // All ranks search when one's nodes changed: the pockets are found
      // together.
      if (Utilities::MPI::logical_or(
            prescribed != decoupled_pressures_searched_for
              || joint_velocity_dofs != joints_searched_for,
            communicator))
        {
          UndeterminedPressures undetermined;
          {
            TimerOutput::Scope scope(timer,
                                     "fluid: undetermined pressure search");
            undetermined = find_undetermined_pressure_dofs(dof_handler,
                                                           mapping,
                                                           zero_constraints,
                                                           prescribed,
                                                           joint_velocity_dofs);
          }
          decoupled_pressure_dofs = std::move(undetermined.decoupled);
          // fluid the bodies wall off from the flow (none without them)
          TimerOutput::Scope scope(timer, "fluid: enclosed fluid search");
          const bool         any_prescribed
            = Utilities::MPI::logical_or(!prescribed.empty(), communicator);
          const EnclosedFluid enclosed_fluid
            = any_prescribed ? find_enclosed_fluid(dof_handler,
                                                   zero_constraints,
                                                   decoupled_pressure_dofs,
                                                   communicator) :
                               EnclosedFluid();
          enclosed_pockets = enclosed_fluid.n_pockets;
          std::vector<types::global_dof_index> merged;
          std::set_union(decoupled_pressure_dofs.begin(),
                         decoupled_pressure_dofs.end(),
                         enclosed_fluid.pinned_pressures.begin(),
                         enclosed_fluid.pinned_pressures.end(),
                         std::back_inserter(merged));
          decoupled_pressure_dofs          = std::move(merged);
          decoupled_pressures_searched_for = std::move(prescribed);
          joints_searched_for              = joint_velocity_dofs;
          enclosed_pressure_mode.clear();
          if (constant_pressure_is_null)
            enclosed_pressure_mode
              = enclosed_flow_pressure_mode(enclosed_fluid.flow_constants,
                                            undetermined.patches,
                                            decoupled_pressure_dofs);
        }
    }



    template <int dim>
    double
    FlowDiscretisation<dim>::fictitious_boundary_value(const std::size_t j,
                                                       const double time) const
    {
      const double end = fictitious_boundary_values[j].second;
      // a stage's end time lies in (step_start, step_start + step_length];
      // any other time (set-up, initial condition) takes the end values
      const double tolerance = 1e-9 * step_length;
      if (fictitious_boundary_start_values.empty() || step_length <= 0.
          || time < step_start - tolerance
          || time > step_start + step_length + tolerance)
        return end;
      const double fraction
        = std::clamp((time - step_start) / step_length, 0., 1.);
      const double start = fictitious_boundary_start_values[j];
      return start + fraction * (end - start);
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::begin_step(const double time, const double k)
    {
      step_start  = time;
      step_length = k;
    }



    template <int dim>
    bool
    FlowDiscretisation<dim>::set_fictitious_boundary_values(
      std::vector<std::pair<types::global_dof_index, double>> values,
      std::vector<types::global_dof_index>                    joint_dofs,
      std::vector<double>                                     start_values)
    {
      AssertThrow(start_values.empty() || start_values.size() == values.size(),
                  ExcMessage("The fictitious-boundary start values must "
                             "match the values one to one."));
      // L_p = B D^{-1} B^T depends on which velocity DoFs are constrained:
      // rebuild it when a body has moved over a node (the values alone
      // change every step and do not matter to it).
      const bool same_nodes            = std::equal(values.begin(),
                                         values.end(),
                                         fictitious_boundary_values.begin(),
                                         fictitious_boundary_values.end(),
                                         [](const auto &a, const auto &b) {
                                           return a.first == b.first;
                                         });
      const bool same_joints           = joint_dofs == joint_velocity_dofs;
      fictitious_boundary_values       = std::move(values);
      fictitious_boundary_start_values = std::move(start_values);
      joint_velocity_dofs              = std::move(joint_dofs);
      // collective: every rank must rebuild together
      return Utilities::MPI::max(same_nodes && same_joints ? 0 : 1,
                                 communicator)
             > 0;
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::setup_matrices()
    {
      // who built preconditioners from these matrices has dropped them: ML's
      // ILU smoothers ask the matrix for its communicator when destroyed
      system_matrix.clear();
      gradient_matrix.clear();
      constrained_gradient.clear();
      pressure_mass.clear();
      pressure_laplacian.clear();
      pressure_laplacian_update.clear();

      const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
      {
        Table<2, DoFTools::Coupling> coupling(dim + 1, dim + 1);
        for (unsigned int c = 0; c < dim + 1; ++c)
          for (unsigned int d = 0; d < dim + 1; ++d)
            coupling[c][d]
              = (c == dim && d == dim) ? DoFTools::none : DoFTools::always;
        if (momentum_operator)
          // only the gradient block B^T (velocity rows, pressure columns),
          // without constraints: they enter by scaling (see
          // build_pressure_laplacian)
          for (unsigned int c = 0; c < dim + 1; ++c)
            for (unsigned int d = 0; d < dim + 1; ++d)
              coupling[c][d]
                = (c < dim && d == dim) ? DoFTools::always : DoFTools::none;
        // Constrained rows keep their couplings (keep_constrained_dofs =
        // true): the fictitious-boundary constraints change every time step
        // and must find their entries in the pattern.
        TrilinosWrappers::BlockSparsityPattern sp(owned_partitioning,
                                                  owned_partitioning,
                                                  relevant_partitioning,
                                                  communicator);
        AffineConstraints<double>              none;
        none.close();
        DoFTools::make_sparsity_pattern(dof_handler,
                                        coupling,
                                        sp,
                                        momentum_operator ? none :
                                                            zero_constraints,
                                        true,
                                        rank);
        sp.compress();
        if (momentum_operator)
          gradient_matrix.reinit(sp.block(0, 1));
        else
          system_matrix.reinit(sp);
      }
      {
        Table<2, DoFTools::Coupling> coupling(dim + 1, dim + 1);
        for (unsigned int c = 0; c < dim + 1; ++c)
          for (unsigned int d = 0; d < dim + 1; ++d)
            coupling[c][d]
              = (c == dim && d == dim) ? DoFTools::always : DoFTools::none;
        TrilinosWrappers::BlockSparsityPattern sp(owned_partitioning,
                                                  owned_partitioning,
                                                  relevant_partitioning,
                                                  communicator);
        DoFTools::make_sparsity_pattern(dof_handler,
                                        coupling,
                                        sp,
                                        zero_constraints,
                                        false,
                                        rank);
        sp.compress();
        pressure_mass.reinit(sp);
      }
      assemble_geometric_matrices();
      constant_pressure_is_null
        = !parameters.boundary_conditions.pressure_is_determined()
          && constant_pressure_is_null_mode(dof_handler,
                                            mapping,
                                            zero_constraints,
                                            owned_partitioning[0],
                                            locally_relevant_dofs,
                                            communicator);
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::assemble_geometric_matrices()
    {
      TimerOutput::Scope scope(timer, "fluid: geometric matrices");
      // B, M_p and the lumped velocity mass change (who built
      // preconditioners from them has dropped them)
      pressure_laplacian_update.clear();
      pressure_mass            = 0.;
      const bool with_gradient = momentum_operator != nullptr;
      if (with_gradient)
        gradient_matrix = 0.;
      // new DoFs or a moved mesh: search the undetermined pressures again
      decoupled_pressures_searched_for.assign(1, numbers::invalid_dof_index);
      // pressure mass matrix and lumped velocity mass: mesh quantities
      TrilinosWrappers::MPI::BlockVector lumped(owned_partitioning,
                                                communicator);
      const QGauss<dim>                  quadrature(3);
      FEValues<dim>                      fe_values(mapping,
                              fe,
                              quadrature,
                              update_values | update_JxW_values
                                | (with_gradient ? update_gradients :
                                                                        update_default));
      GeometricCellIntegrals<dim>        integrals(fe);
      const auto &velocity_dofs = integrals.velocity_dofs();
      const auto &pressure_dofs = integrals.pressure_dofs();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      std::vector<types::global_dof_index> velocity_rows(velocity_dofs.size());
      std::vector<types::global_dof_index> pressure_rows(pressure_dofs.size());
      std::vector<types::global_dof_index> pressure_columns(
        pressure_dofs.size());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            integrals.compute(fe_values, with_gradient);
            cell->get_dof_indices(dof_indices);
            for (unsigned int k = 0; k < pressure_dofs.size(); ++k)
              {
                pressure_rows[k]    = dof_indices[pressure_dofs[k]];
                pressure_columns[k] = pressure_rows[k] - dofs_per_block[0];
              }
            // pressure rows only, and the discontinuous pressure has no
            // constraints: added directly (the velocity constraints, which
            // change with the bodies, have no place in this matrix)
            for (unsigned int k = 0; k < pressure_dofs.size(); ++k)
              pressure_mass.add(pressure_rows[k],
                                pressure_rows.size(),
                                pressure_rows.data(),
                                integrals.mass_row(k));
            for (unsigned int a = 0; a < velocity_dofs.size(); ++a)
              velocity_rows[a] = dof_indices[velocity_dofs[a]];
            // the velocity block comes first: its global and block indices
            // agree
            lumped.block(0).add(velocity_rows, integrals.lumped());
            if (with_gradient)
              for (unsigned int a = 0; a < velocity_dofs.size(); ++a)
                gradient_matrix.add(velocity_rows[a],
                                    pressure_columns.size(),
                                    pressure_columns.data(),
                                    integrals.gradient_row(a));
          }
      if (with_gradient)
        {
          gradient_matrix.compress(VectorOperation::add);
          TimerOutput::Scope operator_scope(timer, "fluid: operator geometry");
          momentum_operator->update_geometry();
        }
      pressure_mass.compress(VectorOperation::add);
      lumped.compress(VectorOperation::add);
      inverse_lumped_mass.reinit(owned_partitioning[0], communicator);
      for (const auto i : owned_partitioning[0])
        {
          const double m         = lumped.block(0)(i);
          inverse_lumped_mass(i) = m > 0. ? 1. / m : 0.;
        }
      inverse_lumped_mass.compress(VectorOperation::insert);
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::set_initial_condition(const double time)
    {
      auto initial = parameters.initial_velocity.template create<dim>(
        dim,
        "Initial condition / Velocity");
      initial->set_time(time);
      BlockVector tmp(owned_partitioning, communicator);
      interpolate_velocity(*initial, tmp);
      make_constraints(time);
      nonzero_constraints.distribute(tmp);
      solution     = tmp;
      old_solution = solution;
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::interpolate_velocity(const Function<dim> &velocity,
                                                  BlockVector &vector) const
    {
      const FiniteElement<dim> &velocity_fe = fe.base_element(0);
      const Quadrature<dim>     nodes(velocity_fe.get_unit_support_points());
      FEValues<dim> fe_values(mapping, fe, nodes, update_quadrature_points);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      std::vector<Vector<double>> values(nodes.size(), Vector<double>(dim));
      const IndexSet             &owned = dof_handler.locally_owned_dofs();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            velocity.vector_value_list(fe_values.get_quadrature_points(),
                                       values);
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const auto base = fe.system_to_base_index(i);
                if (base.first.first == 0 && owned.is_element(dof_indices[i]))
                  vector(dof_indices[i])
                    = values[base.second](base.first.second);
              }
          }
      vector.compress(VectorOperation::insert);
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::set_mesh_velocity(const BlockVector &w)
    {
      mesh_velocity     = w;
      has_mesh_velocity = true;
    }



    namespace {
      /** x itself: interpolated, the coordinates of the velocity nodes. */
      template <int dim>
      class Position : public Function<dim>
      {
      public:
        Position()
          : Function<dim>(dim)
        {}
        double
        value(const Point<dim> &p, const unsigned int c) const override
        {
          return p[c];
        }
      };
    } // namespace



    template <int dim>
    void
    FlowDiscretisation<dim>::move_mesh(
      const std::function<void()> &move_vertices,
      const double                 time_step)
    {
      Assert(time_step > 0., ExcMessage("a mesh moves over a time step"));
      TimerOutput::Scope  scope(timer, "fluid: mesh motion");
      const Position<dim> position;
      BlockVector         before(owned_partitioning, communicator),
        after(owned_partitioning, communicator);
      interpolate_velocity(position, before);
      move_vertices();
      interpolate_velocity(position, after);
      // w = (x_new - x_old) / k at every velocity node, exactly the path
      // the node travelled: the nodal values move with it (ALE)
      after.block(0) -= before.block(0);
      after.block(0) /= time_step;
      after.block(1)    = 0.;
      mesh_velocity     = after;
      has_mesh_velocity = true;
      assemble_geometric_matrices();
    }



    template <int dim>
    double
    FlowDiscretisation<dim>::cfl_number(const double time_step) const
    {
      const QMidpoint<dim> quadrature;
      FEValues<dim>        fe_values(mapping, fe, quadrature, update_values);
      std::vector<Tensor<1, dim>>      u(1);
      const FEValuesExtractors::Vector velocities(0);
      double                           cfl = 0.;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[velocities].get_function_values(solution, u);
            // Q2: the node spacing is half the cell size
            cfl = std::max(cfl,
                           u[0].norm() * time_step
                             / (0.5 * cell->minimum_vertex_distance()));
          }
      return Utilities::MPI::max(cfl, communicator);
    }



    template <int dim>
    std::size_t
    FlowDiscretisation<dim>::memory_consumption() const
    {
      std::size_t bytes = 0;
      for (unsigned int i = 0; i < system_matrix.n_block_rows(); ++i)
        for (unsigned int j = 0; j < system_matrix.n_block_cols(); ++j)
          bytes += system_matrix.block(i, j).memory_consumption()
                   + pressure_mass.block(i, j).memory_consumption();
      if (pressure_laplacian.m() > 0)
        bytes += pressure_laplacian.memory_consumption();
      bytes += pressure_laplacian_update.memory_consumption();
      if (momentum_operator)
        bytes += momentum_operator->memory_consumption()
                 + gradient_matrix.memory_consumption()
                 + constrained_gradient.memory_consumption();
      for (const BlockVector *v :
           {&system_rhs, &solution, &old_solution, &mesh_velocity})
        bytes += v->memory_consumption();
      return bytes + inverse_lumped_mass.memory_consumption();
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::begin_stage(const Stage &stage)
    {
      make_constraints(stage.time_new);
      // The iterate starts from the previous solution with the new Dirichlet
      // values; the Newton updates then keep them (zero constraints).
      BlockVector iterate = make_owned_vector();
      iterate             = solution;
      nonzero_constraints.distribute(iterate);
      set_iterate(iterate);
      if (momentum_operator)
        compute_explicit_residual(stage);
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::set_iterate(BlockVector &iterate)
    {
      for (const auto dof : decoupled_pressure_dofs)
        iterate(dof) = 0.;
      solution = iterate;
    }



    template <int dim>
    const TrilinosWrappers::SparseMatrix *
    FlowDiscretisation<dim>::assembled_velocity_block() const
    {
      return momentum_operator ? nullptr : &system_matrix.block(0, 0);
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::normalise_pressure()
    {
      // Enclosed flow: the pressure is fixed up to a constant; give it zero
      // mean. FE_DGP's first shape function on each cell is the constant 1.
      const double mean = VectorTools::compute_mean_value(mapping,
                                                          dof_handler,
                                                          QGauss<dim>(3),
                                                          solution,
                                                          dim);
      BlockVector  tmp(owned_partitioning, communicator);
      tmp                             = solution;
      const unsigned int constant_dof = fe.component_to_system_index(dim, 0);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            tmp(dof_indices[constant_dof]) -= mean;
          }
      tmp.compress(VectorOperation::add);
      solution = tmp;
    }

    template class FlowDiscretisation<2>;
    template class FlowDiscretisation<3>;
  } // namespace fluid
} // namespace particulate
