#include "enclosed_fluid.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "undetermined_pressures.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
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
        /// every owned cell's set and constant pressure DoF (kept here)
        std::vector<std::pair<unsigned int, types::global_dof_index>>
          cell_constants;

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

        // Elements of `sets`: an owned DoF's place in the owned range, then
        // the DoFs owned elsewhere, all of which lie on ghost cells too.
        std::unordered_set<types::global_dof_index> ghost_dofs;
        std::vector<types::global_dof_index>        dofs(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_ghost())
            {
              cell->get_dof_indices(dofs);
              for (const unsigned int j : velocity_local)
                ghost_dofs.insert(dofs[j]);
            }
        const IndexSet &owned   = dof_handler.locally_owned_dofs();
        const auto      n_owned = owned.n_elements();
        boost::disjoint_sets_with_storage<> sets(n_owned + ghost_dofs.size());
        std::vector<bool>                   owned_free(n_owned, false);
        std::unordered_map<types::global_dof_index, std::size_t> other;
        const auto element_of = [&](const types::global_dof_index dof) {
          if (owned.is_element(dof))
            {
              const auto k  = owned.index_within_set(dof);
              owned_free[k] = true;
              return static_cast<std::size_t>(k);
            }
          return n_owned + other.emplace(dof, other.size()).first->second;
        };

        constexpr std::size_t invalid = ~std::size_t(0);
        std::vector<std::pair<std::size_t, types::global_dof_index>> cell_sets;
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            if (!cell->is_locally_owned())
              continue;
            cell->get_dof_indices(dofs);
            std::size_t first = invalid;
            for (const unsigned int j : velocity_local)
              if (!is_fixed_by_constraint(zero_constraints, dofs[j]))
                {
                  const std::size_t element = element_of(dofs[j]);
                  if (first == invalid)
                    first = element;
                  else
                    sets.union_set(first, element);
                }
            if (first != invalid)
              cell_sets.emplace_back(first, dofs[pressure_constant]);
          }

        // number the sets 0, 1, ... by their roots
        LocalSets                 local;
        std::vector<unsigned int> number(n_owned + ghost_dofs.size(), ~0u);
        const auto                set_number = [&](const std::size_t i) {
          unsigned int &n = number[sets.find_set(i)];
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
            local.cell_constants.emplace_back(n, pressure);
            if (std::binary_search(decoupled.begin(),
                                   decoupled.end(),
                                   pressure))
              continue;
            if (local.pressure[n] == numbers::invalid_dof_index)
              local.pressure[n] = pressure;
          }
        for (unsigned int k = 0; k < n_owned; ++k)
          if (owned_free[k])
            {
              const unsigned int n = set_number(k);
              ++local.sizes[n];
              const types::global_dof_index dof = owned.nth_index_in_set(k);
              if (ghost_dofs.count(dof) > 0)
                local.shared.insert(local.shared.end(), {dof, n});
            }
        for (const auto &[dof, j] : other)
          local.shared.insert(local.shared.end(),
                              {dof, set_number(n_owned + j)});
        return local;
      }

      /** What a rank's set is part of. */
      enum SetRole : char
      {
        flow,
        /// the set of a pocket whose pressure is decoupled
        pocket_representative,
        pocket
      };

      /**
       * On the root: the sets of all ranks joined through their shared
       * DoFs. Returns, per rank and set, its role: in the flow, or in a
       * pocket, one set of which decouples a pressure.
       */
      std::vector<std::vector<char>>
      join_across_ranks(const std::vector<LocalSets> &ranks)
      {
        std::vector<unsigned int> offset(ranks.size() + 1, 0);
        for (unsigned int r = 0; r < ranks.size(); ++r)
          offset[r + 1] = offset[r] + ranks[r].sizes.size();
        boost::disjoint_sets_with_storage<> sets(offset.back());
        std::vector<std::pair<unsigned long long, unsigned int>> shared;
        for (unsigned int r = 0; r < ranks.size(); ++r)
          for (std::size_t k = 0; k < ranks[r].shared.size(); k += 2)
            shared.emplace_back(ranks[r].shared[k],
                                offset[r] + ranks[r].shared[k + 1]);
        std::sort(shared.begin(), shared.end());
        for (std::size_t k = 1; k < shared.size(); ++k)
          if (shared[k].first == shared[k - 1].first)
            sets.union_set(std::size_t(shared[k].second),
                           std::size_t(shared[k - 1].second));

        std::vector<unsigned long long> size(offset.back(), 0);
        for (unsigned int r = 0; r < ranks.size(); ++r)
          for (unsigned int n = 0; n < ranks[r].sizes.size(); ++n)
            size[sets.find_set(std::size_t(offset[r] + n))]
              += ranks[r].sizes[n];
        const auto largest = std::max_element(size.begin(), size.end());

        std::vector<std::vector<char>> role(ranks.size());
        for (unsigned int r = 0; r < ranks.size(); ++r)
          {
            role[r].assign(ranks[r].sizes.size(), pocket);
            for (unsigned int n = 0; n < ranks[r].sizes.size(); ++n)
              {
                const std::size_t i    = offset[r] + n;
                const std::size_t root = sets.find_set(i);
                if (size.begin() + root == largest)
                  role[r][n] = flow;
                else if (root == i)
                  role[r][n] = pocket_representative;
              }
          }
        return role;
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
      std::vector<std::vector<char>> role;
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          std::vector<LocalSets> all;
          for (const auto &packed : gathered)
            all.push_back(LocalSets::unpacked(packed));
          role = join_across_ranks(all);
        }
      role = Utilities::MPI::broadcast(communicator, role, 0);
      for (const auto &rank : role)
        found.n_pockets
          += std::count(rank.begin(), rank.end(), pocket_representative);
      const auto &mine = role[Utilities::MPI::this_mpi_process(communicator)];
      for (unsigned int n = 0; n < mine.size(); ++n)
        if (mine[n] == pocket_representative
            && local.pressure[n] != numbers::invalid_dof_index)
          found.pinned_pressures.push_back(local.pressure[n]);
      for (const auto &[n, constant] : local.cell_constants)
        if (mine[n] == flow)
          found.flow_constants.push_back(constant);
      std::sort(found.pinned_pressures.begin(), found.pinned_pressures.end());
      std::sort(found.flow_constants.begin(), found.flow_constants.end());
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
