#include "enclosed_fluid.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>

#include <algorithm>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "undetermined_pressures.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /// a set whose pressure is decoupled (join_across_ranks())
      constexpr char decouple = 1;

      /** Disjoint sets of 0 ... n-1, by parent links with path halving. */
      class DisjointSets
      {
      public:
        unsigned int
        add()
        {
          parent.push_back(parent.size());
          return parent.size() - 1;
        }

        unsigned int
        find(unsigned int i)
        {
          while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
          return i;
        }

        void
        join(const unsigned int a, const unsigned int b)
        {
          const unsigned int ra = find(a), rb = find(b);
          if (ra != rb)
            parent[std::max(ra, rb)] = std::min(ra, rb);
        }

        unsigned int
        size() const
        {
          return parent.size();
        }

      private:
        std::vector<unsigned int> parent;
      };

      /**
       * One rank's sets: their free velocity DoFs owned here, a pressure
       * DoF (a cell's constant mode) of each, and the sets' DoFs that ghost
       * cells share with another rank, as (DoF, set) pairs.
       */
      struct LocalSets
      {
        std::vector<unsigned long long>      sizes;
        std::vector<types::global_dof_index> pressure;
        std::vector<unsigned long long>      shared; // dof, set, dof, set...

        /** What the root needs: the sizes, then the shared pairs. */
        std::vector<unsigned long long>
        packed() const
        {
          std::vector<unsigned long long> out{sizes.size()};
          out.insert(out.end(), sizes.begin(), sizes.end());
          out.insert(out.end(), shared.begin(), shared.end());
          return out;
        }

        static LocalSets
        unpacked(const std::vector<unsigned long long> &in)
        {
          LocalSets sets;
          sets.sizes.assign(in.begin() + 1, in.begin() + 1 + in[0]);
          sets.shared.assign(in.begin() + 1 + in[0], in.end());
          return sets;
        }
      };

      template <int dim>
      LocalSets
      connect_local_cells(const DoFHandler<dim>           &dof_handler,
                          const AffineConstraints<double> &zero_constraints,
                          const std::vector<types::global_dof_index> &decoupled)
      {
        const auto               &fe = dof_handler.get_fe();
        std::vector<unsigned int> velocity_local;
        unsigned int              pressure_constant = 0;
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const auto [component, index] = fe.system_to_component_index(i);
            if (component < dim)
              velocity_local.push_back(i);
            else if (index == 0)
              pressure_constant = i;
          }

        DisjointSets sets;
        // each free velocity DoF's element of `sets`: owned ones by their
        // place in the owned range, the others in a map
        const IndexSet           &owned = dof_handler.locally_owned_dofs();
        std::vector<unsigned int> set_of_owned(owned.n_elements(), ~0u);
        std::unordered_map<types::global_dof_index, unsigned> set_of_other;
        const auto element_of = [&](const types::global_dof_index dof) {
          unsigned int &element
            = owned.is_element(dof) ?
                set_of_owned[owned.index_within_set(dof)] :
                set_of_other.emplace(dof, ~0u).first->second;
          if (element == ~0u)
            element = sets.add();
          return element;
        };
        std::vector<std::pair<unsigned, types::global_dof_index>> cell_sets;
        std::unordered_set<types::global_dof_index>               ghost_dofs;
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            if (cell->is_artificial())
              continue;
            cell->get_dof_indices(dofs);
            if (cell->is_ghost())
              {
                for (const unsigned int j : velocity_local)
                  ghost_dofs.insert(dofs[j]);
                continue;
              }
            int first = -1;
            for (const unsigned int j : velocity_local)
              if (!is_fixed_by_constraint(zero_constraints, dofs[j]))
                {
                  const unsigned int element = element_of(dofs[j]);
                  if (first < 0)
                    first = element;
                  else
                    sets.join(first, element);
                }
            if (first >= 0)
              cell_sets.emplace_back(first, dofs[pressure_constant]);
          }

        // number the sets 0, 1, ... by their roots
        LocalSets                 local;
        std::vector<unsigned int> number(sets.size(), ~0u);
        const auto                set_number = [&](const unsigned int i) {
          unsigned int &n = number[sets.find(i)];
          if (n == ~0u)
            {
              n = local.sizes.size();
              local.sizes.push_back(0);
              local.pressure.push_back(numbers::invalid_dof_index);
            }
          return n;
        };
        // a cell whose constant pressure is still coupled (another pin
        // there could leave the set's mode in place)
        for (const auto &[i, pressure] : cell_sets)
          {
            const unsigned int n = set_number(i);
            if (std::binary_search(decoupled.begin(),
                                   decoupled.end(),
                                   pressure))
              continue;
            if (local.pressure[n] == numbers::invalid_dof_index)
              local.pressure[n] = pressure;
          }
        for (unsigned int k = 0; k < set_of_owned.size(); ++k)
          if (set_of_owned[k] != ~0u)
            {
              const unsigned int n = set_number(set_of_owned[k]);
              ++local.sizes[n];
              const types::global_dof_index dof = owned.nth_index_in_set(k);
              if (ghost_dofs.count(dof) > 0)
                local.shared.insert(local.shared.end(), {dof, n});
            }
        for (const auto &[dof, i] : set_of_other)
          local.shared.insert(local.shared.end(), {dof, set_number(i)});
        return local;
      }

      /**
       * On the root: the sets of all ranks joined through their shared
       * DoFs. Returns, per rank and set, `decouple` if that set's pressure
       * is to be decoupled (one set of every pocket); counts the pockets.
       */
      std::vector<std::vector<char>>
      join_across_ranks(const std::vector<LocalSets> &ranks,
                        EnclosedFluid                &found)
      {
        std::vector<unsigned int> offset(ranks.size() + 1, 0);
        for (unsigned int r = 0; r < ranks.size(); ++r)
          offset[r + 1] = offset[r] + ranks[r].sizes.size();
        DisjointSets sets;
        for (unsigned int i = 0; i < offset.back(); ++i)
          sets.add();
        std::vector<std::pair<unsigned long long, unsigned int>> shared;
        for (unsigned int r = 0; r < ranks.size(); ++r)
          for (std::size_t k = 0; k < ranks[r].shared.size(); k += 2)
            shared.emplace_back(ranks[r].shared[k],
                                offset[r] + ranks[r].shared[k + 1]);
        std::sort(shared.begin(), shared.end());
        for (std::size_t k = 1; k < shared.size(); ++k)
          if (shared[k].first == shared[k - 1].first)
            sets.join(shared[k].second, shared[k - 1].second);

        std::vector<unsigned long long> size(offset.back(), 0);
        for (unsigned int r = 0; r < ranks.size(); ++r)
          for (unsigned int n = 0; n < ranks[r].sizes.size(); ++n)
            size[sets.find(offset[r] + n)] += ranks[r].sizes[n];
        const auto largest = std::max_element(size.begin(), size.end());

        std::vector<std::vector<char>> pin(ranks.size());
        for (unsigned int r = 0; r < ranks.size(); ++r)
          {
            pin[r].assign(ranks[r].sizes.size(), 0);
            for (unsigned int n = 0; n < ranks[r].sizes.size(); ++n)
              {
                const unsigned int i = offset[r] + n;
                // a root is the lowest index of its set: pin there
                if (sets.find(i) == i && size.begin() + i != largest)
                  {
                    pin[r][n] = decouple;
                    ++found.n_pockets;
                    found.n_pocket_dofs += size[i];
                  }
              }
          }
        return pin;
      }
    } // namespace



    template <int dim>
    EnclosedFluid
    find_enclosed_fluid(const DoFHandler<dim>           &dof_handler,
                        const AffineConstraints<double> &zero_constraints,
                        const std::vector<types::global_dof_index> &decoupled,
                        MPI_Comm communicator)
    {
      const LocalSets local
        = connect_local_cells(dof_handler, zero_constraints, decoupled);
      const auto gathered
        = Utilities::MPI::gather(communicator, local.packed(), 0);
      EnclosedFluid                  found;
      std::vector<std::vector<char>> pin;
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          std::vector<LocalSets> all;
          for (const auto &packed : gathered)
            all.push_back(LocalSets::unpacked(packed));
          pin = join_across_ranks(all, found);
        }
      pin = Utilities::MPI::broadcast(communicator, pin, 0);
      found.n_pockets
        = Utilities::MPI::broadcast(communicator, found.n_pockets, 0);
      found.n_pocket_dofs
        = Utilities::MPI::broadcast(communicator, found.n_pocket_dofs, 0);
      const auto &mine = pin[Utilities::MPI::this_mpi_process(communicator)];
      for (unsigned int n = 0; n < mine.size(); ++n)
        if (mine[n] == decouple
            && local.pressure[n] != numbers::invalid_dof_index)
          found.pinned_pressures.push_back(local.pressure[n]);
      std::sort(found.pinned_pressures.begin(), found.pinned_pressures.end());
      return found;
    }



    template EnclosedFluid
    find_enclosed_fluid<2>(const DoFHandler<2> &,
                           const AffineConstraints<double> &,
                           const std::vector<types::global_dof_index> &,
                           MPI_Comm);
    template EnclosedFluid
    find_enclosed_fluid<3>(const DoFHandler<3> &,
                           const AffineConstraints<double> &,
                           const std::vector<types::global_dof_index> &,
                           MPI_Comm);
  } // namespace fluid
} // namespace particulate
