#ifndef particulate_fluid_momentum_operator_h
#define particulate_fluid_momentum_operator_h

// Private header of the fluid library: the velocity block of the Newton
// (or Oseen) system applied without a matrix. Kept light (the matrix-free
// templates stay in momentum_operator.cc) because navier_stokes_*.cc
// include it.

#include <particulate/fluid/viscosity_model.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * The velocity block A of the linearised momentum equation of one
     * stage (see Stage and NavierStokes::assemble), as an operator:
     *
     *   (A u, v) = rho/k (u, v) + theta_i (2 mu D(u), D(v))
     *            + theta_i rho ((a.grad) u, v)
     *            + theta_i rho ((u.grad) u*, v)      (Newton only)
     *            + theta_i 4 (mu'/g (D*:D(u)), D*:D(v))  (Newton only)
     *
     * with a = u* - w the advecting velocity of the linearisation point u*
     * (w the ALE mesh velocity), mu and mu'/g taken at the shear rate g of
     * u*, D* = D(u*) (see ViscosityModel). It replaces the
     * assembled block (0,0) as the outer FGMRES operator: the matrix costs
     * a full assembly per Newton step and 2 kB per DoF in 3D, the operator a
     * cell loop per product with sum factorisation (thesis eq. 5.14-5.16;
     * doc/performance.md, "Flow solver alone").
     *
     * Constrained rows (Dirichlet boundaries, free-slip planes, the nodes
     * inside fictitious-boundary bodies) act as the identity and their
     * columns as zero, which is what AffineConstraints makes of the
     * assembled block for homogeneous constraints of the form u_i = 0.
     *
     * Q2 vector fields, 3^dim Gauss points, double precision.
     */
    template <int dim>
    class MomentumOperator
    {
    public:
      /**
       * @p velocity_dofs: a Q2^dim DoF handler numbered like the velocity
       * block of the system (VelocityMultigrid has one), with
       * @p owned_velocity its locally owned DoFs; both and @p mapping must
       * outlive this object.
       */
      MomentumOperator(const dealii::DoFHandler<dim> &velocity_dofs,
                       const dealii::IndexSet        &owned_velocity,
                       const dealii::Mapping<dim>    &mapping);
      ~MomentumOperator();

      /** Recompute the geometric data after the mesh vertices moved (the
       *  mesh's cells and DoFs unchanged). */
      void
      update_geometry();

      /** The locally owned velocity DoFs whose rows are the identity. */
      void
      set_constrained_dofs(
        const std::vector<dealii::types::global_dof_index> &dofs);

      /**
       * The stage's linearisation: @p velocity the iterate u* and
       * @p mesh_velocity w (nullptr: none), both in the velocity block
       * layout (locally owned entries are read). @p newton adds the
       * derivative of the convection with respect to the advecting field
       * and that of the viscosity with respect to the shear rate.
       */
      void
      set_linearisation(
        const dealii::TrilinosWrappers::MPI::Vector &velocity,
        const dealii::TrilinosWrappers::MPI::Vector *mesh_velocity,
        const double                                 mass_coefficient,
        const double                                 theta_implicit,
        const double                                 density,
        const bool                                   newton,
        const ViscosityModel                        &viscosity_model);

      /**
       * The nonlinear momentum form of a stage without the pressure and
       * the body force, for the residual:
       *
       *   dst_i = c (u, phi_i) + theta [ (2 mu(u) D(u), D(phi_i))
       *                                  + rho ((u - w).grad u, phi_i) ]
       *
       * on all rows (no constraints; @p velocity u and @p mesh_velocity w
       * as in set_linearisation). The residual of a stage is this form at
       * the iterate (c = rho/k, theta_i) plus this form at the old
       * solution (c = -rho/k, theta_e), which is fixed within the stage.
       * Independent of set_linearisation().
       */
      void
      apply_nonlinear_form(
        dealii::TrilinosWrappers::MPI::Vector       &dst,
        const dealii::TrilinosWrappers::MPI::Vector &velocity,
        const dealii::TrilinosWrappers::MPI::Vector *mesh_velocity,
        const double                                 mass_coefficient,
        const double                                 theta,
        const double                                 density,
        const ViscosityModel                        &viscosity_model) const;

      /** dst = A src (velocity block layout, locally owned entries). */
      void
      vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
            const dealii::TrilinosWrappers::MPI::Vector &src) const;

      /** Bytes held by this rank (geometry and quadrature-point data). */
      std::size_t
      memory_consumption() const;

    private:
      struct Implementation;
      std::unique_ptr<Implementation> implementation;
    };
  } // namespace fluid
} // namespace particulate

#endif
