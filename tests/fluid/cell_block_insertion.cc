// Direct insertion of a cell's saddle-point blocks (include/particulate/
// fluid/cell_block_insertion.h, what the Jacobian assembly uses) against
// the reference, AffineConstraints::distribute_local_to_global into the
// same Trilinos block matrix. Q2^dim x P1disc on a distorted, fully
// distributed box, 2D and 3D, on the ranks the test is started with;
// random cell matrices; velocities constrained on the walls and inside a
// ball (as the fictitious boundary constrains them), some diagonal entries
// zero and some cells without any (the average-diagonal and l1-norm
// rules), some pressures decoupled (no row, no column). Checks:
// - the direct path applies to plain Dirichlet constraints and is refused
//   once a constraint couples DoFs (a hanging-node-like line);
// - ||direct - reference||_F <= 1e-14 ||reference||_F in every block (the
//   same additions in the same order: equal up to nothing but rounding).

#include <particulate/fluid/cell_block_insertion.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "distorted_box.h"
#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  template <int dim>
  void
  check_insertion(testing::Checker &checker)
  {
    const MPI_Comm                                 comm = MPI_COMM_WORLD;
    parallel::fullydistributed::Triangulation<dim> tria(comm);
    testing::make_distorted_box(tria, dim == 2 ? 8 : 4, 5);

    const FESystem<dim>           fe(FE_Q<dim>(2), dim, FE_DGP<dim>(1), 1);
    DoFHandler<dim>               dof_handler(tria);
    const types::global_dof_index n_u
      = testing::distribute_velocities_first(dof_handler, fe);
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    IndexSet        relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    const std::vector<IndexSet> partitioning
      = {owned.get_view(0, n_u), owned.get_view(n_u, owned.size())};
    const std::vector<IndexSet> relevant_partitioning
      = {relevant.get_view(0, n_u), relevant.get_view(n_u, relevant.size())};

    // velocities fixed on the walls and inside a ball around a point off
    // the mesh's symmetry
    const std::map<types::global_dof_index, Point<dim>> points
      = testing::velocity_node_positions(MappingQ1<dim>(), dof_handler);
    const IndexSet on_walls
      = DoFTools::extract_boundary_dofs(dof_handler,
                                        fe.component_mask(
                                          FEValuesExtractors::Vector(0)));
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.45 + 0.03 * d;
    AffineConstraints<double> constraints(relevant);
    for (const auto dof : relevant)
      if (dof < n_u
          && (on_walls.is_element(dof)
              || points.at(dof).distance(centre) < 0.2))
        constraints.add_line(dof);
    constraints.close();

    Table<2, DoFTools::Coupling> coupling(dim + 1, dim + 1);
    for (unsigned int c = 0; c < dim + 1; ++c)
      for (unsigned int d = 0; d < dim + 1; ++d)
        coupling[c][d]
          = (c == dim && d == dim) ? DoFTools::none : DoFTools::always;
    TrilinosWrappers::BlockSparsityPattern pattern(partitioning,
                                                   partitioning,
                                                   relevant_partitioning,
                                                   comm);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    coupling,
                                    pattern,
                                    constraints,
                                    true,
                                    Utilities::MPI::this_mpi_process(comm));
    pattern.compress();
    TrilinosWrappers::BlockSparseMatrix reference, direct;
    reference.reinit(pattern);
    direct.reinit(pattern);

    const bool applies
      = fluid::CellBlockInsertion::applicable(direct, constraints, n_u);
    checker.check(Utilities::MPI::min(int(applies), comm) == 1,
                  std::to_string(dim)
                    + "D: direct insertion applies to Dirichlet rows");
    {
      AffineConstraints<double>     coupled(relevant);
      const types::global_dof_index first = *partitioning[0].begin();
      coupled.add_line(first);
      coupled.add_entry(first, first + 1, 0.5);
      coupled.close();
      checker.check(!fluid::CellBlockInsertion::applicable(direct,
                                                           coupled,
                                                           n_u),
                    std::to_string(dim)
                      + "D: and is refused for a constraint that couples DoFs");
    }

    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   local(n, n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<unsigned int>            velocity_local, pressure_local;
    for (unsigned int i = 0; i < n; ++i)
      (fe.system_to_component_index(i).first < dim ? velocity_local :
                                                     pressure_local)
        .push_back(i);
    std::vector<types::global_dof_index> velocity_dofs(velocity_local.size()),
      pressure_dofs(pressure_local.size());
    fluid::CellBlockInsertion insertion;
    unsigned int              cell_count = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          // the same numbers on any partition
          std::mt19937 random(std::hash<std::string>()(cell->id().to_string()));
          std::uniform_real_distribution<double> entry(-1., 1.);
          ++cell_count;
          // every third cell without any diagonal entry (the l1-norm
          // rule), every fifth with its pressures decoupled
          const bool no_diagonal = cell_count % 3 == 0;
          const bool decoupled   = cell_count % 5 == 0;
          local                  = 0.;
          for (const unsigned int i : velocity_local)
            {
              for (const unsigned int j : velocity_local)
                local(i, j) = entry(random);
              // elsewhere every seventh diagonal entry zero (the average
              // rule)
              local(i, i)
                = (no_diagonal || dofs[i] % 7 == 0) ? 0. : 4. + entry(random);
              for (const unsigned int k : pressure_local)
                local(i, k) = local(k, i) = entry(random);
            }
          for (unsigned int k = 0; k < pressure_local.size(); ++k)
            pressure_dofs[k] = decoupled ? numbers::invalid_dof_index :
                                           dofs[pressure_local[k]];
          for (unsigned int i = 0; i < velocity_local.size(); ++i)
            velocity_dofs[i] = dofs[velocity_local[i]];

          insertion.add_saddle_point_cell(
            direct,
            constraints,
            velocity_dofs,
            pressure_dofs,
            n_u,
            [&](const unsigned int i, const unsigned int j) {
              return local(velocity_local[i], velocity_local[j]);
            },
            [&](const unsigned int k, const unsigned int j) {
              return local(pressure_local[k], velocity_local[j]);
            },
            n);
          if (decoupled)
            for (const unsigned int k : pressure_local)
              for (unsigned int i = 0; i < n; ++i)
                local(k, i) = local(i, k) = 0.;
          constraints.distribute_local_to_global(local, dofs, reference);
        }
    reference.compress(VectorOperation::add);
    direct.compress(VectorOperation::add);

    for (const auto &[r, c] :
         {std::pair<unsigned int, unsigned int>{0, 0}, {0, 1}, {1, 0}})
      {
        TrilinosWrappers::SparseMatrix difference;
        difference.copy_from(direct.block(r, c));
        difference.add(-1., reference.block(r, c));
        const double norm  = reference.block(r, c).frobenius_norm();
        const double error = difference.frobenius_norm();
        char         numbers[120];
        std::snprintf(numbers,
                      sizeof(numbers),
                      " (||reference||_F = %.4g, ||difference||_F = %.2e)",
                      norm,
                      error);
        checker.check(norm > 0. && error <= 1e-14 * norm,
                      std::to_string(dim) + "D block (" + std::to_string(r)
                        + "," + std::to_string(c)
                        + "): direct insertion equals "
                          "distribute_local_to_global"
                        + numbers);
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  check_insertion<2>(checker);
  check_insertion<3>(checker);
  return checker.exit_code();
}
