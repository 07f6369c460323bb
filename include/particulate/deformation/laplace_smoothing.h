#ifndef particulate_deformation_laplace_smoothing_h
#define particulate_deformation_laplace_smoothing_h

#include <particulate/deformation/mesh_deformation.h>
#include <particulate/deformation/vertex_hierarchy.h>

#include <deal.II/base/point.h>

#include <functional>
#include <vector>

namespace particulate {
  namespace deformation {
    /** Settings shared by the two smoothing-based methods (§5.7). */
    struct SmoothingSettings
    {
      double                    width = 0.1; ///< [m] reach of the hat weight
      double                    peak_weight = 8.;  ///< weight at the surface
      double                    relaxation  = 0.5; ///< omega of eq. 5.27
      std::vector<unsigned int> sweeps_per_level{4};
      double                    min_quality = 0.2;

      /** Sweeps on @p level (the last entry repeats). */
      unsigned int
      sweeps(const unsigned int level) const
      {
        return sweeps_per_level.empty() ?
                 0 :
                 sweeps_per_level
                   [std::min<std::size_t>(level, sweeps_per_level.size() - 1)];
      }
    };

    /**
     * The weight of a vertex at signed distance @p d from the nearest
     * surface (figure 5.5): a hat, @p peak at the surface, falling linearly
     * to 1 at distance @p width and 1 beyond.
     */
    inline double
    hat_weight(const double d, const double width, const double peak)
    {
      const double x = 1. - std::abs(d) / width;
      return 1. + (peak - 1.) * (x > 0. ? x : 0.);
    }

    /**
     * One Jacobi sweep of weighted Laplacian smoothing (eq. 5.27) over the
     * vertices of @p level: each free vertex moves to
     * (1 - omega) x + omega sum_j w_j x_j / sum_j w_j over its neighbours,
     * boundary vertices only along their boundary, @p pinned ones not at
     * all; then VertexHierarchy::back_off() keeps every cell valid.
     * @return the number of vertices held back
     */
    template <int dim>
    unsigned int
    smoothing_sweep(const VertexHierarchy<dim>      &hierarchy,
                    const unsigned int               level,
                    const std::vector<double>       &weight,
                    const std::vector<bool>         &pinned,
                    const SmoothingSettings         &settings,
                    std::vector<dealii::Point<dim>> &positions);

    /**
     * Laplace-kappa (thesis §5.7, Algorithm 12): on each level from the
     * coarsest up, a few sweeps of smoothing weighted by the hat of the
     * distance to the bodies pull vertices towards the surfaces; the
     * vertices the next refinement created then follow by interpolation.
     */
    template <int dim>
    class LaplaceKappa : public MeshDeformation<dim>
    {
    public:
      explicit LaplaceKappa(const SmoothingSettings &settings);

      DeformationReport
      deform(dealii::Triangulation<dim> &tria,
             const DistanceField<dim>   &distance) const override;

      std::string
      name() const override
      {
        return "Laplace-kappa";
      }

    private:
      SmoothingSettings settings;
    };

    /**
     * Laplace-alpha (thesis §5.7, figure 5.6): on every level, coarsest
     * first, the vertices that lie within `projection_range` times their
     * shortest edge of a surface are put onto it, and so are the midpoints
     * of edges that run along the surface between two such vertices (not
     * chords across the body); between levels a few weighted sweeps smooth
     * the rest, the projected vertices held in place. Faces then follow the
     * surface instead of cutting it, also around bodies smaller than the
     * coarse cells.
     */
    template <int dim>
    class LaplaceAlpha : public MeshDeformation<dim>
    {
    public:
      LaplaceAlpha(const SmoothingSettings &settings,
                   const double             projection_range);

      DeformationReport
      deform(dealii::Triangulation<dim> &tria,
             const DistanceField<dim>   &distance) const override;

      /** deform(), also telling which vertices it put onto a surface
       *  (@p on_surface, one flag per vertex of @p tria). */
      DeformationReport
      deform(dealii::Triangulation<dim> &tria,
             const DistanceField<dim>   &distance,
             std::vector<bool>          &on_surface) const;

      /**
       * Follow moving bodies keeping the vertices on their surfaces (thesis
       * §5.7: the surface vertices move with their body, so no vertex
       * changes sides). The vertices in @p on_surface move by
       * @p body_displacement (the displacement over the step of the body
       * nearest to a point) and back onto the surfaces that @p distance
       * describes at their new places; the rest of the mesh comes from the
       * level-by-level pass of deform() started at @p undeformed, with these
       * vertices placed instead of projected anew, so the mesh depends only
       * on where the surface vertices are. A surface vertex that a cell's
       * quality holds back off the surface is released from @p on_surface
       * (the caller then adapts afresh).
       */
      DeformationReport
      carry(
        dealii::Triangulation<dim>            &tria,
        const std::vector<dealii::Point<dim>> &undeformed,
        const DistanceField<dim>              &distance,
        const std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &)>
                          &body_displacement,
        std::vector<bool> &on_surface) const;

      std::string
      name() const override
      {
        return "Laplace-alpha";
      }

    private:
      SmoothingSettings settings;
      double            projection_range;
    };
  } // namespace deformation
} // namespace particulate

#endif
