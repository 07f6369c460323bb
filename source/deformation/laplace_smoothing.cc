#include <particulate/deformation/laplace_smoothing.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    template <int dim>
    unsigned int
    smoothing_sweep(const VertexHierarchy<dim> &hierarchy,
                    const unsigned int          level,
                    const std::vector<double>  &weight,
                    const std::vector<bool>    &pinned,
                    const SmoothingSettings    &settings,
                    std::vector<Point<dim>>    &positions)
    {
      std::vector<Point<dim>> moved = positions;
      for (const unsigned int v : hierarchy.vertices_on_level(level))
        {
          if (pinned[v] || hierarchy.is_fixed(v))
            continue;
          Point<dim> average;
          double     sum = 0.;
          for (const unsigned int j : hierarchy.neighbours(level, v))
            {
              average += weight[j] * positions[j];
              sum += weight[j];
            }
          const Tensor<1, dim> step
            = settings.relaxation * (average / sum - positions[v]);
          moved[v] = positions[v] + hierarchy.admissible_displacement(v, step);
        }
      const unsigned int held
        = hierarchy.back_off(level, positions, moved, settings.min_quality);
      positions.swap(moved);
      return held;
    }



    namespace {
      /** The sweeps of one level (Algorithm 12's inner loop), the hat
       *  weights recomputed from the moved vertices before each. */
      template <int dim>
      void
      smooth_level(const VertexHierarchy<dim> &hierarchy,
                   const unsigned int          level,
                   const DistanceField<dim>   &distance,
                   const SmoothingSettings    &settings,
                   const std::vector<bool>    &pinned,
                   std::vector<Point<dim>>    &positions,
                   DeformationReport          &report)
      {
        std::vector<double> weight(positions.size(), 1.);
        for (unsigned int s = 0; s < settings.sweeps(level); ++s)
          {
            for (const unsigned int v : hierarchy.vertices_on_level(level))
              weight[v] = hat_weight(distance.signed_distance(positions[v]),
                                     settings.width,
                                     settings.peak_weight);
            report.held_back_vertices += smoothing_sweep(hierarchy,
                                                         level,
                                                         weight,
                                                         pinned,
                                                         settings,
                                                         positions);
            ++report.steps;
          }
      }
    } // namespace



    template <int dim>
    LaplaceKappa<dim>::LaplaceKappa(const SmoothingSettings &settings_)
      : settings(settings_)
    {}



    template <int dim>
    DeformationReport
    LaplaceKappa<dim>::deform(Triangulation<dim>       &tria,
                              const DistanceField<dim> &distance) const
    {
      DeformationReport          report;
      const VertexHierarchy<dim> hierarchy(tria);
      std::vector<Point<dim>>    positions = tria.get_vertices();
      const std::vector<bool>    pinned(positions.size(), false);
      for (unsigned int level = 0; level < hierarchy.n_levels(); ++level)
        {
          smooth_level(hierarchy,
                       level,
                       distance,
                       settings,
                       pinned,
                       positions,
                       report);
          if (level + 1 < hierarchy.n_levels())
            hierarchy.prolongate(level, positions);
        }
      VertexHierarchy<dim>::write_positions(tria, positions);
      report.quality = compute_mesh_quality(tria);
      return report;
    }



    template <int dim>
    LaplaceAlpha<dim>::LaplaceAlpha(const SmoothingSettings &settings_,
                                    const double             projection_range_)
      : settings(settings_)
      , projection_range(projection_range_)
    {}



    template <int dim>
    DeformationReport
    LaplaceAlpha<dim>::deform(Triangulation<dim>       &tria,
                              const DistanceField<dim> &distance) const
    {
      std::vector<bool> on_surface;
      return deform(tria, distance, on_surface);
    }



    template <int dim>
    DeformationReport
    LaplaceAlpha<dim>::deform(Triangulation<dim>       &tria,
                              const DistanceField<dim> &distance,
                              std::vector<bool>        &pinned) const
    {
      DeformationReport          report;
      const VertexHierarchy<dim> hierarchy(tria);
      std::vector<Point<dim>>    positions = tria.get_vertices();
      pinned.assign(positions.size(), false);

      // Put vertex v onto the surface if that keeps it on its boundary.
      auto project = [&](const unsigned int v, std::vector<Point<dim>> &x) {
        Tensor<1, dim> normal;
        const double   d       = distance.signed_distance(x[v], &normal);
        const auto     step    = -d * normal;
        const auto     allowed = hierarchy.admissible_displacement(v, step);
        if ((allowed - step).norm() > 1e-12 * (1. + std::abs(d)))
          return false;
        x[v] += step;
        return true;
      };

      for (unsigned int level = 0; level < hierarchy.n_levels(); ++level)
        {
          // Vertices of this level close to a surface (within
          // projection_range of their shortest edge) go onto it: on the
          // coarsest level these start the trace of the surface, on finer
          // levels they start it where the body is smaller than the coarse
          // cells and no coarse vertex came near.
          std::vector<unsigned int> candidates;
          for (const unsigned int v : hierarchy.vertices_on_level(level))
            {
              if (pinned[v])
                continue;
              double shortest = std::numeric_limits<double>::max();
              for (const unsigned int j : hierarchy.neighbours(level, v))
                shortest
                  = std::min(shortest, positions[v].distance(positions[j]));
              Tensor<1, dim> normal;
              const double d = distance.signed_distance(positions[v], &normal);
              if (std::abs(d) >= projection_range * shortest)
                continue;
              // Where the surface is traced already (a pinned vertex near
              // the foot point, within two edges), a second vertex there
              // would only crush the cells between the two.
              const Point<dim> foot  = positions[v] - d * normal;
              bool             taken = false;
              for (const unsigned int j : hierarchy.neighbours(level, v))
                {
                  taken |= pinned[j]
                           && positions[j].distance(foot) < 0.5 * shortest;
                  for (const unsigned int k : hierarchy.neighbours(level, j))
                    taken |= pinned[k]
                             && positions[k].distance(foot) < 0.5 * shortest;
                }
              if (!taken)
                candidates.push_back(v);
            }
          if (level > 0)
            {
              // The edge midpoints this refinement created between two
              // vertices on the surface: the only new vertices with exactly
              // two neighbours from the coarser level, both pinned.
              std::vector<bool> old(positions.size(), false);
              for (const unsigned int v :
                   hierarchy.vertices_on_level(level - 1))
                old[v] = true;
              for (const unsigned int v : hierarchy.vertices_on_level(level))
                {
                  if (old[v])
                    continue;
                  unsigned int              n_pinned = 0;
                  std::vector<unsigned int> ends;
                  for (const unsigned int j : hierarchy.neighbours(level, v))
                    if (old[j])
                      {
                        ends.push_back(j);
                        n_pinned += pinned[j];
                      }
                  // Only an edge that runs along the surface: a chord
                  // across the body (both ends on the surface, the midpoint
                  // deep inside) would fold its cells when the midpoint is
                  // pulled out. Along the surface the midpoint is at most
                  // the sagitta, a quarter of the edge for arcs up to
                  // about 106 degrees.
                  if (ends.size() == 2 && n_pinned == 2
                      && std::abs(distance.signed_distance(positions[v]))
                           <= 0.25
                                * positions[ends[0]].distance(
                                  positions[ends[1]]))
                    candidates.push_back(v);
                }
            }
          // Project, keep every cell valid, and pin the vertices that got
          // there; smoothing then makes room, and the candidates that were
          // held back get a second try.
          auto project_candidates = [&]() {
            std::vector<Point<dim>>   projected = positions;
            std::vector<unsigned int> placed;
            for (const unsigned int v : candidates)
              if (!pinned[v] && !hierarchy.is_fixed(v) && project(v, projected))
                placed.push_back(v);
            const unsigned int held = hierarchy.back_off(level,
                                                         positions,
                                                         projected,
                                                         settings.min_quality);
            positions.swap(projected);
            // (a vertex may be a candidate twice: near the surface and an
            // edge midpoint between two surface vertices)
            for (const unsigned int v : placed)
              if (!pinned[v]
                  && std::abs(distance.signed_distance(positions[v]))
                       < 1e-9 * (1. + settings.width))
                {
                  pinned[v] = true;
                  ++report.projected_vertices;
                }
            return held;
          };
          project_candidates();
          smooth_level(hierarchy,
                       level,
                       distance,
                       settings,
                       pinned,
                       positions,
                       report);
          report.held_back_vertices += project_candidates();
          if (level + 1 < hierarchy.n_levels())
            hierarchy.prolongate(level, positions);
        }
      VertexHierarchy<dim>::write_positions(tria, positions);
      report.quality = compute_mesh_quality(tria);
      return report;
    }

    template <int dim>
    DeformationReport
    LaplaceAlpha<dim>::carry(
      Triangulation<dim>            &tria,
      const std::vector<Point<dim>> &undeformed,
      const DistanceField<dim>      &distance,
      const std::function<Tensor<1, dim>(const Point<dim> &)>
                        &body_displacement,
      std::vector<bool> &on_surface) const
    {
      DeformationReport              report;
      const VertexHierarchy<dim>     hierarchy(tria);
      const std::vector<Point<dim>> &current = tria.get_vertices();
      AssertDimension(on_surface.size(), current.size());
      AssertDimension(undeformed.size(), current.size());
      const double on_surface_tolerance = 1e-9 * (1. + settings.width);

      // where the bodies take their surface vertices (and back onto the
      // surface: round-off, and the chord of a curved path)
      std::vector<Point<dim>> target(current.size());
      for (unsigned int v = 0; v < current.size(); ++v)
        if (on_surface[v])
          {
            target[v] = current[v] + body_displacement(current[v]);
            Tensor<1, dim> normal;
            const double   d = distance.signed_distance(target[v], &normal);
            target[v] -= d * normal;
          }

      // Laplace-alpha's level-by-level pass from the undeformed mesh, with
      // the surface vertices put where their body took them instead of
      // projecting anew: the mesh depends only on where the surface
      // vertices are, and none changes sides.
      std::vector<Point<dim>> positions = undeformed;
      const auto place_surface_vertices = [&](const unsigned int level) {
        std::vector<Point<dim>> moved = positions;
        for (const unsigned int v : hierarchy.vertices_on_level(level))
          if (on_surface[v])
            moved[v]
              = positions[v]
                + hierarchy.admissible_displacement(v,
                                                    target[v] - positions[v]);
        const unsigned int held
          = hierarchy.back_off(level, positions, moved, settings.min_quality);
        positions.swap(moved);
        return held;
      };
      for (unsigned int level = 0; level < hierarchy.n_levels(); ++level)
        {
          place_surface_vertices(level);
          smooth_level(hierarchy,
                       level,
                       distance,
                       settings,
                       on_surface,
                       positions,
                       report);
          // those held back get a second try once smoothing made room
          report.held_back_vertices += place_surface_vertices(level);
          if (level + 1 < hierarchy.n_levels())
            hierarchy.prolongate(level, positions);
        }
      // a surface vertex that could not follow is one no longer
      for (unsigned int v = 0; v < positions.size(); ++v)
        if (on_surface[v]
            && std::abs(distance.signed_distance(positions[v]))
                 > on_surface_tolerance)
          on_surface[v] = false;
      report.projected_vertices
        = std::count(on_surface.begin(), on_surface.end(), true);
      VertexHierarchy<dim>::write_positions(tria, positions);
      report.quality = compute_mesh_quality(tria);
      return report;
    }

    template unsigned int
    smoothing_sweep<2>(const VertexHierarchy<2> &,
                       const unsigned int,
                       const std::vector<double> &,
                       const std::vector<bool> &,
                       const SmoothingSettings &,
                       std::vector<Point<2>> &);
    template unsigned int
    smoothing_sweep<3>(const VertexHierarchy<3> &,
                       const unsigned int,
                       const std::vector<double> &,
                       const std::vector<bool> &,
                       const SmoothingSettings &,
                       std::vector<Point<3>> &);
    template class LaplaceKappa<2>;
    template class LaplaceKappa<3>;
    template class LaplaceAlpha<2>;
    template class LaplaceAlpha<3>;
  } // namespace deformation
} // namespace particulate
