#include <particulate/core/choice_names.h>
#include <particulate/core/input_file.h>
#include <particulate/core/parameter_text.h>
#include <particulate/fluid/fluid_parameters.h>

#include <algorithm>
#include <map>
#include <stdexcept>

namespace particulate {
  namespace fluid {
    using dealii::ParameterHandler;
    namespace Patterns  = dealii::Patterns;
    namespace Utilities = dealii::Utilities;

    namespace {
      std::vector<unsigned int>
      id_list(const ParameterHandler &prm, const std::string &name)
      {
        std::vector<unsigned int> ids;
        for (const auto &s : Utilities::split_string_list(prm.get(name)))
          ids.push_back(Utilities::string_to_int(s));
        return ids;
      }

      std::vector<double>
      double_list(const ParameterHandler &prm, const std::string &name)
      {
        std::vector<double> v;
        for (const auto &s : Utilities::split_string_list(prm.get(name)))
          v.push_back(Utilities::string_to_double(s));
        return v;
      }

      const core::ChoiceNames<ViscosityModelType> viscosity_model_names
        = {{ViscosityModelType::newtonian, "Newtonian"},
           {ViscosityModelType::carreau, "Carreau"},
           {ViscosityModelType::cross, "Cross"},
           {ViscosityModelType::power_law, "power law"},
           {ViscosityModelType::table, "table"}};
      const core::ChoiceNames<NonlinearMethod> nonlinear_method_names
        = {{NonlinearMethod::newton, "Newton"},
           {NonlinearMethod::fixed_point, "fixed point"}};
      const core::ChoiceNames<InitialGuess> initial_guess_names
        = {{InitialGuess::extrapolated, "extrapolated"},
           {InitialGuess::previous_solution, "previous solution"}};
      const core::ChoiceNames<SchurApproximation> schur_names
        = {{SchurApproximation::automatic, "automatic"},
           {SchurApproximation::cahouet_chabard, "Cahouet-Chabard"},
           {SchurApproximation::least_squares_commutator,
            "least-squares commutator"}};
      const core::ChoiceNames<PressureLaplacianSmoother>
        laplacian_smoother_names
        = {{PressureLaplacianSmoother::ilu, "ILU"},
           {PressureLaplacianSmoother::chebyshev, "Chebyshev"}};
      const core::ChoiceNames<VelocityPreconditioner>
        velocity_preconditioner_names
        = {{VelocityPreconditioner::automatic, "automatic"},
           {VelocityPreconditioner::amg, "AMG"},
           {VelocityPreconditioner::chebyshev, "Chebyshev"},
           {VelocityPreconditioner::geometric_multigrid,
            "geometric multigrid"}};
      const core::ChoiceNames<VelocityOperator> velocity_operator_names
        = {{VelocityOperator::automatic, "automatic"},
           {VelocityOperator::assembled, "assembled"},
           {VelocityOperator::matrix_free, "matrix-free"}};
      const core::ChoiceNames<MultigridCoarseSolver> coarse_solver_names
        = {{MultigridCoarseSolver::automatic, "automatic"},
           {MultigridCoarseSolver::chebyshev, "Chebyshev"},
           {MultigridCoarseSolver::cg_amg, "CG + AMG"}};
      const core::ChoiceNames<MultigridOnMovingMesh> moving_mesh_names
        = {{MultigridOnMovingMesh::rebuild, "rebuild"},
           {MultigridOnMovingMesh::keep, "keep"}};
      const core::ChoiceNames<AmgSmoother> amg_smoother_names
        = {{AmgSmoother::chebyshev, "Chebyshev"},
           {AmgSmoother::symmetric_gauss_seidel, "symmetric Gauss-Seidel"},
           {AmgSmoother::gauss_seidel, "Gauss-Seidel"},
           {AmgSmoother::ilu, "ILU"}};
    } // namespace



    std::string
    to_string(const ViscosityModelType choice)
    {
      return core::name_of(viscosity_model_names, choice);
    }

    std::string
    to_string(const NonlinearMethod choice)
    {
      return core::name_of(nonlinear_method_names, choice);
    }

    std::string
    to_string(const InitialGuess choice)
    {
      return core::name_of(initial_guess_names, choice);
    }

    std::string
    to_string(const SchurApproximation choice)
    {
      return core::name_of(schur_names, choice);
    }

