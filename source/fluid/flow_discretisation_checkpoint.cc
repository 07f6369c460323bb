#include <particulate/core/checkpoint.h>
#include <particulate/fluid/flow_discretisation.h>

#include <stdexcept>

#include "owned_entries_io.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    void
    FlowDiscretisation<dim>::save_solution(std::ostream &out) const
    {
      core::write_binary<unsigned long>(out, dof_handler.n_dofs());
      core::write_binary<unsigned int>(out, dofs_per_block.size());
      write_owned(out, solution, owned_partitioning);
    }



    template <int dim>
    void
    FlowDiscretisation<dim>::load_solution(std::istream &in)
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
    }

    template void
    FlowDiscretisation<2>::save_solution(std::ostream &) const;
    template void
    FlowDiscretisation<3>::save_solution(std::ostream &) const;
    template void
    FlowDiscretisation<2>::load_solution(std::istream &);
    template void
    FlowDiscretisation<3>::load_solution(std::istream &);
  } // namespace fluid
} // namespace particulate
