#ifndef particulate_geometry_dealii_mesh_point_classifier_h
#define particulate_geometry_dealii_mesh_point_classifier_h

#include <particulate/geometry/point_containment.h>
#include <particulate/geometry/point_hash_grid.h>

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace particulate {
  namespace geometry {

    /**
     * Point classification on the locally owned part of a deal.II mesh (thesis
     * §5.4.2; the adapter between the FE code and PointHashGrid): the points of
     * this rank -- the vertices of its locally owned cells, or the support
     * points of its locally owned degrees of freedom (e.g. the Q2 velocity
     * nodes) -- go into a hash grid once, and each classification then tests
     * only the points inside each body's bounding box.
     *
     * Works with serial triangulations (all cells are locally owned) and with
     * distributed ones (parallel::distributed or fullydistributed). After the
     * mesh moves or is refined, construct a new classifier.
     */
    class MeshPointClassifier
    {
    public:
      /**
       * The vertices of the locally owned cells, each once. Vertices on the
       * boundary between two ranks' cells belong to both ranks.
       * @param tria the mesh
       * @param cell_size hash-grid cell edge [m]; 0 chooses one from the points
       */
      explicit MeshPointClassifier(const dealii::Triangulation<3> &tria,
                                   const double cell_size = 0.);

      /**
       * The support points of the locally owned degrees of freedom of one
       * vector component (each point once, owned by exactly one rank).
       * @param mapping the mapping of the FE space
       * @param dof_handler a DoFHandler whose element has support points
       * @param component the component whose nodes are wanted (e.g. 0, the
       *   first velocity component, for the velocity nodes)
       * @param cell_size hash-grid cell edge [m]; 0 chooses one from the points
       */
      MeshPointClassifier(const dealii::Mapping<3>    &mapping,
                          const dealii::DoFHandler<3> &dof_handler,
                          const unsigned int           component = 0,
                          const double                 cell_size = 0.);

      /**
       * Per point, the index of the first body containing it, or -1 (same
       * order as points() and point_ids()).
       * @param bodies the placed shapes
       * @param distances if not null, the smallest signed distance per point
       *   to the bodies whose box holds it [m] (+infinity elsewhere)
       * @param statistics if not null, the work counters
       */
      std::vector<int>
      classify(const std::vector<PlacedShape> &bodies,
               std::vector<double>            *distances  = nullptr,
               ContainmentStatistics          *statistics = nullptr) const;

      /** The points of this rank [m]. */
      const std::vector<Eigen::Vector3d> &
      points() const
      {
        return grid.points();
      }

      /** For each point its deal.II index: the vertex index (first
       *  constructor) or the global DoF index (second constructor). */
      const std::vector<dealii::types::global_dof_index> &
      point_ids() const
      {
        return ids;
      }

      /** The hash grid over the points. */
      const PointHashGrid &
      hash_grid() const
      {
        return grid;
      }

    private:
      std::vector<dealii::types::global_dof_index> ids;
      PointHashGrid                                grid;
    };

  } // namespace geometry
} // namespace particulate

#endif
