// The pressure mode no equation of an enclosed flow determines, made exact on
// the reduced system (source/fluid/flow_pressure_mode.cc). On the unit square
// in 6 x 6 distorted Q2/P1disc cells with fixed walls, bodies fix velocities:
// - two cells have every velocity fixed but one vertex they share with the
//   flow: a cell's three pressures see only that node's two velocities, so
//   each has a null mode that mixes its constant with its gradients, and
//   the patch search decouples one pressure for it, the constant;
// - one more cell has every velocity fixed and loses all its pressures.
// The returned vector z must be a left null vector of the divergence block
// B (pressure rows not decoupled, free velocity columns): z^T B = 0 to
// round-off, and it must be zero on every decoupled pressure. The plain
// constant on the flow's cells, with the decoupled entries dropped, is not
// one: its z^T B is checked to be far from zero, so the first check could
// fail if the patch modes were not used.
//
// The constant pressure is a null vector at all only where the divergence
// of every free velocity integrates to zero: on these straight-sided cells
// constant_pressure_is_null_mode() must say it is; on the ball mesh of
// prm/sphere-in-container (the sphere's manifold on the boundary cells,
// refined twice) the flux of some face functions is 18 % of a cell's, and
// it must say it is not.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "../../source/fluid/enclosed_fluid.h"
#include "../../source/fluid/flow_pressure_mode.h"
#include "../../source/fluid/undetermined_pressures.h"
#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  constexpr unsigned int n = 6;

  /** Largest |(z^T B)_j| over the free velocity DoFs j. */
  double
  largest_flux(const DoFHandler<2>                             &dof_handler,
               const MappingQ<2>                               &mapping,
               const AffineConstraints<double>                 &constraints,
               const std::map<types::global_dof_index, double> &z)
  {
    const auto                               &fe = dof_handler.get_fe();
    const QGauss<2>                           quadrature(3);
    FEValues<2>                               fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector          velocity(0);
    const FEValuesExtractors::Scalar          pressure(2);
    std::vector<types::global_dof_index>      dofs(fe.n_dofs_per_cell());
    std::map<types::global_dof_index, double> flux;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell->get_dof_indices(dofs);
        for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
          {
            const auto found = z.find(dofs[k]);
            if (fe.system_to_component_index(k).first != 2 || found == z.end())
              continue;
            for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
              if (fe.system_to_component_index(j).first < 2
                  && !fluid::is_fixed_by_constraint(constraints, dofs[j]))
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  flux[dofs[j]] += found->second
                                   * fe_values[pressure].value(k, q)
                                   * fe_values[velocity].divergence(j, q)
                                   * fe_values.JxW(q);
          }
      }
    double largest = 0.;
    for (const auto &[dof, value] : flux)
      largest = std::max(largest, std::abs(value));
    return largest;
  }

  /** constant_pressure_is_null_mode() with fixed walls, velocities
   *  numbered first. */
  template <int dim>
  bool
  constant_is_null_mode(DoFHandler<dim>     &dof_handler,
                        const MappingQ<dim> &mapping)
  {
    std::vector<unsigned int> blocks(dim + 1, 0);
    blocks[dim] = 1;
    DoFRenumbering::component_wise(dof_handler, blocks);
    AffineConstraints<double> walls;
    VectorTools::interpolate_boundary_values(
      mapping,
      dof_handler,
      0,
      Functions::ZeroFunction<dim>(dim + 1),
      walls,
      dof_handler.get_fe().component_mask(FEValuesExtractors::Vector(0)));
    walls.close();
    const auto n_velocities
      = DoFTools::count_dofs_per_fe_block(dof_handler, blocks)[0];
    return fluid::constant_pressure_is_null_mode(
      dof_handler,
      mapping,
      walls,
      dof_handler.locally_owned_dofs().get_view(0, n_velocities),
      DoFTools::extract_locally_relevant_dofs(dof_handler),
      MPI_COMM_WORLD);
  }

  std::string
  scientific(const double value)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%.2e", value);
    return text;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;

  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_cube(tria, n, 0., 1.);
  for (const auto &cell : tria.active_cell_iterators())
    cell->set_user_index(unsigned(cell->center()[0] * n)
                         + n * unsigned(cell->center()[1] * n));
  GridTools::distort_random(0.2, tria, false, 11);
  const FESystem<2> fe(FE_Q<2>(2), 2, FE_DGP<2>(1), 1);
  DoFHandler<2>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const MappingQ<2> mapping(2);

  // walls
  AffineConstraints<double> constraints;
  VectorTools::interpolate_boundary_values(mapping,
                                           dof_handler,
                                           0,
                                           Functions::ZeroFunction<2>(3),
                                           constraints,
                                           fe.component_mask(
                                             FEValuesExtractors::Vector(0)));
  // bodies: cell (2, 2) but its top right vertex, cell (4, 3) but its
  // bottom left one, and all of cell (2, 4)
  const std::map<unsigned int, unsigned int> free_vertex{{2 + n * 2, 3},
                                                         {4 + n * 3, 0},
                                                         {2 + n * 4, ~0u}};
  std::vector<types::global_dof_index>       dofs(fe.n_dofs_per_cell());
  std::vector<types::global_dof_index>       prescribed;
  for (const auto &cell : dof_handler.active_cell_iterators())
    {
      const auto body = free_vertex.find(cell->user_index());
      if (body == free_vertex.end())
        continue;
      cell->get_dof_indices(dofs);
      for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
        {
          const auto [component, node] = fe.system_to_component_index(k);
          if (component < 2 && node != body->second)
            {
              prescribed.push_back(dofs[k]);
              if (!constraints.is_constrained(dofs[k]))
                constraints.add_line(dofs[k]);
            }
        }
    }
  constraints.close();
  std::sort(prescribed.begin(), prescribed.end());
  prescribed.erase(std::unique(prescribed.begin(), prescribed.end()),
                   prescribed.end());

  const fluid::UndeterminedPressures undetermined
    = fluid::find_undetermined_pressure_dofs(dof_handler,
                                             mapping,
                                             constraints,
                                             prescribed);
  const fluid::EnclosedFluid enclosed
    = fluid::find_enclosed_fluid(dof_handler,
                                 constraints,
                                 undetermined.decoupled,
                                 MPI_COMM_WORLD);
  std::vector<types::global_dof_index> decoupled;
  std::set_union(undetermined.decoupled.begin(),
                 undetermined.decoupled.end(),
                 enclosed.pinned_pressures.begin(),
                 enclosed.pinned_pressures.end(),
                 std::back_inserter(decoupled));

  std::map<types::global_dof_index, double> mode, plain;
  for (const auto &[dof, value] :
       fluid::enclosed_flow_pressure_mode(enclosed.flow_constants,
                                          undetermined.patches,
                                          decoupled))
    mode[dof] = value;
  for (const auto dof : enclosed.flow_constants)
    if (!std::binary_search(decoupled.begin(), decoupled.end(), dof))
      plain[dof] = 1.;

  // the scale of B: one cell's flux of a unit velocity, about h
  const double h = 1. / n;
  const double flux_mode
    = largest_flux(dof_handler, mapping, constraints, mode);
  const double flux_plain
    = largest_flux(dof_handler, mapping, constraints, plain);
  bool zero_on_decoupled = true;
  for (const auto dof : decoupled)
    zero_on_decoupled &= mode.count(dof) == 0;

  checker.check(enclosed.n_pockets == 0, "no pocket");
  unsigned int patch_pins = 0;
  for (const auto &patch : undetermined.patches)
    patch_pins += patch.pinned.size();
  checker.check(patch_pins >= 2 && decoupled.size() == 3 + patch_pins,
                "the covered cell's 3 pressures decoupled, and "
                  + std::to_string(patch_pins) + " for patch modes");
  checker.check(mode.size() >= n * n - 3,
                "the mode covers the flow (" + std::to_string(mode.size())
                  + " entries)");
  checker.check(zero_on_decoupled, "the mode is zero on decoupled pressures");
  checker.check(flux_mode < 1e-10 * h,
                "z^T B = 0 to round-off (largest " + scientific(flux_mode)
                  + ")");
  checker.check(flux_plain > 1e-3 * h,
                "the plain constant is no null vector here (largest "
                  + scientific(flux_plain) + ")");

  DoFHandler<2> straight(tria);
  straight.distribute_dofs(fe);
  checker.check(constant_is_null_mode(straight, mapping),
                "straight-sided cells: the constant is a null mode");
  Triangulation<3> ball;
  GridGenerator::hyper_ball(ball, Point<3>(), 1., true);
  ball.refine_global(2);
  const FESystem<3> fe_3d(FE_Q<3>(2), 3, FE_DGP<3>(1), 1);
  DoFHandler<3>     curved(ball);
  curved.distribute_dofs(fe_3d);
  checker.check(!constant_is_null_mode(curved, MappingQ<3>(2)),
                "the ball mesh: the constant is none");
  return checker.exit_code();
}
