#include <particulate/fbm/particle_parameters.h>
#include <particulate/fbm/set_up_warnings.h>
#include <particulate/geometry/mapped_surface.h>

#include <algorithm>
#include <sstream>

namespace particulate {
  namespace fbm {
    namespace set_up_warnings {
      namespace {
        /// the fraction of a cell below which a contact distance counts as
        /// thinner than the cell: room for the cells of a graded mesh
        /// around a particle and for rounding (the automatic contact
        /// distance is the smallest cell edge)
        constexpr double thinnest_resolved_film = 0.9;
      } // namespace

      std::string
      resolution(const std::vector<double> &sizes,
                 const std::vector<double> &cell_sizes)
      {
        unsigned int n_coarse = 0, worst = 0;
        double       fewest = minimum_cells_across;
        for (unsigned int i = 0; i < sizes.size(); ++i)
          {
            if (!(cell_sizes[i] > 0.))
              continue;
            const double across = sizes[i] / cell_sizes[i];
            if (across >= minimum_cells_across)
              continue;
            ++n_coarse;
            if (across < fewest)
              {
                fewest = across;
                worst  = i;
              }
          }
        if (n_coarse == 0)
          return "";
        std::ostringstream message;
        message << "Warning: " << n_coarse << " of " << sizes.size()
                << " particle(s) span fewer than " << minimum_cells_across
                << " cells across their size; the fewest, particle " << worst
                << ", spans " << fewest << " (size " << sizes[worst]
                << " m, cell " << cell_sizes[worst]
                << " m at its centre). The fictitious boundary resolves them "
                   "coarsely: the drag of a fixed cylinder is 2.7 % low at 4 "
                   "cells per diameter and within 1.4 % from 8 on "
                   "(doc/validation/dfg-2d-1-fbm.md). Refine the mesh around "
                   "the particles "
                   "('Refinements' in subsection 'Mesh', or subsection "
                   "'Mesh deformation') if their forces matter.";
        return message.str();
      }



      std::string
      coupling_stability(const std::vector<double> &density_ratios,
                         const double               added_mass_coefficient,
                         const unsigned int         dim)
      {
        const double added_mass = dim == 2 ? 1. : 0.5;
        const double limit      = added_mass - 2. * added_mass_coefficient;
        unsigned int n_unstable = 0, lightest = 0;
        for (unsigned int i = 0; i < density_ratios.size(); ++i)
          if (density_ratios[i] < limit)
            {
              if (n_unstable == 0
                  || density_ratios[i] < density_ratios[lightest])
                lightest = i;
              ++n_unstable;
            }
        if (n_unstable == 0)
          return "";
        std::ostringstream message;
        message << "Warning: " << n_unstable
                << " free particle(s) are lighter than the explicit coupling "
                   "can carry with 'Added mass coefficient' = "
                << added_mass_coefficient << ": the lightest has rho_p / "
                << "rho_f = " << density_ratios[lightest]
                << ", below C_a - 2 C = " << limit << " (C_a = " << added_mass
                << " for a " << (dim == 2 ? "disk" : "sphere")
                << "), where its acceleration grows from step to step. A "
                   "disk of ratio 0.5 with C = 0 flipped its acceleration "
                   "in every step at 10 ms and was smooth with C = 1 "
                   "(doc/developer/fbm.md, \"Stability for light particles\"). "
                   "Set "
                   "'Added mass coefficient' in subsection 'Particles' to "
                   "at least "
                << (added_mass - density_ratios[lightest]) / 2.
                << " (the default is "
                << ParticleParameters{}.added_mass_coefficient << ").";
        return message.str();
      }



      std::string
      contact_distance(const double               contact_distance,
                       const std::vector<double> &cell_sizes)
      {
        unsigned int n_thin       = 0;
        double       largest_cell = 0.;
        for (const double h : cell_sizes)
          if (contact_distance < thinnest_resolved_film * h)
            {
              ++n_thin;
              largest_cell = std::max(largest_cell, h);
            }
        if (n_thin == 0)
          return "";
        std::ostringstream message;
        message << "Warning: the contact distance, " << contact_distance
                << " m, is below the cell size at " << n_thin << " of "
                << cell_sizes.size() << " free particle(s) (up to "
                << largest_cell
                << " m): films between particles, or between a particle "
                   "and a wall, thinner than a cell are not resolved, and "
                   "the pressure in them can throw particles together or "
                   "apart (doc/developer/fbm.md, \"Near contact\"). Set "
                   "'Contact distance' in subsection 'Particles' to the "
                   "cell size or more where particles meet.";
        return message.str();
      }



      std::string
      thin_surface_meshes(const std::vector<std::string> &names,
                          const std::vector<double>      &thicknesses,
                          const std::vector<double>      &spacings)
      {
        std::ostringstream message;
        for (unsigned int i = 0; i < names.size(); ++i)
          if (thicknesses[i] < 2. * spacings[i])
            message << (message.tellp() > 0 ? "\n" : "")
                    << "Warning: the surface mesh of shape '" << names[i]
                    << "' is only " << thicknesses[i]
                    << " m thick where its distance map resolves it, less "
                       "than two map cells (spacing "
                    << spacings[i]
                    << " m): its thin parts may let nodes and contacts "
                       "through. Set a smaller 'Map spacing' in subsection "
                       "'Particles / Shape "
                    << names[i] << "'.";
        return message.str();
      }



      std::string
      thin_surface_meshes(const std::vector<ParticleDescription> &particles)
      {
        std::vector<std::string> names;
        std::vector<double>      thicknesses, spacings;
        for (const ParticleDescription &p : particles)
          if (const auto *mesh
              = dynamic_cast<const geometry::MappedSurface *>(p.shape.get());
              mesh
              && std::find(names.begin(), names.end(), p.shape_name)
                   == names.end())
            {
              names.push_back(p.shape_name);
              thicknesses.push_back(2. * mesh->map().deepest_inside());
              spacings.push_back(mesh->map().spacing());
            }
        return thin_surface_meshes(names, thicknesses, spacings);
      }
    } // namespace set_up_warnings
  }   // namespace fbm
} // namespace particulate
