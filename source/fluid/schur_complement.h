#ifndef particulate_fluid_schur_complement_h
#define particulate_fluid_schur_complement_h

#include <particulate/fluid/fluid_parameters.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

#include "saddle_point_operator.h"

namespace particulate {
  namespace fluid {
    /**
     * Approximate action of L_p^{-1} (the discrete pressure Laplacian
     * L_p = B D^{-1} B^T, D the lumped velocity mass): conjugate gradients
     * with an AMG preconditioner to a loose relative tolerance. The AMG
     * V-cycle alone is not enough: the least-squares commutator applies
     * L_p^{-1} twice, and with Cahouet-Chabard FGMRES needs several times
     * the iterations. Counts its solves and CG iterations.
     */
    class PressureLaplaceInverse
    {
    public:
      PressureLaplaceInverse(
        const dealii::TrilinosWrappers::SparseMatrix    &matrix,
        const dealii::TrilinosWrappers::PreconditionAMG &amg,
        const double                                     relative_tolerance);

      void
      solve(dealii::TrilinosWrappers::MPI::Vector       &x,
            const dealii::TrilinosWrappers::MPI::Vector &b) const;

      mutable unsigned int iterations = 0, solves = 0;

    private:
      const dealii::TrilinosWrappers::SparseMatrix    &matrix;
      const dealii::TrilinosWrappers::PreconditionAMG &amg;
      const double                                     relative_tolerance;
    };

    /**
     * An approximation of the inverse of the Schur complement
     * S = B A^{-1} B^T (B = -div, so S is positive) inside the block
     * preconditioner.
     */
    class SchurComplementInverse
    {
    public:
      virtual ~SchurComplementInverse() = default;

      /** dst = -S^{-1} src, approximately. */
      virtual void
      vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
            const dealii::TrilinosWrappers::MPI::Vector &src) const = 0;
    };

    /** 'Schur complement approximation = automatic' resolved for a stage:
     *  the least-squares commutator for the steady problem, else
     *  Cahouet-Chabard. */
    SchurApproximation
    resolve_schur_approximation(const SchurApproximation choice,
                                const bool               steady);

    /** The relative tolerance of the inner L_p solves that 'Pressure Poisson
     *  tolerance = automatic' means for @p approximation (resolved): loose
     *  for Cahouet-Chabard, tighter for the least-squares commutator, which
     *  applies L_p^{-1} twice. */
    double
    automatic_pressure_poisson_tolerance(
      const SchurApproximation approximation);

    /** What the Schur complement approximations are made of. */
    struct SchurIngredients
    {
      const SaddlePointOperator    *system                          = nullptr;
      const PressureLaplaceInverse *laplace_inverse                 = nullptr;
      const dealii::TrilinosWrappers::PreconditionILU *mass_inverse = nullptr;
      /// 1 / row sums of the velocity mass matrix
      const dealii::TrilinosWrappers::MPI::Vector *inverse_lumped_mass
        = nullptr;
      /// theta_i mu: the weight of M_p^{-1} (viscous limit)
      double viscous_weight = 0.;
      /// rho / k: the weight of L_p^{-1} (small-time-step limit); 0 steady
      double inertial_weight = 0.;
    };

    /**
     * The Schur complement inverse for @p approximation (resolved):
     * - Cahouet-Chabard: theta_i mu M_p^{-1} + (rho/k) L_p^{-1};
     * - least-squares commutator: L_p^{-1} (B D^{-1} A D^{-1} B^T) L_p^{-1}.
     */
    std::unique_ptr<SchurComplementInverse>
    make_schur_complement_inverse(const SchurApproximation approximation,
                                  const SchurIngredients  &ingredients);
  } // namespace fluid
} // namespace particulate

#endif
