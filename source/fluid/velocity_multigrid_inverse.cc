#include "velocity_multigrid_inverse.h"

#include <algorithm>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    VelocityMultigridInverse<dim>::VelocityMultigridInverse(
      std::unique_ptr<VelocityMultigrid<dim>> multigrid,
      const IndexSet                         &owned_velocity,
      const MPI_Comm                          communicator,
      const MultigridOnMovingMesh             on_moving_mesh,
      const ConditionalOStream               &log)
      : multigrid(std::move(multigrid))
      , owned_velocity(owned_velocity)
      , communicator(communicator)
      , on_moving_mesh(on_moving_mesh)
      , log(log)
    {}



    template <int dim>
    void
    VelocityMultigridInverse<dim>::linearise(const VelocityLinearisation &a)
    {
      TrilinosWrappers::MPI::Vector velocity(owned_velocity, communicator);
      velocity = *a.velocity;
      multigrid->set_linearisation(velocity,
                                   a.mass_coefficient,
                                   a.theta_implicit,
                                   *a.viscosity);
      is_linearised = true;
    }



    namespace {
      /*
       * The V-cycle of a geometry the mesh has since moved from is worn out
       * once FGMRES needs a fifth more iterations than with a fresh one,
       * plus 2: a tighter rule than for a kept matrix
       * (kept_preconditioner_is_worn). A refresh costs about as much as a
       * dozen iterations and the iterations grow by a few per step after
       * it, so a refresh every few steps costs least overall; every motion
       * is too often (doc/performance.md, "Preconditioners on a moving
       * mesh").
       */
      bool
      kept_geometry_is_worn(const unsigned int iterations,
                            const unsigned int fresh_iterations)
      {
        return iterations > 1.2 * fresh_iterations + 2;
      }
    } // namespace



    template <int dim>
    bool
    VelocityMultigridInverse<dim>::prepare(const VelocityLinearisation &a)
    {
      if (!is_linearised)
        linearise(a);
      // linearised at this very matrix, unless the mesh has moved since its
      // geometry was built
      return !geometry_is_stale;
    }



    template <int dim>
    void
    VelocityMultigridInverse<dim>::rebuild(const VelocityLinearisation &a)
    {
      refresh_geometry();
      linearise(a);
    }



    template <int dim>
    void
    VelocityMultigridInverse<dim>::vmult(
      TrilinosWrappers::MPI::Vector       &dst,
      const TrilinosWrappers::MPI::Vector &src) const
    {
      multigrid->vmult(dst, src);
    }



    template <int dim>
    void
    VelocityMultigridInverse<dim>::record_solve(const unsigned int iterations,
                                                const bool         fresh)
    {
      // With no fresh solve yet (a run or restart whose mesh moved before
      // its first solve) the first one stands in: its V-cycle is one motion
      // old, and counting all of its iterations as extra would rebuild for
      // nothing.
      if (fresh || recent_fresh_iterations.empty())
        {
          auto &recent = recent_fresh_iterations;
          recent.push_back(iterations);
          if (recent.size() > 5)
            recent.erase(recent.begin());
          std::vector<unsigned int> sorted = recent;
          std::nth_element(sorted.begin(),
                           sorted.begin() + sorted.size() / 2,
                           sorted.end());
          fresh_iterations = sorted[sorted.size() / 2];
          log << (fresh ? "      fresh V-cycle: " :
                          "      first solve, taken as fresh: ")
              << iterations << " FGMRES iterations (reference now "
              << fresh_iterations << ")" << std::endl;
          return;
        }
      const bool worn = kept_geometry_is_worn(iterations, fresh_iterations);
      log << "      kept V-cycle: " << iterations
          << " FGMRES iterations against " << fresh_iterations
          << " with a fresh one" << (worn ? ": rebuilt" : "") << std::endl;
      if (worn)
        refresh_geometry(); // for the next solve
    }



    template <int dim>
    void
    VelocityMultigridInverse<dim>::reset()
    {
      multigrid->forget_linearisations();
      // a restarted run builds its V-cycles on the current mesh
      if (geometry_is_stale)
        refresh_geometry();
      is_linearised = false;
    }



    template <int dim>
    void
    VelocityMultigridInverse<dim>::mesh_moved()
    {
      // a V-cycle is only a preconditioner: with 'keep' the old geometry's
      // serves until FGMRES needs markedly more iterations (record_solve())
      if (on_moving_mesh == MultigridOnMovingMesh::keep)
        geometry_is_stale = true;
      else
        refresh_geometry();
    }



    template <int dim>
    void
    VelocityMultigridInverse<dim>::refresh_geometry()
    {
      multigrid->update_geometry();
      is_linearised     = false;
      geometry_is_stale = false;
    }

    template class VelocityMultigridInverse<2>;
    template class VelocityMultigridInverse<3>;
  } // namespace fluid
} // namespace particulate
