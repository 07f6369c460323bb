// The in-place update of the pressure Laplacian (source/fluid/
// pressure_laplacian.cc) against its definition. With B^T the Q2/P1disc
// gradient, D the lumped velocity mass, M_v and M_p the 0/1 masks of free
// velocities and coupled pressures,
//
//   L_p = (M_v B^T M_p)^T D^{-1} (M_v B^T M_p),
//
// formed here directly by deal.II's Tmmult, and by PressureLaplacian::update
// as L_base (all velocities not fixed by the walls) minus the part of the
// covered velocities. A ball moves through a distorted box over four
// positions; at the last it covers wall nodes, which changes the split
// between wall-fixed and covered velocities and must rebuild L_base.
// Checks, 2D and 3D, on the ranks the test is started with:
// - |(L_update - L_direct) x| <= 1e-12 |L_direct x| for random x (the two
//   differ by the rounding of a subtraction only);
// - the same first flow row (the pressure pinned in enclosed flow);
// - the matrix keeps its Epetra object while the wall-fixed set stays, and
//   keeps_structure() says so; it does not at the wall.

#include <particulate/fluid/pressure_laplacian.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/fully_distributed_tria.h>
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
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <cstdio>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "distorted_box.h"
#include "test_utilities.h"
#include <Epetra_CrsMatrix.h>

using namespace dealii;
using namespace particulate;

namespace {
  template <int dim>
  void
  check_update(testing::Checker &checker)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    // distorted: no symmetry that could hide an entry missing from L_base
    parallel::fullydistributed::Triangulation<dim> tria(comm);
    testing::make_distorted_box(tria, dim == 2 ? 10 : 5, 3);

    const FESystem<dim>           fe(FE_Q<dim>(2), dim, FE_DGP<dim>(1), 1);
    DoFHandler<dim>               dof_handler(tria);
    const types::global_dof_index n_u
      = testing::distribute_velocities_first(dof_handler, fe);
    const IndexSet             &owned = dof_handler.locally_owned_dofs();
    const std::vector<IndexSet> partitioning
      = {owned.get_view(0, n_u), owned.get_view(n_u, owned.size())};
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

