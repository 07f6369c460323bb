#include "schur_complement.h"

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    PressureLaplaceInverse::PressureLaplaceInverse(
      const TrilinosWrappers::SparseMatrix    &matrix,
      const TrilinosWrappers::PreconditionAMG &amg,
      const double                             relative_tolerance)
      : matrix(matrix)
      , amg(amg)
      , relative_tolerance(relative_tolerance)
    {}



    void
    PressureLaplaceInverse::solve(TrilinosWrappers::MPI::Vector       &x,
                                  const TrilinosWrappers::MPI::Vector &b) const
    {
      ++solves;
      SolverControl                           control(200,
                            relative_tolerance * b.l2_norm(),
                            false,
                            false);
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      x = 0;
      try
        {
          cg.solve(matrix, x, b, amg);
        }
      catch (const SolverControl::NoConvergence &)
        {
          // An inexact L_p^{-1} is still a valid preconditioner for the
          // flexible outer solver; FGMRES judges convergence itself.
        }
      iterations += control.last_step();
    }



    SchurApproximation
    resolve_schur_approximation(const SchurApproximation choice,
                                const bool               steady)
    {
      if (choice != SchurApproximation::automatic)
        return choice;
      return steady ? SchurApproximation::least_squares_commutator :
                      SchurApproximation::cahouet_chabard;
    }



    double
    automatic_pressure_poisson_tolerance(const SchurApproximation approximation)
    {
      return approximation == SchurApproximation::least_squares_commutator ?
               1e-2 :
               0.3;
    }



    namespace {
      class CahouetChabardInverse : public SchurComplementInverse
      {
      public:
        explicit CahouetChabardInverse(const SchurIngredients &ingredients)
          : in(ingredients)
        {}

        void
        vmult(TrilinosWrappers::MPI::Vector       &dst,
              const TrilinosWrappers::MPI::Vector &src) const override
        {
          in.mass_inverse->vmult(dst, src);
          dst *= -in.viscous_weight;
          if (in.inertial_weight > 0.)
            {
              if (tmp_p.size() != src.size())
                tmp_p.reinit(src, true);
              in.laplace_inverse->solve(tmp_p, src);
              dst.add(-in.inertial_weight, tmp_p);
            }
        }

      private:
        const SchurIngredients                in;
        mutable TrilinosWrappers::MPI::Vector tmp_p;
      };



      class LeastSquaresCommutatorInverse : public SchurComplementInverse
      {
      public:
        explicit LeastSquaresCommutatorInverse(
          const SchurIngredients &ingredients)
          : in(ingredients)
          , tmp_u(*ingredients.inverse_lumped_mass)
          , tmp_u2(tmp_u)
        {}

        void
        vmult(TrilinosWrappers::MPI::Vector       &dst,
              const TrilinosWrappers::MPI::Vector &src) const override
        {
          if (tmp_p.size() != src.size())
            tmp_p.reinit(src, true);
          const auto &inverse_mass = *in.inverse_lumped_mass;
          in.laplace_inverse->solve(tmp_p, src);
          in.system->apply_gradient(tmp_u, tmp_p);
          tmp_u.scale(inverse_mass);
          in.system->apply_velocity_block(tmp_u2, tmp_u);
          tmp_u2.scale(inverse_mass);
          in.system->apply_divergence(tmp_p, tmp_u2);
          in.laplace_inverse->solve(dst, tmp_p);
          dst *= -1.;
        }

      private:
        const SchurIngredients                in;
        mutable TrilinosWrappers::MPI::Vector tmp_u, tmp_u2, tmp_p;
      };
    } // namespace



    std::unique_ptr<SchurComplementInverse>
    make_schur_complement_inverse(const SchurApproximation approximation,
                                  const SchurIngredients  &ingredients)
    {
      switch (approximation)
        {
          case SchurApproximation::least_squares_commutator:
            return std::make_unique<LeastSquaresCommutatorInverse>(ingredients);
          case SchurApproximation::cahouet_chabard:
            return std::make_unique<CahouetChabardInverse>(ingredients);
          case SchurApproximation::automatic:
            break;
        }
      AssertThrow(false,
                  ExcMessage("resolve 'automatic' before choosing the Schur "
                             "complement approximation"));
      return nullptr;
    }
  } // namespace fluid
} // namespace particulate
