#include <particulate/core/checkpoint.h>
#include <particulate/fluid/navier_stokes.h>

#include <stdexcept>

#include "owned_entries_io.h"
#include "velocity_block_inverse.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    void
    NavierStokes<dim>::save_state(std::ostream &out) const
    {
      core::write_binary<unsigned long>(out, dof_handler.n_dofs());
      core::write_binary<unsigned int>(out, dofs_per_block.size());
      write_owned(out, solution, owned_partitioning);
      time_integrator.save(out);
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
      solution = owned;
      time_integrator.load(in);
      reset_preconditioners();
    }



    template <int dim>
    void
    NavierStokes<dim>::reset_preconditioners()
    {
      velocity_inverse->reset();
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