    std::string
    to_string(const PressureLaplacianSmoother choice)
    {
      return core::name_of(laplacian_smoother_names, choice);
    }

    std::string
    to_string(const VelocityPreconditioner choice)
    {
      return core::name_of(velocity_preconditioner_names, choice);
    }

    std::string
    to_string(const VelocityOperator choice)
    {
      return core::name_of(velocity_operator_names, choice);
    }

    std::string
    to_string(const MultigridCoarseSolver choice)
    {
      return core::name_of(coarse_solver_names, choice);
    }

    std::string
    to_string(const MultigridOnMovingMesh choice)
    {
      return core::name_of(moving_mesh_names, choice);
    }

    std::string
    to_string(const AmgSmoother choice)
    {
      return core::name_of(amg_smoother_names, choice);
    }



    void
    FluidProperties::declare(ParameterHandler &prm)
    {
      const FluidProperties defaults;
      prm.enter_subsection("Fluid");
      prm.declare_entry("Density",
                        core::number_text(defaults.density),
                        Patterns::Double(0.),
                        "Fluid density rho [kg/m^3].");
      prm.declare_entry("Dynamic viscosity",
                        core::number_text(defaults.dynamic_viscosity),
                        Patterns::Double(0.),
                        "Dynamic viscosity mu [Pa s] (NOT the kinematic "
                        "viscosity nu = mu/rho). For Carreau and Cross it is "
                        "the zero-shear viscosity mu_0.");
      prm.declare_entry(
        "Viscosity model",
        to_string(defaults.viscosity_model),
        Patterns::Selection(core::selection_of(viscosity_model_names)),
        "mu as a function of the shear rate g = sqrt(2 D:D). Newtonian: "
        "constant mu. Carreau: mu_inf + (mu_0 - mu_inf) (1 + (lambda "
        "g)^2)^((n-1)/2), shear-thinning for n < 1 and shear-thickening for "
        "n > 1. Cross: mu_inf + (mu_0 - mu_inf) / (1 + (lambda g)^(1-n)), "
        "n < 1, from mu_0 at rest to mu_inf at high shear rates: "
        "shear-thinning for mu_inf < mu_0, shear-thickening with a bounded "
        "rise for mu_inf > mu_0 (n = -1: smooth in g^2). power law: K max(g, g_min)^(n-1). table: "
        "interpolated from 'Viscosity table'. Newton's method linearises the "
        "viscosity's dependence on the shear rate as well.");
      prm.declare_entry("Infinite-shear viscosity",
                        core::number_text(defaults.infinite_shear_viscosity),
                        Patterns::Double(0.),
                        "Carreau and Cross: mu_inf [Pa s].");
      prm.declare_entry("Relaxation time",
                        core::number_text(defaults.relaxation_time),
                        Patterns::Double(0.),
                        "Carreau and Cross: lambda [s]; 1/lambda is the shear "
                        "rate where the viscosity leaves mu_0.");
      prm.declare_entry("Power-law index",
                        core::number_text(defaults.power_law_index),
                        Patterns::Double(),
                        "Carreau, Cross and power law: n [-]; positive for "
                        "Carreau and power law, below 1 for Cross.");
      prm.declare_entry("Consistency",
                        core::number_text(defaults.consistency),
                        Patterns::Double(0.),
                        "power law: K [Pa s^n], the viscosity at g = 1/s.");
      prm.declare_entry("Minimum shear rate",
                        core::number_text(defaults.minimum_shear_rate),
                        Patterns::Double(0.),
                        "power law: g_min [1/s]. Below it the viscosity is "
                        "constant, which keeps it finite at rest for n < 1 "
                        "and positive for n > 1. Take it well below the "
                        "flow's shear rates.");
      prm.declare_entry("Viscosity table",
                        defaults.viscosity_table,
                        Patterns::Anything(),
                        "table: a file of rows 'shear rate [1/s]  viscosity "
                        "[Pa s]' ('#' starts a comment; a relative path "
                        "starts at the case file's folder), shear rates "
                        "increasing. Interpolated by a monotone cubic in "
                        "log-log; beyond its ends the end's viscosity.");
      core::FunctionExpression::declare(prm,
                                        "Body force",
                                        "",
                                        "Body force per unit mass f [m/s^2], "
                                        "e.g. gravity '0; -9.81'.");
      prm.leave_subsection();
    }

