#ifndef particulate_fluid_flow_diagnostics_h
#define particulate_fluid_flow_diagnostics_h

#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>

#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * Force exerted by the fluid on the boundary parts @p boundary_ids,
     * F = -int_Gamma sigma n dS with n the outward normal of the fluid
     * domain (thesis eq. 5.4), sigma = -p I + 2 mu D(u) (eq. 5.2).
     */
    template <int dim>
    dealii::Tensor<1, dim>
    surface_force(const NavierStokes<dim>         &flow,
                  const std::vector<unsigned int> &boundary_ids);

    /**
     * The same force as a volume integral F = -int sigma . grad(alpha)
     * (thesis eq. 5.12-5.13) with alpha_h a finite-element indicator of
     * the body: @p indicator is a vector in the flow's FE space whose
     * first velocity component holds alpha_h. Only cells where grad alpha_h
     * is non-zero contribute. (The fictitious boundary method integrates
     * the same stress, from cauchy_stress(), over the cells its bodies cut,
     * per body and with torques: fbm::hydrodynamic_loads().)
     */
    template <int dim>
    dealii::Tensor<1, dim>
    volume_force(const NavierStokes<dim>                       &flow,
                 const typename NavierStokes<dim>::BlockVector &indicator);

    /**
     * The Cauchy stress sigma = -p I + 2 mu(D) D(u) (eq. 5.2) of the current
     * solution at the quadrature points of @p fe_values, which must be
     * reinit'ed on a cell of the flow's DoFHandler with update_values and
     * update_gradients. @p sigma is resized to the number of points.
     */
    template <int dim>
    void
    cauchy_stress(const NavierStokes<dim>             &flow,
                  const dealii::FEValues<dim>         &fe_values,
                  std::vector<dealii::Tensor<2, dim>> &sigma);

    /**
     * The indicator alpha_h of a body-fitted obstacle: 1 at the velocity
     * nodes on @p boundary_ids, 0 at all others (ghosted vector in the
     * flow's FE space, alpha in the first velocity component).
     */
    template <int dim>
    typename NavierStokes<dim>::BlockVector
    boundary_indicator(const NavierStokes<dim>         &flow,
                       const std::vector<unsigned int> &boundary_ids);

    /**
     * Pressure at a point, found on whichever rank owns it; the same value
     * on all ranks. Throws if the point is outside the mesh.
     */
    template <int dim>
    double
    pressure_at(const NavierStokes<dim> &flow, const dealii::Point<dim> &point);

    /**
     * Kinetic energy of the fluid, (1/2) int rho |u|^2 [J] (or J/m in 2D).
     * Note: thesis eq. 6.2 writes the integral without the factor 1/2.
     */
    template <int dim>
    double
    kinetic_energy(const NavierStokes<dim> &flow);
  } // namespace fluid
} // namespace particulate

#endif
