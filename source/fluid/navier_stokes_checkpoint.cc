#include <particulate/core/checkpoint.h>
#include <particulate/fluid/navier_stokes.h>

#include <stdexcept>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /** The locally owned entries of @p v in index order. */
      void
      write_owned(std::ostream                             &out,
                  const TrilinosWrappers::MPI::BlockVector &v,
                  const std::vector<IndexSet>              &owned)
      {
        for (unsigned int b = 0; b < owned.size(); ++b)
          {
            core::write_binary<unsigned long>(out, owned[b].n_elements());
            for (const auto i : owned[b])
              core::write_binary<double>(out, v.block(b)(i));
          }
      }

      void
      read_owned(std::istream                       &in,
                 TrilinosWrappers::MPI::BlockVector &owned_vector,
                 const std::vector<IndexSet>        &owned)
      {
        for (unsigned int b = 0; b < owned.size(); ++b)
          {
            if (core::read_binary<unsigned long>(in) != owned[b].n_elements())
              throw std::runtime_error(
                "the fluid unknowns of this rank differ from the saved ones "
                "(was the mesh or the element changed in the case file?)");
            for (const auto i : owned[b])
              owned_vector.block(b)(i) = core::read_binary<double>(in);
          }
        owned_vector.compress(VectorOperation::insert);
      }
    } // namespace



    template <int dim>
    void
    NavierStokes<dim>::save_state(std::ostream &out) const
    {
      core::write_binary<unsigned long>(out, dof_handler.n_dofs());
      core::write_binary<unsigned int>(out, dofs_per_block.size());
      write_owned(out, solution, owned_partitioning);
      core::write_binary<bool>(out, has_previous_solution);
      core::write_binary<double>(out, previous_time);
      if (has_previous_solution)
        write_owned(out, previous_solution, owned_partitioning);
    }



    template <int dim>
    void
    NavierStokes<dim>::load_state(std::istream &in)
    {
      const auto n_saved = core::read_binary<unsigned long>(in);
      if (n_saved != dof_handler.n_dofs())
        throw std::runtime_error(
          "the checkpoint has " + std::to_string(n_saved)
          + " fluid unknowns and this mesh "
          + std::to_string(dof_handler.n_dofs())
          + "; restart with the mesh of the checkpointed run");
      if (core::read_binary<unsigned int>(in) != dofs_per_block.size())
        throw std::runtime_error("the checkpoint's block structure differs");
      BlockVector owned = make_owned_vector();
      read_owned(in, owned, owned_partitioning);
      solution              = owned;
      has_previous_solution = core::read_binary<bool>(in);
      previous_time         = core::read_binary<double>(in);
      if (has_previous_solution)
        {
          read_owned(in, owned, owned_partitioning);
          previous_solution = owned;
        }
      reset_preconditioners();
    }



    template <int dim>
    void
    NavierStokes<dim>::reset_preconditioners()
    {
      velocity_amg.reset();
      if (velocity_multigrid)
        {
          velocity_multigrid->forget_linearisations();
          // a restarted run builds its V-cycles on the current mesh
          if (multigrid_geometry_is_stale)
            refresh_multigrid_geometry();
        }
      velocity_multigrid_is_current  = false;
      schur_approximation_is_current = false;
    }



    template void
    NavierStokes<2>::save_state(std::ostream &) const;
    template void
    NavierStokes<3>::save_state(std::ostream &) const;
    template void
    NavierStokes<2>::load_state(std::istream &);
    template void
    NavierStokes<3>::load_state(std::istream &);
    template void
    NavierStokes<2>::reset_preconditioners();
    template void
    NavierStokes<3>::reset_preconditioners();
  } // namespace fluid
} // namespace particulate
