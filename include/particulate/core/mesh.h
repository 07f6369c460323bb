#ifndef particulate_core_mesh_h
#define particulate_core_mesh_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/grid/manifold.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace particulate {
  namespace core {
    /** subsection `Mesh`: the coarse mesh and its refinement. */
    struct MeshParameters
    {
      enum class Type
      {
        hyper_rectangle,
        ball,
        column,
        graded_rectangle,
        channel_with_cylinder,
        file
      };
      Type                      type = Type::hyper_rectangle;
      std::string               file_name;
      unsigned int              refinements = 2;
      std::vector<double>       lower_corner{0., 0., 0.};
      std::vector<double>       upper_corner{1., 1., 1.};
      std::vector<unsigned int> subdivisions{1, 1, 1};
      /// graded rectangle: the fine region, its cell size and the growth
      /// ratio of the cells outside it
      std::vector<double> fine_lower{0., 0., 0.};
      std::vector<double> fine_upper{1., 1., 1.};
      double              fine_cell_size       = 0.1; ///< [m], coarse level
      double              grading_ratio        = 1.2;
      double              cylinder_shell_width = 0.03;
      unsigned int        cylinder_shells      = 2;
      double cylinder_center_x = 0.2;  ///< [m], DFG 2D: 0.2, 3D-1Z: 0.5
      double channel_length    = 2.2;  ///< [m], DFG 2D: 2.2, 3D-1Z: 2.5
      double channel_depth     = 0.41; ///< [m], z extent of a 3D channel
      /// directory of the `.prm` file: relative mesh paths start there
      std::string base_directory = ".";

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);
    };

    /**
     * The whole mesh on this rank: the coarse mesh (generated or read) and
     * its global refinements, every level kept. create_mesh() partitions
     * it; mesh deformation moves the vertices of this hierarchy and copies
     * them into the distributed mesh.
     */
    template <int dim>
    void
    create_serial_mesh(const MeshParameters       &parameters,
                       dealii::Triangulation<dim> &serial);

    /**
     * Build the distributed mesh: every rank creates the coarse mesh
     * (generated, or read from a Gmsh `.msh`, UCD `.inp`/`.ucd` or Abaqus
     * `.inp` file), refines it globally, and takes its part of a partition
     * into a parallel::fullydistributed::Triangulation (no p4est). Curved
     * boundaries keep their manifold so that a higher-order mapping sees them.
     *
     * @throws std::runtime_error naming the file path tried when a mesh file
     *   is missing or cannot be read.
     */
    template <int dim>
    void
    create_mesh(const MeshParameters &parameters,
                dealii::parallel::fullydistributed::Triangulation<dim> &tria);

    /**
     * Cell sizes of a graded 1D subdivision of [@p lower, @p upper]: cells
     * of about @p h inside [@p fine_lower, @p fine_upper] (sized to fit it
     * exactly), growing by the factor @p ratio per cell outside it, the
     * growing cells on each side scaled to end exactly at the boundary.
     */
    std::vector<double>
    graded_cell_sizes(const double lower,
                      const double upper,
                      const double fine_lower,
                      const double fine_upper,
                      const double h,
                      const double ratio);

    /**
     * The curved wall of a channel with cylinder: the cylinder's axis through
     * (@p x, @p y), along z in 3D (manifold id 0 of the generated mesh).
     */
    template <int dim>
    std::unique_ptr<dealii::Manifold<dim>>
    cylinder_axis_manifold(const double x, const double y);

    /** All boundary ids present on the (global) mesh. */
    template <int dim>
    std::vector<unsigned int>
    global_boundary_ids(
      const dealii::parallel::fullydistributed::Triangulation<dim> &tria);

    /** Lower and upper corner of the whole mesh: the extremes of the
     *  vertices of the locally owned cells, over all ranks of @p comm. */
    template <int dim>
    std::pair<dealii::Point<dim>, dealii::Point<dim>>
    global_bounding_box(const dealii::Triangulation<dim> &tria, MPI_Comm comm);

    /** The shortest cell edge of the whole mesh (its locally owned cells'
     *  smallest vertex distance, over all ranks of @p comm). */
    template <int dim>
    double
    smallest_cell_edge(const dealii::Triangulation<dim> &tria, MPI_Comm comm);
  } // namespace core
} // namespace particulate

#endif
