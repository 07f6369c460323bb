// The near-null space given to the AMG of the pressure Laplacian
// (source/fluid/pressure_near_null_space.cc): the constant and the dim
// linear functions, projected cell by cell onto P1disc, on a box
// distributed over two ranks.
// - On an affine mesh (a sheared box) P1disc holds the linear functions,
//   so the modes reproduce 1 and (x_d - centre_d) / diagonal exactly at
//   every quadrature point (to 1e-12).
// - On the randomly distorted box (bilinear cells) they cannot, but the
//   difference is orthogonal to every pressure shape function of its cell
//   (the projection's defining property, to 1e-13 of the function's size),
//   and the constant is still exact.
// Every rank checks its own cells and the values it holds for them.

#include "../../source/fluid/pressure_near_null_space.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <cstdio>

#include "distorted_box.h"

using namespace dealii;
using namespace particulate;

namespace {
  template <int dim>
  bool
  check(const bool affine)
  {
    const MPI_Comm                                 comm = MPI_COMM_WORLD;
    parallel::fullydistributed::Triangulation<dim> tria(comm);
    {
      // the unit box, distorted at random or sheared (an affine map)
      Triangulation<dim> serial;
      GridGenerator::subdivided_hyper_cube(serial, 4, 0., 1.);
      if (affine)
        GridTools::transform(
          [](const Point<dim> &p) {
            Point<dim> q = p;
            q[0] += 0.3 * p[1];
            q[1] *= 2.;
            return q;
          },
          serial);
      else
        GridTools::distort_random(0.2, serial, true, 7); // box kept
      GridTools::partition_triangulation(Utilities::MPI::n_mpi_processes(comm),
                                         serial);
      tria.create_triangulation(
        TriangulationDescription::Utilities::
          create_description_from_triangulation(serial, comm));
    }
    const FESystem<dim> fe(FE_Q<dim>(2), dim, FE_DGP<dim>(1), 1);
    DoFHandler<dim>     dof_handler(tria);
    const auto          n_velocity
      = testing::distribute_velocities_first(dof_handler, fe);
    const IndexSet owned_pressures
      = dof_handler.locally_owned_dofs().get_view(n_velocity,
                                                  dof_handler.n_dofs());
    const MappingQ<dim> mapping(2);
    const auto          modes = fluid::pressure_near_null_space(mapping,
                                                       dof_handler,
                                                       owned_pressures,
                                                       n_velocity,
                                                       comm);

    // the box's bounding box, as the function centres and scales by it
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = 1.;
    if (affine)
      {
        upper[0] = 1.3;
        upper[1] = 2.;
      }
    const Point<dim> centre   = 0.5 * (lower + upper);
    const double     diagonal = (upper - lower).norm();

    const QGauss<dim> quadrature(3);
    FEValues<dim>     fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_quadrature_points
                              | update_JxW_values);
    const std::size_t n_owned     = owned_pressures.n_elements();
    double            worst_value = 0., worst_moment = 0., size = 0.;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int m = 0; m < dim + 1; ++m)
            {
              std::vector<double> moment(fe.n_dofs_per_cell(), 0.);
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  const Point<dim> &x = fe_values.quadrature_point(q);
                  const double      target
                    = m == 0 ? 1. : (x[m - 1] - centre[m - 1]) / diagonal;
                  double field = 0.;
                  for (unsigned int i = 0; i < dofs.size(); ++i)
                    if (fe.system_to_component_index(i).first == dim)
                      field += modes[m * n_owned
                                     + owned_pressures.index_within_set(
                                       dofs[i] - n_velocity)]
                               * fe_values.shape_value(i, q);
                  size = std::max(size, std::abs(target));
                  if (affine || m == 0)
                    worst_value
                      = std::max(worst_value, std::abs(field - target));
                  for (unsigned int i = 0; i < dofs.size(); ++i)
                    if (fe.system_to_component_index(i).first == dim)
                      moment[i] += (field - target)
                                   * fe_values.shape_value(i, q)
                                   * fe_values.JxW(q);
                }
              for (const double value : moment)
                worst_moment
                  = std::max(worst_moment, std::abs(value) / cell->measure());
            }
        }
    worst_value       = Utilities::MPI::max(worst_value, comm);
    worst_moment      = Utilities::MPI::max(worst_moment, comm);
    size              = Utilities::MPI::max(size, comm);
    const bool passed = worst_value <= 1e-12 && worst_moment <= 1e-13 * size;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::printf("%s: %dD %s box, largest error at a quadrature point %.2e "
                  "(limit 1e-12; %s), largest moment of the error %.2e "
                  "(limit %.2e)\n",
                  passed ? "PASS" : "FAIL",
                  dim,
                  affine ? "sheared" : "distorted",
                  worst_value,
                  affine ? "every mode" : "the constant",
                  worst_moment,
                  1e-13 * size);
    return passed;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             passed = true;
  passed &= check<2>(true);
  passed &= check<2>(false);
  passed &= check<3>(true);
  passed &= check<3>(false);
  return passed ? 0 : 1;
}
