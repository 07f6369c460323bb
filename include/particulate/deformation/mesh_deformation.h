#ifndef particulate_deformation_mesh_deformation_h
#define particulate_deformation_mesh_deformation_h

#include <particulate/deformation/deformation_parameters.h>
#include <particulate/deformation/distance_field.h>
#include <particulate/deformation/mesh_quality.h>

#include <deal.II/grid/tria.h>

#include <memory>
#include <string>

namespace particulate {
  namespace deformation {
    /** What one deformation did, for the log and the tests. */
    struct DeformationReport
    {
      /// adaptation steps (robust method) or smoothing sweeps (all levels)
      unsigned int steps = 0;
      /// vertices whose move was cut back to keep every cell valid
      unsigned int held_back_vertices = 0;
      /// Laplace-alpha: vertices placed on a body surface
      unsigned int projected_vertices = 0;
      /// PDE methods: point locations that needed the brute-force search
      unsigned int location_fallbacks = 0;
      /// MovingMesh::follow(): the mesh was adapted afresh from the
      /// undeformed one (always, unless surface vertices are carried)
      bool readapted = false;
      /// MovingMesh::follow(): the largest distance a vertex moved [m]
      double max_vertex_move = 0.;
      /// quality of the active cells afterwards
      MeshQuality quality;
    };

    /**
     * r-adaptivity: move the vertices of a mesh, keeping its connectivity,
     * so that it resolves the bodies better (thesis §5.5-5.7). One interface,
     * three implementations chosen by `Mesh deformation / Method` (the
     * ExaDG mesh-motion pattern).
     *
     * The mesh is a serial triangulation holding its whole refinement
     * hierarchy; in a parallel run every rank deforms the same copy, so
     * the result needs no communication. A method never leaves an
     * inverted cell behind: it holds vertices back, or throws
     * DeformationError, and says which.
     */
    template <int dim>
    class MeshDeformation
    {
    public:
      virtual ~MeshDeformation() = default;

      /**
       * Move the vertices of @p tria from where they are now to resolve the
       * surfaces that @p distance describes.
       */
      virtual DeformationReport
      deform(dealii::Triangulation<dim> &tria,
             const DistanceField<dim>   &distance) const = 0;

      /** The method's name for the log. */
      virtual std::string
      name() const = 0;
    };

    /** The method that @p parameters select (nullptr for `none`). */
    template <int dim>
    std::unique_ptr<MeshDeformation<dim>>
    create_mesh_deformation(const DeformationParameters &parameters);

    /** Thrown when a method cannot deform the mesh without inverting it. */
    class DeformationError : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };
  } // namespace deformation
} // namespace particulate

#endif
