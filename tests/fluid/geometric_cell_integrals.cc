// The mesh-only integrals of one Q2^dim x P1disc cell
// (source/fluid/geometric_cell_integrals.h) on a distorted cell, against
// closed forms that hold for any cell (|K| from deal.II's cell measure):
//
//   sum_a lumped(a)                    = dim |K|   (partition of unity)
//   mass(0, 0) = |K|, mass(k, 0) = (psi_k, 1)      (psi_0 = 1)
//   sum_a gradient(a, k) u_a           = -(psi_k, div u)
//
// for the nodal values u_a of u = x_c e_c (div u = 1, which Q2 on the
// degree-2 mapping holds exactly) and of a constant u (div u = 0). A
// wrong component, a missing weight or a transposed block is off by
// O(|K|).

#include "../../source/fluid/geometric_cell_integrals.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <string>
#include <vector>

#include "test_utilities.h"

using namespace dealii;

namespace {
  template <int dim>
  void
  check(particulate::testing::Checker &checker)
  {
    Triangulation<dim> tria;
    GridGenerator::hyper_cube(tria);
    // the far corner pulled outwards and sideways: no face stays parallel
    Point<dim> &corner = tria.begin_active()->vertex((1 << dim) - 1);
    corner[0] += 0.3;
    corner[1] += 0.15;
    const std::string dimension = std::to_string(dim) + "D: ";

    const FESystem<dim> fe(FE_Q<dim>(2), dim, FE_DGP<dim>(1), 1);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const MappingQ<dim> mapping(2);
    const QGauss<dim>   quadrature(3);
    FEValues<dim>       fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients | update_JxW_values
                              | update_quadrature_points);
    const auto          cell = dof_handler.begin_active();
    fe_values.reinit(cell);
    particulate::fluid::GeometricCellIntegrals<dim> integrals(fe);
    integrals.compute(fe_values, true);
    const auto        &velocity = integrals.velocity_dofs();
    const auto        &pressure = integrals.pressure_dofs();
    const double       volume   = cell->measure();
    const unsigned int n_p      = pressure.size();

    checker.check(std::abs(fe.base_element(1).shape_value(0, Point<dim>()) - 1.)
                    < 1e-14,
                  dimension + "the first P1disc function is the constant");

    double lumped_sum = 0.;
    for (const double m : integrals.lumped())
      lumped_sum += m;
    checker.check_relative(lumped_sum,
                           dim * volume,
                           1e-12,
                           dimension + "sum of the lumped velocity mass");

    // (psi_k, 1), summed independently of the class
    std::vector<double> psi_integral(n_p, 0.);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int k = 0; k < n_p; ++k)
        psi_integral[k]
          += fe_values.shape_value(pressure[k], q) * fe_values.JxW(q);
    checker.check_relative(integrals.mass_row(0)[0],
                           volume,
                           1e-12,
                           dimension + "M_p(0, 0) = |K|");
    for (unsigned int k = 1; k < n_p; ++k)
      checker.check(std::abs(integrals.mass_row(k)[0] - psi_integral[k])
                      < 1e-13 * volume,
                    dimension + "M_p(" + std::to_string(k)
                      + ", 0) = (psi_k, 1)");

    // velocity support points on the cell
    const auto &unit_points = fe.base_element(0).get_unit_support_points();
    for (unsigned int c = 0; c < dim; ++c)
      {
        double largest_error = 0., largest_constant = 0.;
        for (unsigned int k = 0; k < n_p; ++k)
          {
            double linear = 0., constant = 0.;
            for (unsigned int a = 0; a < velocity.size(); ++a)
              {
                const auto [component, node]
                  = fe.system_to_component_index(velocity[a]);
                if (component != c)
                  continue;
                const Point<dim> x
                  = mapping.transform_unit_to_real_cell(cell,
                                                        unit_points[node]);
                linear += integrals.gradient_row(a)[k] * x[c];
                constant += integrals.gradient_row(a)[k];
              }
            largest_error
              = std::max(largest_error, std::abs(linear + psi_integral[k]));
            largest_constant = std::max(largest_constant, std::abs(constant));
          }
        checker.check(largest_error < 1e-12 * volume,
                      dimension + "B^T of u = x_" + std::to_string(c) + " e_"
                        + std::to_string(c) + " is -(psi_k, 1)");
        checker.check(largest_constant < 1e-12 * volume,
                      dimension + "B^T of a constant u_" + std::to_string(c)
                        + " vanishes");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  particulate::testing::Checker    checker;
  check<2>(checker);
  check<3>(checker);
  return checker.exit_code();
}
