// 'Velocity preconditioner = automatic' and 'Velocity operator = automatic'
// (the defaults): the geometric multigrid on the matrix-free operator where
// the mesh allows it, AMG on the assembled operator where it does not, and
// AMG for steady flow.
//  - a box whose free-slip walls are planes normal to the axes: multigrid,
//    matrix-free;
//  - the same box rotated by 30 degrees: its free-slip walls are skewed
//    planes, so AMG, assembled, and the log line names the boundary; with no
//    free-slip walls the rotated box takes the multigrid again;
//  - a disk with a free-slip rim (a curved boundary): AMG; asking there for
//    the matrix-free operator is refused with a message naming the cause;
//  - a box with one cell refined (hanging nodes): AMG;
//  - explicit choices are kept as they are, on any mesh;
//  - the library's steady DFG 2D-1 takes AMG ("steady flow"), unless it asks
//    for the matrix-free operator; its time-dependent DFG 2D-2 leaves the
//    choice to the mesh.

#include <particulate/fluid/velocity_solver_choice.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <iostream>
#include <stdexcept>
#include <string>

#include "test_utilities.h"

using namespace dealii;
using namespace particulate;
using namespace particulate::fluid;

namespace {
  /** The unit square cut into 4 x 4 cells, boundary ids 0-3 (x-, x+, y-,
   *  y+), rotated by @p degrees about the origin. */
  void
  make_box(Triangulation<2> &tria, const double degrees)
  {
    GridGenerator::hyper_rectangle(tria, Point<2>(0, 0), Point<2>(1, 1), true);
    tria.refine_global(2);
    if (degrees != 0.)
      GridTools::rotate(degrees * numbers::PI / 180., tria);
  }

  BoundaryConditions
  free_slip_on(const std::vector<unsigned int> &ids)
  {
    BoundaryConditions conditions;
    conditions.free_slip = ids;
    return conditions;
  }

  void
  check_choice(testing::Checker            &checker,
               const VelocitySolverChoice  &choice,
               const VelocityPreconditioner preconditioner,
               const VelocityOperator       velocity_operator,
               const std::string           &phrase,
               const std::string           &what)
  {
    std::cout << what << ": " << choice.description << std::endl;
    checker.check(choice.preconditioner == preconditioner
                    && choice.velocity_operator == velocity_operator,
                  what + ": " + to_string(preconditioner) + ", "
                    + to_string(velocity_operator));
    checker.check(choice.description.find(phrase) != std::string::npos,
                  what + ": the log line says '" + phrase + "'");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const LinearSolverParameters     automatic;
  checker.check(automatic.velocity_preconditioner
                    == VelocityPreconditioner::automatic
                  && automatic.velocity_operator == VelocityOperator::automatic,
                "the defaults are automatic");

  {
    Triangulation<2> box;
    make_box(box, 0.);
    check_choice(checker,
                 resolve_velocity_solver(automatic, free_slip_on({0, 2}), box),
                 VelocityPreconditioner::geometric_multigrid,
                 VelocityOperator::matrix_free,
                 "(automatic)",
                 "box with free-slip planes x = 0, y = 0");
  }
  {
    Triangulation<2> rotated;
    make_box(rotated, 30.);
    check_choice(checker,
                 resolve_velocity_solver(automatic, free_slip_on({2}), rotated),
                 VelocityPreconditioner::amg,
                 VelocityOperator::assembled,
                 "free-slip boundary 2 is not a plane normal",
                 "rotated box with a free-slip wall");
    check_choice(checker,
                 resolve_velocity_solver(automatic, free_slip_on({}), rotated),
                 VelocityPreconditioner::geometric_multigrid,
                 VelocityOperator::matrix_free,
                 "(automatic)",
                 "rotated box without free-slip walls");
  }
  {
    Triangulation<2> disk;
    GridGenerator::hyper_ball(disk);
    disk.refine_global(1);
    check_choice(checker,
                 resolve_velocity_solver(automatic, free_slip_on({0}), disk),
                 VelocityPreconditioner::amg,
                 VelocityOperator::assembled,
                 "free-slip boundary 0",
                 "disk with a free-slip rim");
    LinearSolverParameters matrix_free = automatic;
    matrix_free.velocity_operator      = VelocityOperator::matrix_free;
    std::string message;
    try
      {
        resolve_velocity_solver(matrix_free, free_slip_on({0}), disk);
      }
    catch (const std::runtime_error &e)
      {
        message = e.what();
      }
    std::cout << "matrix-free on the disk: " << message << std::endl;
    checker.check(message.find("'Velocity operator = matrix-free'")
                      != std::string::npos
                    && message.find("free-slip boundary 0")
                         != std::string::npos,
                  "the matrix-free operator on the disk is refused, "
                  "naming the entry and the boundary");
  }
  {
    Triangulation<2> box;
    make_box(box, 0.);
    box.begin_active()->set_refine_flag();
    box.execute_coarsening_and_refinement();
    check_choice(checker,
                 resolve_velocity_solver(automatic, free_slip_on({}), box),
                 VelocityPreconditioner::amg,
                 VelocityOperator::assembled,
                 "hanging nodes",
                 "box with hanging nodes");
    LinearSolverParameters chebyshev  = automatic;
    chebyshev.velocity_preconditioner = VelocityPreconditioner::chebyshev;
    check_choice(checker,
                 resolve_velocity_solver(chebyshev, free_slip_on({}), box),
                 VelocityPreconditioner::chebyshev,
                 VelocityOperator::assembled,
                 "Chebyshev, assembled operator",
                 "Chebyshev asked for by name");
  }
  {
    Triangulation<2> box;
    make_box(box, 0.);
    LinearSolverParameters amg  = automatic;
    amg.velocity_preconditioner = VelocityPreconditioner::amg;
    check_choice(checker,
                 resolve_velocity_solver(amg, free_slip_on({0}), box),
                 VelocityPreconditioner::amg,
                 VelocityOperator::assembled,
                 "AMG, assembled operator",
                 "AMG asked for by name on the box");
  }

  Triangulation<2> box;
  make_box(box, 0.);
  const auto steady = testing::library_case("dfg-2d-1", "");
  check_choice(checker,
               resolve_velocity_solver(steady.fluid.linear_solver,
                                       free_slip_on({}),
                                       box),
               VelocityPreconditioner::amg,
               VelocityOperator::assembled,
               "(automatic: steady flow)",
               "steady DFG 2D-1 as shipped");
  const auto steady_matrix_free = testing::library_case(
    "dfg-2d-1",
    "subsection Linear solver\n set Velocity operator = matrix-free\nend\n");
  check_choice(checker,
               resolve_velocity_solver(steady_matrix_free.fluid.linear_solver,
                                       free_slip_on({}),
                                       box),
               VelocityPreconditioner::geometric_multigrid,
               VelocityOperator::matrix_free,
               "(automatic)",
               "steady DFG 2D-1 asking for the matrix-free operator");
  const auto unsteady = testing::library_case("dfg-2d-2", "");
  checker.check(unsteady.fluid.linear_solver.multigrid_ruled_out_by.empty(),
                "time-dependent DFG 2D-2 as shipped: left to the mesh");
  return checker.exit_code();
}
