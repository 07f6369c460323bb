#include <particulate/fluid/velocity_solver_choice.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /** The lowest free-slip boundary id with a face off the axis planes
       *  on this rank, or -1. Looks at the cells of every level this rank
       *  knows, as the multigrid's level constraints do. */
      template <int dim>
      int
      skewed_free_slip_id(const Triangulation<dim>        &tria,
                          const std::vector<unsigned int> &free_slip)
      {
        int found = -1;
        for (const auto &cell : tria.cell_iterators())
          if (cell->level_subdomain_id() != numbers::artificial_subdomain_id)
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary()
                  && std::count(free_slip.begin(),
                                free_slip.end(),
                                face->boundary_id())
                       > 0
                  && axis_along_normal<dim>(face) == dim)
                {
                  const int id = static_cast<int>(face->boundary_id());
                  found        = found < 0 ? id : std::min(found, id);
                }
        return found;
      }
    } // namespace



    template <int dim>
    unsigned int
    axis_along_normal(const typename Triangulation<dim>::face_iterator &face)
    {
      const Tensor<1, dim> normal
        = face->get_manifold().normal_vector(face, face->center());
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(normal[d]) >= (1. - 1e-10) * normal.norm())
          return d;
      return dim;
    }



    template <int dim>
    std::string
    geometric_multigrid_obstacle(const Triangulation<dim> &tria,
                                 const BoundaryConditions &conditions)
    {
      const MPI_Comm comm = tria.get_communicator();
      if (Utilities::MPI::max(tria.has_hanging_nodes() ? 1 : 0, comm) > 0)
        return "the mesh has hanging nodes";
      // the lowest offending id over all ranks
      const int none  = std::numeric_limits<int>::max();
      const int local = skewed_free_slip_id(tria, conditions.free_slip);
      const int id    = Utilities::MPI::min(local < 0 ? none : local, comm);
      if (id != none)
        return "the free-slip boundary " + std::to_string(id)
               + " is not a plane normal to a coordinate axis";
      return "";
    }



    template <int dim>
    VelocitySolverChoice
    resolve_velocity_solver(const LinearSolverParameters &requested,
                            const BoundaryConditions     &conditions,
                            const Triangulation<dim>     &tria)
    {
      VelocitySolverChoice choice{requested.velocity_preconditioner,
                                  requested.velocity_operator,
                                  ""};
      std::string          note;
      if (choice.preconditioner == VelocityPreconditioner::automatic)
        {
          const bool matrix_free_asked
            = choice.velocity_operator == VelocityOperator::matrix_free;
          // the case's reasons give way to an explicit matrix-free
          // operator, which needs the multigrid; the mesh's do not
          std::string obstacle = matrix_free_asked ?
                                   std::string() :
                                   requested.multigrid_ruled_out_by;
          if (obstacle.empty())
            obstacle = geometric_multigrid_obstacle(tria, conditions);
          if (!obstacle.empty() && matrix_free_asked)
            throw std::runtime_error(
              "subsection 'Linear solver': 'Velocity operator = matrix-free' "
              "needs the geometric multigrid, which this mesh does not "
              "allow: "
              + obstacle
              + ". Set 'Velocity operator' to 'assembled' or 'automatic'.");
          choice.preconditioner
            = obstacle.empty() ? VelocityPreconditioner::geometric_multigrid :
                                 VelocityPreconditioner::amg;
          note = obstacle.empty() ? " (automatic)" :
                                    " (automatic: " + obstacle + ")";
        }
      if (choice.velocity_operator == VelocityOperator::automatic)
        choice.velocity_operator
          = choice.preconditioner
                == VelocityPreconditioner::geometric_multigrid ?
              VelocityOperator::matrix_free :
              VelocityOperator::assembled;
      choice.description = to_string(choice.preconditioner) + ", "
                           + to_string(choice.velocity_operator) + " operator"
                           + note;
      return choice;
    }



    template unsigned int
    axis_along_normal<2>(const Triangulation<2>::face_iterator &);
    template unsigned int
    axis_along_normal<3>(const Triangulation<3>::face_iterator &);
    template std::string
    geometric_multigrid_obstacle(const Triangulation<2> &,
                                 const BoundaryConditions &);
    template std::string
    geometric_multigrid_obstacle(const Triangulation<3> &,
                                 const BoundaryConditions &);
    template VelocitySolverChoice
    resolve_velocity_solver(const LinearSolverParameters &,
                            const BoundaryConditions &,
                            const Triangulation<2> &);
    template VelocitySolverChoice
    resolve_velocity_solver(const LinearSolverParameters &,
                            const BoundaryConditions &,
                            const Triangulation<3> &);
  } // namespace fluid
} // namespace particulate
