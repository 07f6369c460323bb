#ifndef particulate_deformation_mesh_quality_h
#define particulate_deformation_mesh_quality_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <functional>
#include <vector>

namespace particulate {
  namespace deformation {
    /**
     * Scaled Jacobian of a quadrilateral or hexahedron given by its
     * vertices in deal.II's lexicographic order: at each corner the
     * determinant of the dim edges leaving it, each edge divided by its
     * length; the cell's value is the smallest corner's. 1 for a rectangle
     * or a brick, 0 for a degenerate corner, negative for an inverted one.
     */
    template <int dim>
    double
    scaled_jacobian(
      const std::array<dealii::Point<dim>,
                       dealii::GeometryInfo<dim>::vertices_per_cell> &vertices);

    /** Longest over shortest edge of the cell given by its vertices. */
    template <int dim>
    double
    aspect_ratio(
      const std::array<dealii::Point<dim>,
                       dealii::GeometryInfo<dim>::vertices_per_cell> &vertices);

    /** The quality of a mesh (or of one level of its hierarchy). */
    struct MeshQuality
    {
      double       min_scaled_jacobian  = 1.;
      double       mean_scaled_jacobian = 1.;
      double       max_aspect_ratio     = 1.;
      unsigned int n_inverted_cells     = 0; ///< scaled Jacobian <= 0
      unsigned int n_cells              = 0;
    };

    /**
     * Quality of the locally owned active cells of @p tria (all active
     * cells of a serial mesh), reduced over the mesh's communicator, or of
     * the cells of @p level when it is given (serial meshes only).
     */
    template <int dim>
    MeshQuality
    compute_mesh_quality(const dealii::Triangulation<dim> &tria,
                         const int                         level = -1);

    /** Equidistribution of a mesh against a target cell-size function. */
    struct EquidistributionError
    {
      double l2  = 0.; ///< volume-weighted root mean square of e_K
      double max = 0.; ///< largest |e_K|
    };

    /**
     * How far the active cells K of a serial mesh are from having the sizes
     * that the monitor f asks for (thesis eq. 5.19: the deformed cell sizes
     * are proportional to f): e_K = |K| / (c f(x_K)) - 1 with x_K the
     * cell's vertex mean and c = |Omega| / sum_K f(x_K), so that the sizes
     * sum to the domain. A perfectly equidistributed mesh has e_K = 0.
     */
    template <int dim>
    EquidistributionError
    equidistribution_error(
      const dealii::Triangulation<dim>                        &tria,
      const std::function<double(const dealii::Point<dim> &)> &monitor);
  } // namespace deformation
} // namespace particulate

#endif
