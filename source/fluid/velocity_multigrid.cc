// simd.h first: it must precede every deal.II header
// clang-format off
#include "simd.h"
// clang-format on

#include <particulate/fluid/velocity_multigrid.h>
#include <particulate/fluid/velocity_solver_choice.h>

#include <deal.II/base/mg_level_object.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/matrix_free/tools.h>
#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_tools.h>
#include <deal.II/multigrid/mg_transfer_matrix_free.h>
#include <deal.II/multigrid/multigrid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "mass_viscous_operator.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      using LevelVector = LinearAlgebra::distributed::Vector<float>;
      /// level geometry and DoF maps, a batch of cells per SIMD instruction
      template <int dim>
      using LevelMatrixFree = MatrixFree<dim, float, SimdArray<float>>;

      /**
       * The coarse level (the unrefined input mesh), solved one of two ways:
       *
       * - a Chebyshev polynomial of the matrix-free level operator around
       *   its diagonal, of the degree that reduces the error by
       *   coarse_chebyshev_reduction over the eigenvalue range a few Lanczos
       *   steps estimate. When the mass term dominates (time steps of a few
       *   ms on the mm-sized cells of a sedimentation box) the Jacobi-scaled
       *   operator is about as well conditioned as the Q2 mass matrix and a
       *   polynomial of degree 4-6 does what the assembled path does (same
       *   FGMRES iterations), at a fraction of its cost: one ML cycle on the
       *   assembled Q2 matrix (~375 entries per row in 3D) costs as much as
       *   tens of matrix-free products on that level;
       * - its matrix, computed from the level operator's cell kernel,
       *   solved by CG with one ML AMG cycle as the preconditioner to a
       *   loose tolerance, when the polynomial would need a high degree:
       *   steady or viscous-dominated flow on a coarse mesh of many cells,
       *   where the level operator carries the viscous part's h^-2
       *   condition number.
       *
       * Either way the coarse solve is accurate enough to keep the V-cycle
       * independent of how coarse that mesh is. A mesh without refinement
       * has no other level: there the coarse solve is the whole V-cycle.
       */
      template <int dim>
      class CoarseSolver : public MGCoarseGridBase<LevelVector>
      {
      public:
        using Chebyshev
          = PreconditionChebyshev<MassViscousOperator<dim, float>, LevelVector>;

        /// the polynomial, when chosen (use_chebyshev)
        Chebyshev chebyshev;
        bool      use_chebyshev = false;

        TrilinosWrappers::SparseMatrix    matrix;
        TrilinosWrappers::PreconditionAMG amg;
        /// near-null space of the coarse matrix for ML: one constant mode
        /// per velocity component (locally owned rows)
        std::vector<std::vector<bool>> constant_modes;

        /** The coarse level's locally owned DoFs, and the run's timer, in
         *  whose profile the coarse solves get their own line. */
        void
        reinit(const IndexSet &owned,
               const MPI_Comm  communicator,
               TimerOutput    &run_timer)
        {
          rhs.reinit(owned, communicator);
          solution.reinit(owned, communicator);
          timer = &run_timer;
        }

        void
        operator()(const unsigned int,
                   LevelVector       &dst,
                   const LevelVector &src) const override
        {
          if (use_chebyshev)
            {
              TimerOutput::Scope scope(
                *timer,
                "fluid: velocity coarse solve (Chebyshev)");
              chebyshev.vmult(dst, src);
              return;
            }
          TimerOutput::Scope scope(*timer,
                                   "fluid: velocity coarse solve (CG + ML)");
          for (unsigned int i = 0; i < src.locally_owned_size(); ++i)
            rhs.begin()[i] = src.local_element(i);
          solution = 0.;
          SolverControl control(50, 1e-3 * rhs.l2_norm(), false, false);
          SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
          try
            {
              cg.solve(matrix, solution, rhs, amg);
            }
          catch (const SolverControl::NoConvergence &)
            {
              // an inexact coarse solve still gives a usable V-cycle; the
              // flexible outer solver judges convergence
            }
          for (unsigned int i = 0; i < dst.locally_owned_size(); ++i)
            dst.local_element(i) = solution.begin()[i];
        }

      private:
        mutable TrilinosWrappers::MPI::Vector rhs, solution;
        TimerOutput                          *timer = nullptr;
      };
    } // namespace



    template <int dim>
    struct VelocityMultigrid<dim>::Implementation
    {
      using FineVector    = LinearAlgebra::distributed::Vector<double>;
      using LevelOperator = MassViscousOperator<dim, float>;
      using Smoother      = PreconditionChebyshev<LevelOperator, LevelVector>;

      Implementation(const DoFHandler<dim> &system_dofs,
                     const IndexSet        &owned_velocity,
                     const Mapping<dim>    &mapping,
                     const Settings        &settings,
                     TimerOutput           &timer);

      void
      distribute_dofs();
      void
      make_level_constraints();
      void
      build_levels();
      /** The levels' geometric data for the current vertex positions: the
       *  mesh and the DoFs are those build_levels() saw. */
      void
      update_level_mappings();
      /** Level operators and V-cycles follow lazily, when a stage needs
       *  them. */
      void
      invalidate_hierarchies();

      const DoFHandler<dim> &system_dofs;
      const IndexSet         owned_velocity;
      const Mapping<dim>    &mapping;
      const Settings         settings;
      TimerOutput           &timer;
      const MPI_Comm         communicator;

      const FESystem<dim> fe;
      DoFHandler<dim>     dofs;
      unsigned int        finest_level = 0;
      MGConstrainedDoFs   mg_constrained_dofs;
      /// finest-level DoF of each locally owned velocity DoF (offset by
      /// the first owned index; the owned range is contiguous)
      std::vector<types::global_dof_index> active_to_level;
      std::vector<types::global_dof_index> masked_active_dofs;

      MGLevelObject<std::shared_ptr<LevelMatrixFree<dim>>> matrix_free;
      AffineConstraints<float>                             coarse_constraints;
      MGTransferMatrixFree<dim, float>                     transfer;
      /// the coarse matrix's pattern, locally owned rows, and the constant
      /// modes of its ML (shared by the hierarchies)
      std::unique_ptr<TrilinosWrappers::SparsityPattern> coarse_pattern;
      IndexSet                                           coarse_owned;
      std::vector<std::vector<bool>>                     coarse_modes;
      /// the finest level's masked DoFs (level numbering)
      std::vector<types::global_dof_index> masked_level_dofs;

      /**
       * The level operators with one set of coefficients and the V-cycle
       * built on them (smoother eigenvalue estimates, coarse matrix and its
       * AMG). Fractional-step theta alternates two sets of (rho/k,
       * theta_i) stage by stage; with one hierarchy per set the V-cycles
       * are built once per run instead of two or three times per step.
       */
      struct Hierarchy
      {
        MGLevelObject<LevelOperator>                                 operators;
        MGSmootherPrecondition<LevelOperator, Smoother, LevelVector> smoother;
        mg::Matrix<LevelVector>                                      mg_matrix;
        CoarseSolver<dim>                                            coarse;
        std::unique_ptr<Multigrid<LevelVector>>                      multigrid;
        std::unique_ptr<
          PreconditionMG<dim, LevelVector, MGTransferMatrixFree<dim, float>>>
                      preconditioner;
        bool          geometry_is_current = false;
        bool          linearised          = false;
        double        mass = -1., theta = -1.; ///< its coefficients
        unsigned long last_use = 0;
      };
      std::array<Hierarchy, 2> hierarchies;
      unsigned int             active = 0;
      unsigned long            n_uses = 0;

      /** Level operators and V-cycle of @p h on the current geometry. */
      void
      prepare(Hierarchy &h);

      /** The coarse solve of @p h for its current coefficients: Chebyshev
       *  if its degree for the wanted reduction stays at most
       *  max_coarse_chebyshev_degree, CG + ML otherwise. */
      void
      build_coarse_solver(Hierarchy &h);

      mutable FineVector fine_src, fine_dst;
    };



    template <int dim>
    VelocityMultigrid<dim>::Implementation::Implementation(
      const DoFHandler<dim> &system_dofs,
      const IndexSet        &owned_velocity,
      const Mapping<dim>    &mapping,
      const Settings        &settings,
      TimerOutput           &timer)
      : system_dofs(system_dofs)
      , owned_velocity(owned_velocity)
      , mapping(mapping)
      , settings(settings)
      , timer(timer)
      , communicator(system_dofs.get_communicator())
      , fe(FE_Q<dim>(2), dim)
      , dofs(system_dofs.get_triangulation())
    {
      if (system_dofs.get_triangulation().has_hanging_nodes())
        throw std::runtime_error(
          "The geometric multigrid velocity preconditioner needs a "
          "uniformly refined mesh (no hanging nodes). Use 'Velocity "
          "preconditioner = AMG' in subsection 'Linear solver'.");
      distribute_dofs();
      make_level_constraints();
      build_levels();
      fine_src.reinit(owned_velocity, communicator);
      fine_dst.reinit(owned_velocity, communicator);
    }



    /*
     * The velocity DoF handler gets the numbers of the velocity block of
     * the system: every locally owned velocity DoF is matched with its
     * system DoF through a cell that holds both (same component, same
     * index within the Q2 element). DoF ownership follows the cells in both
     * handlers alike, so the locally owned sets coincide.
     */
    template <int dim>
    void
    VelocityMultigrid<dim>::Implementation::distribute_dofs()
    {
      dofs.distribute_dofs(fe);
      const FiniteElement<dim> &system_fe = system_dofs.get_fe();
      std::vector<unsigned int> velocity_to_system(fe.n_dofs_per_cell());
      for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
        for (unsigned int i = 0; i < system_fe.n_dofs_per_cell(); ++i)
          if (system_fe.system_to_component_index(i)
              == fe.system_to_component_index(j))
            velocity_to_system[j] = i;

      const IndexSet                       owned = dofs.locally_owned_dofs();
      std::vector<types::global_dof_index> new_numbers(
        owned.n_elements(),
        numbers::invalid_dof_index);
      std::vector<types::global_dof_index> system_indices(
        system_fe.n_dofs_per_cell()),
        velocity_indices(fe.n_dofs_per_cell());
      for (const auto &cell : system_dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const typename DoFHandler<dim>::active_cell_iterator velocity_cell(
              &dofs.get_triangulation(),
              cell->level(),
              cell->index(),
              &dofs);
            cell->get_dof_indices(system_indices);
            velocity_cell->get_dof_indices(velocity_indices);
            for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
              if (owned.is_element(velocity_indices[j]))
                new_numbers[owned.index_within_set(velocity_indices[j])]
                  = system_indices[velocity_to_system[j]];
          }
      for (const auto n : new_numbers)
        AssertThrow(n != numbers::invalid_dof_index
                      && owned_velocity.is_element(n),
                    ExcMessage("Velocity multigrid: the velocity DoFs are "
                               "not owned alike in the two DoF handlers."));
      dofs.renumber_dofs(new_numbers);
      AssertThrow(dofs.locally_owned_dofs() == owned_velocity,
                  ExcInternalError());
      dofs.distribute_mg_dofs();
      finest_level = dofs.get_triangulation().n_global_levels() - 1;

      const types::global_dof_index first
        = owned_velocity.n_elements() > 0 ? owned_velocity.nth_index_in_set(0) :
                                            0;
      active_to_level.assign(owned_velocity.n_elements(),
                             numbers::invalid_dof_index);
      std::vector<types::global_dof_index> level_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            AssertThrow(static_cast<unsigned int>(cell->level())
                          == finest_level,
                        ExcInternalError());
            cell->get_dof_indices(velocity_indices);
            cell->get_mg_dof_indices(level_indices);
            for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
              if (owned_velocity.is_element(velocity_indices[j]))
                active_to_level[velocity_indices[j] - first] = level_indices[j];
          }
    }



    /*
     * The zero rows of every level: all velocity components on Dirichlet
     * boundaries, the normal component on free-slip planes. The DoFs are
     * collected here face by face rather than with MGConstrainedDoFs::
     * make_zero_boundary_constraints / make_no_normal_flux_constraints:
     * with those (deal.II 9.4) the ten Cate quarter box with the free-slip
     * plane x = 0 needed 189 FGMRES iterations per Newton step (with the
     * plane y = 0 instead: 7), with both planes 130-260; collected here, 7
     * and 6 (measured by switching back temporarily; the test
     * fluid_multigrid_matches_amg fails with those helpers: 5.3 times AMG's
     * iterations on its half channel). We did not find out which of the two
     * calls goes wrong.
     */
    template <int dim>
    void
    VelocityMultigrid<dim>::Implementation::make_level_constraints()
    {
      mg_constrained_dofs.initialize(dofs);
      const std::set<types::boundary_id> dirichlet(
        settings.dirichlet_ids.begin(),
        settings.dirichlet_ids.end());
      const std::set<types::boundary_id> free_slip(
        settings.free_slip_ids.begin(),
        settings.free_slip_ids.end());

      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      for (unsigned int level = 0; level <= finest_level; ++level)
        {
          IndexSet zero_rows(dofs.n_dofs(level));
          for (const auto &cell : dofs.mg_cell_iterators_on_level(level))
            if (cell->level_subdomain_id() != numbers::artificial_subdomain_id)
              for (const unsigned int f : cell->face_indices())
                if (cell->at_boundary(f))
                  {
                    const types::boundary_id id = cell->face(f)->boundary_id();
                    const bool is_dirichlet     = dirichlet.count(id) > 0;
                    if (!is_dirichlet && free_slip.count(id) == 0)
                      continue;
                    // the component along the plane's normal; the level
                    // rows can only fix whole components
                    const unsigned int normal_component
                      = is_dirichlet ? dim :
                                       axis_along_normal<dim>(cell->face(f));
                    if (!is_dirichlet && normal_component == dim)
                      {
                        std::ostringstream message;
                        message << "The geometric multigrid velocity "
                                   "preconditioner supports free-slip "
                                   "boundaries only on planes normal to a "
                                   "coordinate axis; boundary id "
                                << id << " is not (the face at "
                                << cell->face(f)->center() << " on level "
                                << level
                                << "). Use 'Velocity preconditioner = "
                                   "AMG' in subsection 'Linear solver'.";
                        throw std::runtime_error(message.str());
                      }
                    cell->face(f)->get_mg_dof_indices(level, face_dofs);
                    for (unsigned int i = 0; i < face_dofs.size(); ++i)
                      if (is_dirichlet
                          || fe.face_system_to_component_index(i, f).first
                               == normal_component)
                        zero_rows.add_index(face_dofs[i]);
                  }
          mg_constrained_dofs.add_boundary_indices(dofs, level, zero_rows);
        }
    }



    template <int dim>
    void
    VelocityMultigrid<dim>::Implementation::build_levels()
    {
      matrix_free.resize(0, finest_level);
      std::vector<std::shared_ptr<const Utilities::MPI::Partitioner>>
        partitioners(finest_level + 1);
      for (unsigned int level = 0; level <= finest_level; ++level)
        {
          const IndexSet relevant
            = DoFTools::extract_locally_relevant_level_dofs(dofs, level);
          AffineConstraints<float> constraints;
          constraints.reinit(relevant);
          constraints.add_lines(
            mg_constrained_dofs.get_boundary_indices(level));
          constraints.close();

          typename LevelMatrixFree<dim>::AdditionalData data;
          data.tasks_parallel_scheme
            = LevelMatrixFree<dim>::AdditionalData::none;
          data.mapping_update_flags
            = update_values | update_gradients | update_JxW_values;
          data.mg_level   = level;
          auto level_data = std::make_shared<LevelMatrixFree<dim>>();
          level_data->reinit(mapping, dofs, constraints, QGauss<1>(3), data);
          matrix_free[level]  = level_data;
          partitioners[level] = level_data->get_vector_partitioner();
          if (level == 0)
            coarse_constraints.copy_from(constraints);
        }
      transfer.clear();
      transfer.initialize_constraints(mg_constrained_dofs);
      transfer.build(dofs, partitioners);

      // the coarse matrix's pattern and ML's near-null space
      coarse_owned = dofs.locally_owned_mg_dofs(0);
      const IndexSet relevant0
        = DoFTools::extract_locally_relevant_level_dofs(dofs, 0);
      coarse_pattern
        = std::make_unique<TrilinosWrappers::SparsityPattern>(coarse_owned,
                                                              coarse_owned,
                                                              relevant0,
                                                              communicator);
      MGTools::make_sparsity_pattern(dofs, *coarse_pattern, 0);
      coarse_pattern->compress();
      coarse_modes.assign(dim,
                          std::vector<bool>(coarse_owned.n_elements(), false));
      std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
      for (const auto &cell : dofs.mg_cell_iterators_on_level(0))
        if (cell->is_locally_owned_on_level())
          {
            cell->get_mg_dof_indices(indices);
            for (unsigned int j = 0; j < indices.size(); ++j)
              if (coarse_owned.is_element(indices[j]))
                coarse_modes[fe.system_to_component_index(j).first]
                            [coarse_owned.index_within_set(indices[j])]
                  = true;
          }
      invalidate_hierarchies();
    }



    template <int dim>
    void
    VelocityMultigrid<dim>::Implementation::update_level_mappings()
    {
      // Only the Jacobians at the quadrature points change when vertices
      // move: DoF numbering, level partitioners, the transfer and the
      // coarse pattern stay as they are.
      for (unsigned int level = 0; level <= finest_level; ++level)
        matrix_free[level]->update_mapping(mapping);
      invalidate_hierarchies();
    }



    template <int dim>
    void
    VelocityMultigrid<dim>::Implementation::invalidate_hierarchies()
    {
      for (auto &h : hierarchies)
        {
          h.geometry_is_current = false;
          h.linearised          = false;
        }
    }



    template <int dim>
    void
    VelocityMultigrid<dim>::Implementation::prepare(Hierarchy &h)
    {
      if (h.geometry_is_current)
        return;
      h.operators.resize(0, finest_level);
      for (unsigned int level = 0; level <= finest_level; ++level)
        h.operators[level].initialize(matrix_free[level]);
      h.operators[finest_level].set_masked_dofs(masked_level_dofs);
      // ML's ILU smoothers ask their matrix for its communicator when
      // destroyed: the old hierarchy goes first
      h.coarse.amg.clear();
      h.coarse.matrix.clear();
      h.coarse.use_chebyshev = false;
      h.coarse.reinit(coarse_owned, communicator, timer);
      h.coarse.constant_modes = coarse_modes;
      h.mg_matrix.initialize(h.operators);
      h.multigrid      = std::make_unique<Multigrid<LevelVector>>(h.mg_matrix,
                                                             h.coarse,
                                                             transfer,
                                                             h.smoother,
                                                             h.smoother,
                                                             0,
                                                             finest_level);
      h.preconditioner = std::make_unique<
        PreconditionMG<dim, LevelVector, MGTransferMatrixFree<dim, float>>>(
        dofs,
        *h.multigrid,
        transfer);
      h.geometry_is_current = true;
      h.linearised          = false;
    }



    namespace {
      /*
       * The error reduction asked of the coarse Chebyshev polynomial, and
       * the largest degree that 'automatic' accepts. A looser reduction
       * leaves the outer FGMRES iterations unchanged as long as the
       * polynomial damps the smooth error by an order of magnitude; one
       * CG + AMG coarse solve costs tens of matrix-free products, so a
       * polynomial of degree up to 30 is still the cheaper one
       * (doc/performance.md).
       */
      constexpr double       coarse_chebyshev_reduction  = 0.1;
      constexpr unsigned int max_coarse_chebyshev_degree = 30;
    } // namespace



    template <int dim>
    void
    VelocityMultigrid<dim>::Implementation::build_coarse_solver(Hierarchy &h)
    {
      // ML's ILU smoothers ask their matrix for its communicator when
      // destroyed: the old hierarchy goes before its matrix
      h.coarse.amg.clear();
      h.coarse.use_chebyshev = false;
      if (settings.coarse_solver != CoarseSolve::cg_amg)
        {
          typename CoarseSolver<dim>::Chebyshev::AdditionalData data;
          data.degree          = numbers::invalid_unsigned_int;
          data.smoothing_range = coarse_chebyshev_reduction;
          // the level is small: enough Lanczos steps for a fair lambda_min
          data.eig_cg_n_iterations = 30;
          data.preconditioner = h.operators[0].get_matrix_diagonal_inverse();
          h.coarse.chebyshev.initialize(h.operators[0], data);
          LevelVector layout;
          h.operators[0].initialize_dof_vector(layout);
          const auto estimate = h.coarse.chebyshev.estimate_eigenvalues(layout);
          h.coarse.use_chebyshev
            = settings.coarse_solver == CoarseSolve::chebyshev
              || estimate.degree <= max_coarse_chebyshev_degree;
        }
      if (h.coarse.use_chebyshev)
        {
          h.coarse.matrix.clear();
          return;
        }

      h.coarse.matrix.reinit(*coarse_pattern);
      MatrixFreeTools::compute_matrix(*matrix_free[0],
                                      coarse_constraints,
                                      h.coarse.matrix,
                                      &LevelOperator::cell_kernel,
                                      &h.operators[0]);
      TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
      amg_data.constant_modes        = h.coarse.constant_modes;
      amg_data.elliptic              = true;
      amg_data.higher_order_elements = true;
      amg_data.smoother_type         = "ILU";
      amg_data.smoother_sweeps       = 2;
      amg_data.aggregation_threshold = 0.02;
      h.coarse.amg.initialize(h.coarse.matrix, amg_data);
    }



    template <int dim>
    VelocityMultigrid<dim>::VelocityMultigrid(
      const DoFHandler<dim> &system_dofs,
      const IndexSet        &owned_velocity,
      const Mapping<dim>    &mapping,
      const Settings        &settings,
      TimerOutput           &timer)
    {
      TimerOutput::Scope scope(timer, "fluid: velocity multigrid setup");
      implementation = std::make_unique<Implementation>(system_dofs,
                                                        owned_velocity,
                                                        mapping,
                                                        settings,
                                                        timer);
    }



    template <int dim>
    VelocityMultigrid<dim>::~VelocityMultigrid() = default;



    template <int dim>
    void
    VelocityMultigrid<dim>::update_geometry()
    {
      TimerOutput::Scope scope(implementation->timer,
                               "fluid: velocity multigrid setup");
      implementation->update_level_mappings();
      set_masked_dofs(implementation->masked_active_dofs);
    }



    template <int dim>
    void
    VelocityMultigrid<dim>::set_linearisation(
      const TrilinosWrappers::MPI::Vector &velocity,
      const double                         mass_coefficient,
      const double                         theta_implicit,
      const ViscosityModel                &viscosity_model)
    {
      auto &m = *implementation;
      // With a constant viscosity the operator depends only on the stage
      // (rho/k, theta_i): a hierarchy built for them is kept. Equal up to
      // rounding counts as equal: the last step of a run, shortened to
      // End time - t, has k off in its last bits, which rebuilt the
      // V-cycle (a tenth of a 20-step benchmark).
      const auto same = [](const double a, const double b) {
        return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
      };
      const bool variable_mu = viscosity_model.depends_on_shear_rate();
      ++m.n_uses;
      if (!variable_mu)
        for (unsigned int i = 0; i < m.hierarchies.size(); ++i)
          {
            auto &h = m.hierarchies[i];
            if (h.geometry_is_current && h.linearised
                && same(h.mass, mass_coefficient)
                && same(h.theta, theta_implicit))
              {
                m.active   = i;
                h.last_use = m.n_uses;
                return;
              }
          }
      // otherwise the least recently used one is rebuilt
      unsigned int chosen = 0;
      for (unsigned int i = 1; i < m.hierarchies.size(); ++i)
        if (m.hierarchies[i].last_use < m.hierarchies[chosen].last_use)
          chosen = i;
      auto              &h = m.hierarchies[chosen];
      TimerOutput::Scope scope(m.timer, "fluid: velocity multigrid update");
      m.prepare(h);
      MGLevelObject<LevelVector> level_velocity(0, m.finest_level);
      if (variable_mu)
        {
          std::copy(velocity.begin(), velocity.end(), m.fine_src.begin());
          m.transfer.interpolate_to_mg(m.dofs, level_velocity, m.fine_src);
        }

      using SmootherData = typename Implementation::Smoother::AdditionalData;
      MGLevelObject<SmootherData> smoother_data(0, m.finest_level);
      for (unsigned int level = 0; level <= m.finest_level; ++level)
        {
          h.operators[level].set_coefficients(level_velocity[level],
                                              mass_coefficient,
                                              theta_implicit,
                                              viscosity_model);
          auto &data  = smoother_data[level];
          data.degree = m.settings.smoother_degree;
          // Smooth the upper part of the spectrum; the coarse-grid
          // correction takes care of the rest.
          data.smoothing_range     = 15.;
          data.eig_cg_n_iterations = 12;
          data.preconditioner
            = h.operators[level].get_matrix_diagonal_inverse();
        }
      h.smoother.initialize(h.operators, smoother_data);

      m.build_coarse_solver(h);
      h.linearised = true;
      h.mass       = mass_coefficient;
      h.theta      = theta_implicit;
      h.last_use   = m.n_uses;
      m.active     = chosen;
    }



    template <int dim>
    void
    VelocityMultigrid<dim>::forget_linearisations()
    {
      for (auto &h : implementation->hierarchies)
        h.linearised = false;
    }



    template <int dim>
    void
    VelocityMultigrid<dim>::set_masked_dofs(
      const std::vector<types::global_dof_index> &dofs)
    {
      auto &m = *implementation;
      m.masked_active_dofs.clear();
      std::vector<types::global_dof_index> level_dofs;
      const types::global_dof_index        first
        = m.owned_velocity.n_elements() > 0 ?
            m.owned_velocity.nth_index_in_set(0) :
            0;
      for (const auto dof : dofs)
        if (m.owned_velocity.is_element(dof))
          {
            m.masked_active_dofs.push_back(dof);
            level_dofs.push_back(m.active_to_level[dof - first]);
          }
      m.masked_level_dofs = level_dofs;
      for (auto &h : m.hierarchies)
        if (h.geometry_is_current)
          h.operators[m.finest_level].set_masked_dofs(level_dofs);
    }



    template <int dim>
    void
    VelocityMultigrid<dim>::vmult(
      TrilinosWrappers::MPI::Vector       &dst,
      const TrilinosWrappers::MPI::Vector &src) const
    {
      auto &m = *implementation;
      AssertThrow(m.hierarchies[m.active].linearised,
                  ExcMessage("VelocityMultigrid::vmult before "
                             "set_linearisation()"));
      std::copy(src.begin(), src.end(), m.fine_src.begin());
      const types::global_dof_index first
        = m.owned_velocity.n_elements() > 0 ?
            m.owned_velocity.nth_index_in_set(0) :
            0;
      for (const auto dof : m.masked_active_dofs)
        m.fine_src.local_element(dof - first) = 0.;
      m.hierarchies[m.active].preconditioner->vmult(m.fine_dst, m.fine_src);
      for (const auto dof : m.masked_active_dofs)
        m.fine_dst.local_element(dof - first) = 0.;
      std::copy(m.fine_dst.begin(), m.fine_dst.end(), dst.begin());
    }



    template <int dim>
    const DoFHandler<dim> &
    VelocityMultigrid<dim>::get_dof_handler() const
    {
      return implementation->dofs;
    }



    template <int dim>
    std::size_t
    VelocityMultigrid<dim>::memory_consumption() const
    {
      const auto &m = *implementation;
      std::size_t bytes
        = m.transfer.memory_consumption() + m.dofs.memory_consumption();
      for (const auto &h : m.hierarchies)
        if (h.geometry_is_current)
          {
            bytes += h.coarse.matrix.memory_consumption();
            for (unsigned int level = 0; level <= m.finest_level; ++level)
              bytes += h.operators[level].memory_consumption();
          }
      return bytes;
    }

    template <int dim>
    double
    VelocityMultigrid<dim>::bytes_per_vcycle() const
    {
      const auto &m = *implementation;
      const auto &h = m.hierarchies[m.active];
      if (!h.geometry_is_current)
        return 0.;
      const double products = 2. * m.settings.smoother_degree + 1.;
      double       bytes    = 2. * m.transfer.memory_consumption();
      for (unsigned int level = 1; level <= m.finest_level; ++level)
        bytes += products
                 * (h.operators[level].memory_consumption()
                    + 2. * sizeof(float)
                        * m.dofs.locally_owned_mg_dofs(level).n_elements());
      return bytes;
    }



    template class VelocityMultigrid<2>;
    template class VelocityMultigrid<3>;
  } // namespace fluid
} // namespace particulate
