#ifndef particulate_fluid_owned_entries_io_h
#define particulate_fluid_owned_entries_io_h

#include <particulate/core/checkpoint.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <iosfwd>
#include <stdexcept>
#include <vector>

namespace particulate {
  namespace fluid {
    /** Checkpoint helpers: this rank's locally owned entries of a block
     *  vector, block by block in index order, each block led by its
     *  size. */
    inline void
    write_owned(std::ostream                                     &out,
                const dealii::TrilinosWrappers::MPI::BlockVector &v,
                const std::vector<dealii::IndexSet>              &owned)
    {
      for (unsigned int b = 0; b < owned.size(); ++b)
        {
          core::write_binary<unsigned long>(out, owned[b].n_elements());
          for (const auto i : owned[b])
            core::write_binary<double>(out, v.block(b)(i));
        }
    }

    /** Reads what write_owned() wrote into @p owned_vector (locally owned
     *  layout). Throws std::runtime_error when the sizes differ. */
    inline void
    read_owned(std::istream                               &in,
               dealii::TrilinosWrappers::MPI::BlockVector &owned_vector,
               const std::vector<dealii::IndexSet>        &owned)
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
      owned_vector.compress(dealii::VectorOperation::insert);
    }
  } // namespace fluid
} // namespace particulate

#endif