    void
    FluidProperties::check_viscosity_model() const
    {
      if ((viscosity_model == ViscosityModelType::carreau
           || viscosity_model == ViscosityModelType::power_law)
          && !(power_law_index > 0.))
        throw std::runtime_error(
          "subsection 'Fluid': 'Power-law index' must be positive for the "
          "Carreau and power laws: at n = 0 the stress stops growing with "
          "the shear rate, and no flow is determined by it.");
      if (viscosity_model == ViscosityModelType::cross
          && !(power_law_index < 1.))
        throw std::runtime_error(
          "subsection 'Fluid': the Cross law needs 'Power-law index' below "
          "1 (it is "
          + core::number_text(power_law_index)
          + "): its viscosity moves from mu_0 to mu_inf as (lambda "
            "g)^(1-n) grows. For a shear-thickening fluid give it mu_inf > "
            "mu_0, or use 'Carreau' with n > 1, 'power law' or 'table'.");
      if (viscosity_model == ViscosityModelType::table
          && viscosity_table.empty())
        throw std::runtime_error(
          "subsection 'Fluid': 'Viscosity model = table' needs the file of "
          "(shear rate, viscosity) rows in 'Viscosity table'.");
    }



    void
    FluidProperties::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Fluid");
      density = core::get_positive_double(prm, "Density", "Fluid");
      dynamic_viscosity
        = core::get_positive_double(prm, "Dynamic viscosity", "Fluid");
      viscosity_model
        = core::choice_named(viscosity_model_names, prm.get("Viscosity model"));
      infinite_shear_viscosity = prm.get_double("Infinite-shear viscosity");
      relaxation_time          = prm.get_double("Relaxation time");
      power_law_index          = prm.get_double("Power-law index");
      consistency = core::get_positive_double(prm, "Consistency", "Fluid");
      minimum_shear_rate
        = core::get_positive_double(prm, "Minimum shear rate", "Fluid");
      viscosity_table = Utilities::trim(prm.get("Viscosity table"));
      check_viscosity_model();
      body_force.parse(prm, "Body force");
      prm.leave_subsection();
    }



