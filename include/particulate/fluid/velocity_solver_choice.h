#ifndef particulate_fluid_velocity_solver_choice_h
#define particulate_fluid_velocity_solver_choice_h

#include <particulate/fluid/fluid_parameters.h>

#include <deal.II/grid/tria.h>

#include <string>

namespace particulate {
  namespace fluid {
    /**
     * What `Velocity preconditioner = automatic` and `Velocity operator =
     * automatic` become on a given mesh, and the line the run prints about
     * it.
     */
    struct VelocitySolverChoice
    {
      VelocityPreconditioner preconditioner;
      VelocityOperator       velocity_operator;
      /// e.g. "geometric multigrid, matrix-free operator (automatic)"
      std::string description;
    };

    /**
     * The coordinate axis that the normal of the boundary face @p face
     * points along, or dim where it points along none. The multigrid's
     * level rows can hold a free-slip constraint u.n = 0 only where it
     * fixes one whole velocity component, that is on planes normal to an
     * axis.
     */
    template <int dim>
    unsigned int
    axis_along_normal(
      const typename dealii::Triangulation<dim>::face_iterator &face);

    /**
     * Why the geometric multigrid velocity preconditioner (and with it the
     * matrix-free operator) cannot run on @p tria with @p conditions, in a
     * phrase such as "the free-slip boundary 3 is not a plane normal to a
     * coordinate axis"; empty when it can. Collective over the mesh's
     * communicator.
     */
    template <int dim>
    std::string
    geometric_multigrid_obstacle(const dealii::Triangulation<dim> &tria,
                                 const BoundaryConditions         &conditions);

    /**
     * @p requested with its automatic choices made for @p tria: the
     * geometric multigrid on the matrix-free operator where the mesh allows
     * it, AMG on the assembled operator otherwise. Explicit choices stay as
     * they are. Collective over the mesh's communicator.
     */
    template <int dim>
    VelocitySolverChoice
    resolve_velocity_solver(const LinearSolverParameters     &requested,
                            const BoundaryConditions         &conditions,
                            const dealii::Triangulation<dim> &tria);
  } // namespace fluid
} // namespace particulate

#endif
