#ifndef particulate_fluid_fluid_parameters_h
#define particulate_fluid_fluid_parameters_h

#include <particulate/core/function_expression.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace particulate {
  namespace fluid {
    /** 'Viscosity model': mu constant or a function of the shear rate. */
    enum class ViscosityModelType
    {
      newtonian,
      carreau,
      cross,
      power_law,
      table
    };

    /** 'Nonlinear solver / Method': the linearisation of convection. */
    enum class NonlinearMethod
    {
      newton,
      fixed_point
    };

    /** 'Nonlinear solver / Initial guess': the first iterate of a stage. */
    enum class InitialGuess
    {
      extrapolated,
      previous_solution
    };

    /** 'Schur complement approximation'. */
    enum class SchurApproximation
    {
      automatic,
      cahouet_chabard,
      least_squares_commutator
    };

    /** 'Pressure Laplacian smoother' of L_p's ML V-cycle. */
    enum class PressureLaplacianSmoother
    {
      ilu,
      chebyshev
    };

    /** 'Velocity preconditioner': the approximate inverse of the velocity
     *  block. `automatic` becomes a concrete choice once the mesh exists
     *  (resolve_velocity_solver()). */
    enum class VelocityPreconditioner
    {
      automatic,
      amg,
      chebyshev,
      geometric_multigrid
    };

    /** 'Velocity operator': how FGMRES applies the velocity block;
     *  `automatic` as for VelocityPreconditioner. */
    enum class VelocityOperator
    {
      automatic,
      assembled,
      matrix_free
    };

    /** 'Multigrid coarse solver' of the velocity V-cycle. */
    enum class MultigridCoarseSolver
    {
      automatic,
      chebyshev,
      cg_amg
    };

    /** 'Multigrid on a moving mesh': the mesh-built preconditioners after
     *  the mesh moved. */
    enum class MultigridOnMovingMesh
    {
      rebuild,
      keep
    };

    /** 'AMG smoother' of the velocity AMG (Trilinos ML's smoother types). */
    enum class AmgSmoother
    {
      chebyshev,
      symmetric_gauss_seidel,
      gauss_seidel,
      ilu
    };

    /** The name of a choice in a case file ("AMG", "matrix-free", ...);
     *  for AmgSmoother also Trilinos ML's name of the smoother. */
    std::string
    to_string(ViscosityModelType choice);
    std::string
    to_string(NonlinearMethod choice);
    std::string
    to_string(InitialGuess choice);
    std::string
    to_string(SchurApproximation choice);
    std::string
    to_string(PressureLaplacianSmoother choice);
    std::string
    to_string(VelocityPreconditioner choice);
    std::string
    to_string(VelocityOperator choice);
    std::string
    to_string(MultigridCoarseSolver choice);
    std::string
    to_string(MultigridOnMovingMesh choice);
    std::string
    to_string(AmgSmoother choice);

    /**
     * subsection `Fluid`: material properties (thesis eq. 5.1-5.2). Density
     * and the *dynamic* viscosity mu are given separately; the kinematic
     * viscosity is nu = mu / rho.
     */
    struct FluidProperties
    {
      double density = 1.0; ///< rho [kg/m^3]
      /// mu [Pa s]; the zero-shear mu_0 for Carreau and Cross
      double             dynamic_viscosity = 1e-3;
      ViscosityModelType viscosity_model   = ViscosityModelType::newtonian;
      double             infinite_shear_viscosity = 0.; ///< mu_inf [Pa s]
      double             relaxation_time          = 1.; ///< lambda [s]
      double             power_law_index          = 1.; ///< n [-]
      double             consistency = 1e-3; ///< K [Pa s^n], power law
      double      minimum_shear_rate = 1e-3; ///< [1/s], the power law's floor
      std::string viscosity_table; ///< file of (shear rate, viscosity) rows
      core::FunctionExpression
        body_force; ///< f [m/s^2], acceleration (gravity)

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);

    private:
      /** Refuse a law whose entries contradict it (Cross with n >= 1, a
       *  table without a file). */
      void
      check_viscosity_model() const;
    };

    /**
     * subsection `Boundary conditions`: one kind of condition per boundary
     * id. Every boundary id of the mesh must appear in exactly one list;
     * the check after reading the mesh enforces it.
     */
    struct BoundaryConditions
    {
      std::vector<unsigned int> no_slip;    ///< u = 0
      std::vector<unsigned int> dirichlet;  ///< u = g(x, t)
      std::vector<unsigned int> free_slip;  ///< u.n = 0, tangential traction 0
      std::vector<unsigned int> do_nothing; ///< sigma.n = 0 (outflow)
      core::FunctionExpression  dirichlet_velocity;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);

      /**
       * Check that every id in @p mesh_ids has exactly one condition and that
       * every listed id exists on the mesh. Throws with an actionable message.
       */
      void
      check(const std::vector<unsigned int> &mesh_ids,
            const std::string               &parameter_file) const;

      /** True when some boundary fixes the pressure level (outflow). */
      bool
      pressure_is_determined() const
      {
        return !do_nothing.empty();
      }
    };

    /** subsection `Nonlinear solver`. */
    struct NonlinearSolverParameters
    {
      NonlinearMethod method             = NonlinearMethod::newton;
      double          absolute_tolerance = 1e-10;
      double          relative_tolerance = 1e-6;
      unsigned int    maximum_iterations = 20;
      InitialGuess    initial_guess      = InitialGuess::extrapolated;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);
    };

    /** subsection `Linear solver`. */
    struct LinearSolverParameters
    {
      double             relative_tolerance  = 1e-4;
      unsigned int       maximum_iterations  = 1000;
      unsigned int       krylov_size         = 100;
      SchurApproximation schur_approximation = SchurApproximation::automatic;
      /// relative tolerance of the inner CG + AMG solves with L_p inside
      /// the Schur approximation; 0: automatic (0.3 with Cahouet-Chabard, 1e-2
      /// with LSC)
      double pressure_poisson_tolerance = 0.;
      /// smoother of L_p's ML V-cycle: one ILU(0) sweep, or ML's
      /// Jacobi-Chebyshev (two sweeps)
      PressureLaplacianSmoother pressure_laplacian_smoother
        = PressureLaplacianSmoother::ilu;
      VelocityPreconditioner velocity_preconditioner
        = VelocityPreconditioner::automatic;
      unsigned int chebyshev_degree = 4;
      /// the velocity block of the outer FGMRES operator
      VelocityOperator velocity_operator = VelocityOperator::automatic;
      /// coarse solve of the velocity V-cycle
      MultigridCoarseSolver multigrid_coarse_solver
        = MultigridCoarseSolver::automatic;
      /// the velocity V-cycle after a mesh motion
      MultigridOnMovingMesh multigrid_on_moving_mesh
        = MultigridOnMovingMesh::keep;
      /// why the case, not the mesh, rules the geometric multigrid out
      /// for 'automatic' (e.g. "steady flow"; empty: it does not); set
      /// where the case is read, never an entry of its own
      std::string  multigrid_ruled_out_by;
      bool         amg_elliptic        = true;
      AmgSmoother  amg_smoother        = AmgSmoother::ilu;
      unsigned int amg_smoother_sweeps = 2;
      bool         verbose             = false;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);
    };

    /**
     * subsection `Forces`: what the solver measures every step. Drag and
     * lift coefficients are c = 2 F / (rho U^2 A) with the reference
     * velocity U and area A (the diameter per unit depth in 2D).
     */
    struct ForceParameters
    {
      std::vector<unsigned int> body_boundary_ids;
      double                    reference_velocity = 1.;
      double                    reference_area     = 1.;
      std::vector<double>       pressure_point_a;
      std::vector<double>       pressure_point_b;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);
    };

    /** All fluid-solver parameters together. */
    struct FluidParameters
    {
      FluidProperties           properties;
      BoundaryConditions        boundary_conditions;
      core::FunctionExpression  initial_velocity;
      NonlinearSolverParameters nonlinear_solver;
      LinearSolverParameters    linear_solver;
      ForceParameters           forces;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);
    };
  } // namespace fluid
} // namespace particulate

#endif
