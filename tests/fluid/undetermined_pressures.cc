// Which pressure modes no equation determines once bodies fix velocities
// (source/fluid/undetermined_pressures.cc), on one Q2/P1disc cell where the
// answer follows from the divergence theorem:
// - every velocity free: (q, div v) sees all three modes, none is pinned;
// - only the interior (bubble) node free: the bubble vanishes on the cell's
//   boundary, so (1, div v) = the flux of v through the boundary = 0 and the
//   constant mode is unseen, while (x - x_c, div v) = -(1, v_x) != 0 sees the
//   two gradient modes: exactly the constant mode is pinned;
// - every velocity fixed: all three modes are pinned;
// - one vertex node fixed: nothing is pinned, unless its DoFs are where two
//   parts of an articulated body meet (`joint_dofs`): then the cell loses
//   all three.
// The same in 3D (four modes, one of them the constant) with the centre node
// of a Q2 hexahedron.

#include "../../source/fluid/undetermined_pressures.h"

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  /// the pinned local pressure indices (0 = constant mode of FE_DGP) of one
  /// cell whose velocity DoFs are fixed as @p which says
  template <int dim>
  std::vector<unsigned int>
  pinned_modes(const std::string &which)
  {
    Triangulation<dim> tria;
    GridGenerator::hyper_cube(tria, 0., 1.);
    // a distorted cell, so that the answer is not an artefact of symmetry
    GridTools::distort_random(0.2, tria, false, 7);
    const FESystem<dim> fe(FE_Q<dim>(2), dim, FE_DGP<dim>(1), 1);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const MappingQ<dim> mapping(2);

    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    dof_handler.begin_active()->get_dof_indices(dofs);
    AffineConstraints<double>            constraints;
    std::vector<types::global_dof_index> prescribed, joints;
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto [component, index] = fe.system_to_component_index(i);
        if (component == dim)
          continue;
        // the interior node is the last support point of FE_Q(2)
        const bool bubble = index == fe.base_element(0).n_dofs_per_cell() - 1;
        const bool vertex = index == 0;
        if (which == "all" || (which == "all but the bubble" && !bubble)
            || (which.rfind("a vertex", 0) == 0 && vertex))
          {
            constraints.add_line(dofs[i]);
            prescribed.push_back(dofs[i]);
            if (which == "a vertex at a joint")
              joints.push_back(dofs[i]);
          }
      }
    constraints.close();
    if (prescribed.empty())
      // with nothing fixed, the cell is examined only if it touches a body:
      // a prescribed DoF that is not constrained (every velocity is free)
      prescribed.push_back(dofs[0]);
    std::sort(prescribed.begin(), prescribed.end());
    std::sort(joints.begin(), joints.end());

    std::vector<unsigned int> modes;
    for (const auto dof : fluid::find_undetermined_pressure_dofs(dof_handler,
                                                                 mapping,
                                                                 constraints,
                                                                 prescribed,
                                                                 joints)
                            .decoupled)
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        if (dofs[i] == dof)
          modes.push_back(fe.system_to_component_index(i).second);
    std::sort(modes.begin(), modes.end());
    return modes;
  }



  template <int dim>
  void
  check(testing::Checker &checker)
  {
    const std::string d = std::to_string(dim) + "D: ";
    checker.check(pinned_modes<dim>("none").empty(),
                  d + "all velocities free: no mode pinned");
    checker.check(pinned_modes<dim>("all but the bubble")
                    == std::vector<unsigned int>{0},
                  d + "only the bubble free: the constant mode pinned");
    checker.check(pinned_modes<dim>("all").size() == dim + 1,
                  d + "all velocities fixed: every mode pinned");
    checker.check(pinned_modes<dim>("a vertex").empty(),
                  d + "a vertex node fixed: no mode pinned");
    checker.check(pinned_modes<dim>("a vertex at a joint").size() == dim + 1,
                  d + "a vertex node at a joint: every mode pinned");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  check<2>(checker);
  check<3>(checker);
  return checker.exit_code();
}
