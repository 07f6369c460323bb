#ifndef particulate_tests_fluid_solution_error_h
#define particulate_tests_fluid_solution_error_h

// The L2 error of a flow solution against a closed form, for the fluid
// tests that measure convergence rates.

#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <utility>

namespace particulate {
  namespace testing {
    /** || u_h - u || in L2 over the components [@p first, @p last) of
     *  @p flow's solution (velocity 0..dim-1, pressure dim), against
     *  @p exact (dim + 1 components), with a Gauss rule of
     *  @p quadrature_points per direction. */
    template <int dim>
    double
    l2_error(const fluid::NavierStokes<dim> &flow,
             const dealii::Function<dim>    &exact,
             const unsigned int              first,
             const unsigned int              last,
             const unsigned int              quadrature_points)
    {
      const auto            &tria = flow.get_dof_handler().get_triangulation();
      dealii::Vector<double> cellwise(tria.n_active_cells());
      const dealii::ComponentSelectFunction<dim> mask(std::make_pair(first,
                                                                     last),
                                                      dim + 1);
      dealii::VectorTools::integrate_difference(flow.get_mapping(),
                                                flow.get_dof_handler(),
                                                flow.get_solution(),
                                                exact,
                                                cellwise,
                                                dealii::QGauss<dim>(
                                                  quadrature_points),
                                                dealii::VectorTools::L2_norm,
                                                &mask);
      return dealii::VectorTools::compute_global_error(
        tria,
        cellwise,
        dealii::VectorTools::L2_norm);
    }
  } // namespace testing
} // namespace particulate

#endif