    void
    BoundaryConditions::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      const auto ids = Patterns::List(Patterns::Integer(0, 255), 0);
      prm.declare_entry("No-slip",
                        "",
                        ids,
                        "Boundary ids of walls at rest (u = 0).");
      prm.declare_entry("Dirichlet velocity",
                        "",
                        ids,
                        "Boundary ids where u = 'Velocity' (e.g. an inflow).");
      prm.declare_entry("Free-slip",
                        "",
                        ids,
                        "Boundary ids with u.n = 0 and no tangential traction "
                        "(symmetry planes). Planar boundaries only.");
      prm.declare_entry("Do-nothing",
                        "",
                        ids,
                        "Boundary ids with zero traction sigma.n = 0 "
                        "(outflow). The pressure level is then fixed; without "
                        "any, the pressure has zero mean.");
      core::FunctionExpression::declare(prm,
                                        "Velocity",
                                        "",
                                        "Velocity [m/s] on the 'Dirichlet "
                                        "velocity' boundaries.");
      prm.leave_subsection();
    }

    void
    BoundaryConditions::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      no_slip    = id_list(prm, "No-slip");
      dirichlet  = id_list(prm, "Dirichlet velocity");
      free_slip  = id_list(prm, "Free-slip");
      do_nothing = id_list(prm, "Do-nothing");
      dirichlet_velocity.parse(prm, "Velocity");
      prm.leave_subsection();
    }

    void
    BoundaryConditions::check(const std::vector<unsigned int> &mesh_ids,
                              const std::string &parameter_file) const
    {
      const std::string where
        = parameter_file + ": subsection 'Boundary conditions': ";
      std::map<unsigned int, std::string> owner;
      const auto claim = [&](const std::vector<unsigned int> &ids,
                             const std::string               &entry) {
        for (const unsigned int id : ids)
          {
            if (owner.count(id))
              throw std::runtime_error(
                where + "boundary id " + std::to_string(id)
                + " is listed under both '" + owner[id] + "' and '" + entry
                + "'. Give each boundary exactly one condition.");
            owner[id] = entry;
            if (std::find(mesh_ids.begin(), mesh_ids.end(), id)
                == mesh_ids.end())
              {
                std::string present;
                for (const unsigned int m : mesh_ids)
                  present += " " + std::to_string(m);
                throw std::runtime_error(where + "entry '" + entry
                                         + "' names boundary id "
                                         + std::to_string(id)
                                         + ", which is not on the mesh (the "
                                           "mesh has boundary ids"
                                         + present + ").");
              }
          }
      };
      claim(no_slip, "No-slip");
      claim(dirichlet, "Dirichlet velocity");
      claim(free_slip, "Free-slip");
      claim(do_nothing, "Do-nothing");
      for (const unsigned int id : mesh_ids)
        if (!owner.count(id))
          throw std::runtime_error(
            where + "the mesh has boundary id " + std::to_string(id)
            + " but no condition for it. Add it to 'No-slip', 'Dirichlet "
              "velocity', 'Free-slip' or 'Do-nothing'.");
    }



    void
    NonlinearSolverParameters::declare(ParameterHandler &prm)
    {
      const NonlinearSolverParameters defaults;
      prm.enter_subsection("Nonlinear solver");
      prm.declare_entry("Method",
                        to_string(defaults.method),
                        Patterns::Selection(
                          core::selection_of(nonlinear_method_names)),
                        "Linearisation of the convective term. Newton "
                        "converges quadratically; it falls back to the "
                        "fixed-point (Oseen) iteration for the rest of the "
                        "step when the residual stops decreasing.");
      prm.declare_entry("Absolute tolerance",
                        core::number_text(defaults.absolute_tolerance),
                        Patterns::Double(0.),
                        "Stop when the l2 norm of the residual is below this.");
      prm.declare_entry("Relative tolerance",
                        core::number_text(defaults.relative_tolerance),
                        Patterns::Double(0.),
                        "Stop when the residual has fallen by this factor.");
      prm.declare_entry("Maximum iterations",
                        std::to_string(defaults.maximum_iterations),
                        Patterns::Integer(1),
                        "Nonlinear iterations per (sub)step before the run "
                        "stops with an error.");
      prm.declare_entry(
        "Initial guess",
        to_string(defaults.initial_guess),
        Patterns::Selection(core::selection_of(initial_guess_names)),
        "First iterate of every (sub)step. 'extrapolated': the solution at "
        "the start of the (sub)step plus the rate of change over the last "
        "full time step (fewer Newton and FGMRES iterations once the flow "
        "evolves smoothly); 'previous solution': the solution at the start "
        "of the (sub)step.");
      prm.leave_subsection();
    }

    void
    NonlinearSolverParameters::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      method = core::choice_named(nonlinear_method_names, prm.get("Method"));
      absolute_tolerance = prm.get_double("Absolute tolerance");
      relative_tolerance = prm.get_double("Relative tolerance");
      maximum_iterations = prm.get_integer("Maximum iterations");
      initial_guess
        = core::choice_named(initial_guess_names, prm.get("Initial guess"));
      prm.leave_subsection();
    }



    void
    LinearSolverParameters::declare(ParameterHandler &prm)
    {
      const LinearSolverParameters defaults;
      prm.enter_subsection("Linear solver");
      prm.declare_entry("Relative tolerance",
                        core::number_text(defaults.relative_tolerance),
                        Patterns::Double(0.),
                        "FGMRES stops when the residual of the Newton update "
                        "has fallen by this factor.");
      prm.declare_entry("Maximum iterations",
                        std::to_string(defaults.maximum_iterations),
                        Patterns::Integer(1),
                        "FGMRES iterations before the run stops with an "
                        "error.");
      prm.declare_entry("Krylov subspace size",
                        std::to_string(defaults.krylov_size),
                        Patterns::Integer(5),
                        "Restart length of FGMRES.");
      prm.declare_entry(
        "Schur complement approximation",
        to_string(defaults.schur_approximation),
        Patterns::Selection(core::selection_of(schur_names)),
        "Cahouet-Chabard: theta mu M_p^-1 + rho/k L_p^-1, cheap and robust "
        "for time-dependent flow at any time step; for steady flow it is "
        "the pressure mass matrix mu M_p^-1 alone, whose iterations hardly "
        "grow with the mesh level but are many. least-squares commutator "
        "(LSC): L_p^-1 B D^-1 A D^-1 B^T L_p^-1 with D the lumped velocity "
        "mass; it captures convection, so steady solves need far fewer "
        "iterations, though more on each finer level (doc/performance.md). "
        "automatic: LSC for 'Scheme = "
        "steady', Cahouet-Chabard otherwise.");
      prm.declare_entry(
        "Pressure Poisson tolerance",
        defaults.pressure_poisson_tolerance > 0. ?
          core::number_text(defaults.pressure_poisson_tolerance) :
          std::string("automatic"),
        Patterns::Anything(),
        "Relative tolerance of the inner CG+AMG solves with the pressure "
        "Laplacian L_p inside the Schur complement approximation: a "
        "positive number, or automatic: 0.3 with "
        "Cahouet-Chabard, 1e-2 with the least-squares commutator. The outer "
        "FGMRES tolerates loose inner solves with Cahouet-Chabard; the "
        "least-squares commutator applies L_p^-1 twice and needs the "
        "tighter ones. Change it only to study the solver "
        "(doc/performance.md).");
      prm.declare_entry(
        "Pressure Laplacian smoother",
        to_string(defaults.pressure_laplacian_smoother),
        Patterns::Selection(core::selection_of(laplacian_smoother_names)),
        "Smoother on every level of the ML V-cycle that preconditions the "
        "inner CG with the pressure Laplacian L_p. ILU: one ILU(0) sweep "
        "before and after the coarse correction; few CG iterations per "
        "solve, the better choice on graded and stretched meshes such as "
        "the ten Cate boxes. Chebyshev: ML's Jacobi-Chebyshev, two sweeps; "
        "cheaper to set up, the better choice on uniform meshes of many "
        "cells such as the 3D DFG channel (doc/performance.md).");
      prm.declare_entry(
        "Velocity preconditioner",
        to_string(defaults.velocity_preconditioner),
        Patterns::Selection(core::selection_of(velocity_preconditioner_names)),
        "Approximate inverse of the velocity block inside the block "
        "preconditioner. automatic: for time-dependent flow the geometric "
        "multigrid where the mesh allows it, AMG otherwise, for steady flow "
        "and with 'Moving bodies = carry surface vertices'; the run's log "
        "says which and why. "
        "AMG: one V-cycle of Trilinos ML, robust for any "
        "time step, but its set-up costs many Krylov iterations. Chebyshev: "
        "a Jacobi-preconditioned Chebyshev polynomial of degree 'Chebyshev "
        "degree' with eigenvalue bounds estimated by a few CG steps; no "
        "set-up beyond that, and as good as AMG when the mass term rho/k "
        "dominates the viscous one (rho h^2 / (theta k mu) >> 1, small time "
        "steps), useless for steady or viscous-dominated flow. geometric "
        "multigrid: one V-cycle on the levels of the coarse mesh's uniform "
        "refinement for the symmetric part rho/k M + theta mu (grad + "
        "grad^T) of the block, applied without a matrix on every level "
        "(single precision), Chebyshev smoothing of degree 'Chebyshev "
        "degree' and the coarse solve of 'Multigrid coarse solver'; "
        "convection is left to FGMRES. "
        "Rebuilt only when the stage's rho/k or theta change (or at every "
        "Newton step for a shear-rate dependent viscosity). Needs a mesh "
        "without hanging nodes and free-slip planes normal to an axis.");
      prm.declare_entry(
        "Velocity operator",
        to_string(defaults.velocity_operator),
        Patterns::Selection(core::selection_of(velocity_operator_names)),
        "How the outer FGMRES applies the velocity block of the Newton "
        "system. automatic: matrix-free with the geometric multigrid, "
        "assembled with the other preconditioners. "
        "assembled: a Trilinos matrix, assembled at every Newton "
        "step. matrix-free: a cell loop with sum factorisation on the "
        "current iterate (mass, deformation-tensor viscosity, Oseen "
        "convection with the ALE mesh velocity, and the Newton term), no "
        "Jacobian assembly and no velocity-block matrix in memory; the "
        "divergence blocks stay assembled (they change only with the mesh). "
        "Needs the geometric multigrid velocity preconditioner (the other "
        "preconditioners are built from the assembled block) and "
        "constraints of the form u_i = g only (no hanging nodes, free-slip "
        "planes normal to an axis).");
      prm.declare_entry(
        "Multigrid coarse solver",
        to_string(defaults.multigrid_coarse_solver),
        Patterns::Selection(core::selection_of(coarse_solver_names)),
        "Coarse-level solve of the geometric multigrid velocity V-cycle (on "
        "the unrefined mesh). Chebyshev: a Jacobi-preconditioned Chebyshev "
        "polynomial of the matrix-free level operator, of the degree that "
        "reduces the error tenfold over the eigenvalue range estimated by "
        "30 Lanczos steps; cheap when the mass term dominates (the ten Cate "
        "boxes at dt = 1-10 ms: degree 4-6, a seventh to a twelfth of the "
        "cost of CG + AMG, same FGMRES iterations). CG + AMG: the level's "
        "matrix, assembled from the same cell kernel, solved by CG with an "
        "ML V-cycle to a relative 1e-3; its cost does not grow with the "
        "level's condition number (steady or viscous-dominated flow on a "
        "coarse mesh of many cells). automatic: Chebyshev when "
        "its degree is at most 30 (about what one CG + AMG solve costs in "
        "products on that level), CG + AMG otherwise.");
      prm.declare_entry(
        "Multigrid on a moving mesh",
        to_string(defaults.multigrid_on_moving_mesh),
        Patterns::Selection(core::selection_of(moving_mesh_names)),
        "What the preconditioners built from the mesh do when its vertices "
        "move (ALE: r-adaptivity, 'Moving bodies' in subsection 'Mesh "
        "deformation'): the geometric multigrid of the velocity block, and, "
        "with 'Velocity operator = matrix-free', the Schur approximation's "
        "pressure Laplacian L_p with its algebraic multigrid and the ILU of "
        "the pressure mass matrix (rebuilt after every motion with the "
        "assembled operator). rebuild: they "
        "are built anew for the new positions after every motion. keep: "
        "those of the last geometry stay the preconditioner (FGMRES always "
        "applies the current operator). The velocity multigrid is rebuilt "
        "once a solve needs more than 1.2 times the median FGMRES "
        "iterations of the last five solves with a fresh one plus 2, and "
        "the Schur approximation's parts with it; these also when the "
        "covered nodes change or pressures become decoupled (L_p's "
        "structure). A solve with kept parts that does not converge "
        "rebuilds all and is repeated. A fresh "
        "adaptation, which interpolates the flow onto a new mesh, and a "
        "checkpoint rebuild all.");
      prm.declare_entry("Chebyshev degree",
                        std::to_string(defaults.chebyshev_degree),
                        Patterns::Integer(1, 50),
                        "Degree of the Chebyshev velocity preconditioner "
                        "(matrix-vector products per application), and of "
                        "the multigrid smoother's polynomial.");
      prm.declare_entry("AMG elliptic",
                        core::flag_text(defaults.amg_elliptic),
                        Patterns::Bool(),
                        "Trilinos ML aggregation for the velocity block: true "
                        "uses smoothed aggregation (diffusion/mass dominated "
                        "flow), false the non-symmetric variant (strong "
                        "convection).");
      prm.declare_entry("AMG smoother",
                        to_string(defaults.amg_smoother),
                        Patterns::Selection(
                          core::selection_of(amg_smoother_names)),
                        "Smoother on every level of the velocity AMG. ILU is "
                        "robust for the non-symmetric Newton Jacobian; "
                        "Chebyshev and Gauss-Seidel can stagnate when "
                        "convection matters.");
      prm.declare_entry("AMG smoother sweeps",
                        std::to_string(defaults.amg_smoother_sweeps),
                        Patterns::Integer(1),
                        "Smoothing sweeps per level of the velocity AMG.");
      prm.declare_entry("Verbose",
                        core::flag_text(defaults.verbose),
                        Patterns::Bool(),
                        "Print every nonlinear iteration's residual.");
      prm.leave_subsection();
    }

    void
    LinearSolverParameters::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      relative_tolerance
        = core::get_positive_double(prm, "Relative tolerance", "Linear solver");
      maximum_iterations = prm.get_integer("Maximum iterations");
      krylov_size        = prm.get_integer("Krylov subspace size");
      schur_approximation
        = core::choice_named(schur_names,
                             prm.get("Schur complement approximation"));
      const std::string poisson_tolerance
        = prm.get("Pressure Poisson tolerance");
      pressure_poisson_tolerance = 0.; // automatic
      if (poisson_tolerance != "automatic")
        {
          std::size_t parsed = 0;
          try
            {
              pressure_poisson_tolerance
                = std::stod(poisson_tolerance, &parsed);
            }
          catch (const std::exception &)
            {
              parsed = 0;
            }
          if (parsed != poisson_tolerance.size()
              || !(pressure_poisson_tolerance > 0.))
            throw std::runtime_error(
              "The entry 'Pressure Poisson tolerance' in subsection 'Linear "
              "solver' must be 'automatic' or a number larger than zero (it "
              "is '"
              + poisson_tolerance + "').");
        }
      pressure_laplacian_smoother
        = core::choice_named(laplacian_smoother_names,
                             prm.get("Pressure Laplacian smoother"));
      velocity_preconditioner
        = core::choice_named(velocity_preconditioner_names,
                             prm.get("Velocity preconditioner"));
      velocity_operator = core::choice_named(velocity_operator_names,
                                             prm.get("Velocity operator"));
      if (velocity_operator == VelocityOperator::matrix_free
          && velocity_preconditioner
               != VelocityPreconditioner::geometric_multigrid
          && velocity_preconditioner != VelocityPreconditioner::automatic)
        throw std::runtime_error(
          "subsection 'Linear solver': 'Velocity operator = matrix-free' "
          "needs 'Velocity preconditioner = geometric multigrid' (it is '"
          + to_string(velocity_preconditioner)
          + "', which is built from the assembled velocity block). Set "
            "both, or 'Velocity operator = assembled'.");
      multigrid_coarse_solver
        = core::choice_named(coarse_solver_names,
                             prm.get("Multigrid coarse solver"));
      multigrid_on_moving_mesh
        = core::choice_named(moving_mesh_names,
                             prm.get("Multigrid on a moving mesh"));
      chebyshev_degree = prm.get_integer("Chebyshev degree");
      amg_elliptic     = prm.get_bool("AMG elliptic");
      amg_smoother
        = core::choice_named(amg_smoother_names, prm.get("AMG smoother"));
      amg_smoother_sweeps = prm.get_integer("AMG smoother sweeps");
      verbose             = prm.get_bool("Verbose");
      prm.leave_subsection();
    }



    void
    ForceParameters::declare(ParameterHandler &prm)
    {
      const ForceParameters defaults;
      prm.enter_subsection("Forces");
      prm.declare_entry("Body boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, 255), 0),
                        "Boundary ids of the obstacle whose drag and lift are "
                        "written (empty: none).");
      prm.declare_entry("Reference velocity",
                        core::number_text(defaults.reference_velocity),
                        Patterns::Double(0.),
                        "U in c = 2F/(rho U^2 A) [m/s].");
      prm.declare_entry("Reference area",
                        core::number_text(defaults.reference_area),
                        Patterns::Double(0.),
                        "A in c = 2F/(rho U^2 A) [m^2]; in 2D a length [m] "
                        "(per unit depth).");
      prm.declare_entry("Pressure point A",
                        "",
                        Patterns::List(Patterns::Double(), 0, 3),
                        "Point [m] for the pressure difference p(A) - p(B) "
                        "(empty: none).");
      prm.declare_entry("Pressure point B",
                        "",
                        Patterns::List(Patterns::Double(), 0, 3),
                        "Second point [m] of the pressure difference.");
      prm.leave_subsection();
    }

    void
    ForceParameters::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Forces");
      body_boundary_ids = id_list(prm, "Body boundary ids");
      reference_velocity
        = core::get_positive_double(prm, "Reference velocity", "Forces");
      reference_area
        = core::get_positive_double(prm, "Reference area", "Forces");
      pressure_point_a = double_list(prm, "Pressure point A");
      pressure_point_b = double_list(prm, "Pressure point B");
      prm.leave_subsection();
    }



    void
    FluidParameters::declare(ParameterHandler &prm)
    {
      FluidProperties::declare(prm);
      BoundaryConditions::declare(prm);
      prm.enter_subsection("Initial condition");
      core::FunctionExpression::declare(prm,
                                        "Velocity",
                                        "",
                                        "Initial velocity [m/s].");
      prm.leave_subsection();
      NonlinearSolverParameters::declare(prm);
      LinearSolverParameters::declare(prm);
      ForceParameters::declare(prm);
    }

    void
    FluidParameters::parse(ParameterHandler &prm)
    {
      properties.parse(prm);
      boundary_conditions.parse(prm);
      prm.enter_subsection("Initial condition");
      initial_velocity.parse(prm, "Velocity");
      prm.leave_subsection();
      nonlinear_solver.parse(prm);
      linear_solver.parse(prm);
      forces.parse(prm);
    }
  } // namespace fluid
} // namespace particulate