    // B^T (velocity rows, pressure columns): -(div v, q); the lumped
    // velocity mass D_i = integral of the basis function of node i
    Table<2, DoFTools::Coupling> coupling(dim + 1, dim + 1);
    for (unsigned int c = 0; c < dim + 1; ++c)
      for (unsigned int d = 0; d < dim + 1; ++d)
        coupling[c][d]
          = (c < dim && d == dim) ? DoFTools::always : DoFTools::none;
    const std::vector<IndexSet> relevant_partitioning
      = {relevant.get_view(0, n_u), relevant.get_view(n_u, relevant.size())};
    TrilinosWrappers::BlockSparsityPattern pattern(partitioning,
                                                   partitioning,
                                                   relevant_partitioning,
                                                   comm);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    coupling,
                                    pattern,
                                    AffineConstraints<double>(),
                                    true,
                                    Utilities::MPI::this_mpi_process(comm));
    pattern.compress();
    TrilinosWrappers::BlockSparseMatrix system;
    system.reinit(pattern);
    TrilinosWrappers::MPI::Vector lumped_mass(partitioning[0], comm);

    const MappingQ<dim>                  mapping(2);
    const QGauss<dim>                    quadrature(3);
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients
                              | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   local(n, n);
    Vector<double>                       local_mass(n);
    std::vector<types::global_dof_index> dofs(n);
    const AffineConstraints<double>      none;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          local      = 0.;
          local_mass = 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int ci = fe.system_to_component_index(i).first;
                if (ci == dim)
                  continue;
                local_mass(i) += fe_values.shape_value(i, q) * fe_values.JxW(q);
                for (unsigned int j = 0; j < n; ++j)
                  if (fe.system_to_component_index(j).first == dim)
                    local(i, j) -= fe_values.shape_grad(i, q)[ci]
                                   * fe_values.shape_value(j, q)
                                   * fe_values.JxW(q);
              }
          cell->get_dof_indices(dofs);
          none.distribute_local_to_global(local, dofs, system);
          for (unsigned int i = 0; i < n; ++i)
            if (fe.system_to_component_index(i).first < dim)
              lumped_mass(dofs[i]) += local_mass(i);
        }
    system.compress(VectorOperation::add);
    lumped_mass.compress(VectorOperation::add);
    TrilinosWrappers::MPI::Vector inverse_mass(partitioning[0], comm);
    for (const auto i : partitioning[0])
      inverse_mass(i) = 1. / lumped_mass(i);
    inverse_mass.compress(VectorOperation::insert);
    const TrilinosWrappers::SparseMatrix &gradient = system.block(0, 1);

    // velocity nodes: on the walls, and their support points
    const ComponentMask velocities
      = fe.component_mask(FEValuesExtractors::Vector(0));
    const IndexSet on_walls
      = DoFTools::extract_boundary_dofs(dof_handler, velocities);
    const std::map<types::global_dof_index, Point<dim>> points
      = testing::velocity_node_positions(mapping, dof_handler);

    fluid::PressureLaplacian       update;
    TrilinosWrappers::SparseMatrix laplacian;
    const Epetra_CrsMatrix        *previous_object = nullptr;
    const double                   radius          = 0.23;
    for (const double centre_x : {0.35, 0.42, 0.5, 0.85})
      {
        Point<dim> centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = 0.5;
        centre[0]         = centre_x;
        const auto inside = [&](const types::global_dof_index dof) {
          return points.at(dof).distance(centre) < radius;
        };
        // owned velocities fixed by the walls / covered by the ball
        // (covered wins, as in the solver), and the free-velocity mask
        std::vector<types::global_dof_index> wall_fixed, covered;
        TrilinosWrappers::MPI::Vector free_velocity(partitioning[0], comm);
        for (const auto dof : partitioning[0])
          {
            free_velocity(dof) = 1.;
            if (inside(dof))
              covered.push_back(dof);
            else if (on_walls.is_element(dof))
              wall_fixed.push_back(dof);
            else
              continue;
            free_velocity(dof) = 0.;
          }
        free_velocity.compress(VectorOperation::insert);
        // decoupled pressures: those of cells with every velocity fixed
        TrilinosWrappers::MPI::Vector free_pressure(partitioning[1], comm);
        free_pressure = 1.;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              bool all_fixed = true;
              for (unsigned int i = 0; i < n; ++i)
                if (fe.system_to_component_index(i).first < dim)
                  all_fixed &= inside(dofs[i]) || on_walls.is_element(dofs[i]);
              if (all_fixed)
                for (unsigned int i = 0; i < n; ++i)
                  if (fe.system_to_component_index(i).first == dim)
                    free_pressure(dofs[i] - n_u) = 0.;
            }
        free_pressure.compress(VectorOperation::insert);

        // the definition
        TrilinosWrappers::SparseMatrix masked, direct;
        masked.copy_from(gradient);
        auto &epetra = const_cast<Epetra_CrsMatrix &>(masked.trilinos_matrix());
        epetra.LeftScale(*free_velocity.trilinos_vector()(0));
        epetra.RightScale(*free_pressure.trilinos_vector()(0));
        masked.Tmmult(direct, masked, inverse_mass);
        types::global_dof_index direct_flow_row;
        fluid::regularise_empty_pressure_rows(direct, direct_flow_row);

        // the update
        const bool              keeps    = update.keeps_structure(wall_fixed);
        const auto              flow_row = update.update(laplacian,
                                            gradient,
                                            inverse_mass,
                                            wall_fixed,
                                            covered,
                                            free_pressure);
        const Epetra_CrsMatrix *object   = &laplacian.trilinos_matrix();
        const std::string       where
          = std::to_string(dim) + "D, ball at x = " + std::to_string(centre_x);
        const bool at_wall = centre_x + radius > 1.;
        if (previous_object != nullptr)
          {
            checker.check(keeps == !at_wall,
                          where + ": keeps_structure() is "
                            + (keeps ? "true" : "false"));
            if (keeps)
              checker.check(object == previous_object,
                            where + ": updated in place (same Epetra matrix)");
          }
        previous_object = object;

        std::mt19937                           random(11);
        std::uniform_real_distribution<double> uniform(-1., 1.);
        double                                 worst = 0.;
        for (unsigned int sample = 0; sample < 3; ++sample)
          {
            TrilinosWrappers::MPI::Vector x(partitioning[1], comm),
              y_direct(partitioning[1], comm), y(partitioning[1], comm);
            for (const auto i : partitioning[1])
              x(i) = uniform(random);
            x.compress(VectorOperation::insert);
            direct.vmult(y_direct, x);
            laplacian.vmult(y, x);
            y -= y_direct;
            worst = std::max(worst, y.l2_norm() / y_direct.l2_norm());
          }
        char text[120];
        std::snprintf(
          text,
          sizeof(text),
          ": |(L_update - L_direct) x| / |L_direct x| = %.2e "
          "(allowed 1e-12), %u covered velocities",
          worst,
          Utilities::MPI::sum(static_cast<unsigned int>(covered.size()), comm));
        checker.check(worst <= 1e-12, where + text);
        checker.check(flow_row == direct_flow_row,
                      where + ": same first flow row");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  check_update<2>(checker);
  check_update<3>(checker);
  return checker.exit_code();
}
