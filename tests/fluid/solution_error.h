#ifndef particulate_tests_fluid_solution_error_h
#define particulate_tests_fluid_solution_error_h

// The steady flow of a case on its mesh, the L2 error of the solution
// against a closed form, and the rate between two levels, for the fluid
// tests that measure convergence rates.

#include <particulate/core/mesh.h>
#include <particulate/core/simulation_parameters.h>
#include <particulate/fluid/flow_simulation.h>
#include <particulate/fluid/navier_stokes.h>
#include <particulate/fluid/time_integrator.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <iostream>
#include <utility>
#include <vector>

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

    /** The mesh of @p parameters made in @p tria; @p parameters' fluid
     *  part, for the solver built on that mesh next. */
    template <int dim>
    const fluid::FluidParameters &
    make_mesh(const fluid::FlowCaseParameters &parameters,
              dealii::parallel::fullydistributed::Triangulation<dim> &tria)
    {
      core::create_mesh(parameters.mesh, tria);
      return parameters.fluid;
    }

    /** The steady flow of @p parameters on their mesh, solved on
     *  construction; the solver refers to the mesh and the timer, so the
     *  three live together. */
    template <int dim>
    struct SteadyFlow
    {
      explicit SteadyFlow(const fluid::FlowCaseParameters &parameters)
        : tria(MPI_COMM_WORLD)
        , timer(MPI_COMM_WORLD,
                std::cout,
                dealii::TimerOutput::never,
                dealii::TimerOutput::wall_times)
        , flow(make_mesh(parameters, tria), tria, timer)
      {
        flow.setup_dofs();
        flow.set_initial_condition(0.);
        stats = flow.advance(0., 0., core::TimeParameters::Scheme::steady);
      }

      dealii::parallel::fullydistributed::Triangulation<dim> tria;
      dealii::TimerOutput                                    timer;
      fluid::NavierStokes<dim>                               flow;
      fluid::SolveStatistics                                 stats;
    };

    /** The rate of @p errors between their last two entries, levels of
     *  halved mesh size. */
    inline double
    last_rate(const std::vector<double> &errors)
    {
      const std::size_t n = errors.size();
      return std::log(errors[n - 2] / errors[n - 1]) / std::log(2.);
    }
  } // namespace testing
} // namespace particulate

#endif
