#ifndef particulate_fbm_body_adapted_mesh_h
#define particulate_fbm_body_adapted_mesh_h

#include <particulate/deformation/moving_mesh.h>
#include <particulate/fluid/navier_stokes.h>
#include <particulate/geometry/pose.h>
#include <particulate/geometry/shape.h>

#include <Eigen/Core>

#include <iosfwd>
#include <memory>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * The flow mesh of a fictitious-boundary run adapted to where the
     * particles are (thesis §5.7, §6.3-6.4): the particles as distance
     * fields for deformation::MovingMesh, whose vertex positions go into
     * the flow solver's distributed mesh, and when they move, the ALE mesh
     * velocity into its convection term.
     */
    template <int dim>
    class BodyAdaptedMesh
    {
    public:
      /**
       * @p tria must be the distributed mesh that core::create_mesh() made
       * from @p mesh; @p shapes are the bodies' shapes, one per body (the
       * objects their rigid bodies hold). Nothing moves yet.
       */
      BodyAdaptedMesh(
        const core::MeshParameters                                &mesh,
        const deformation::DeformationParameters                  &parameters,
        const std::vector<std::shared_ptr<const geometry::Shape>> &shapes,
        dealii::Triangulation<dim>                                &tria);

      /**
       * Before the flow solver is set up: adapt to the bodies placed at
       * @p poses and move @p tria there.
       */
      deformation::DeformationReport
      adapt(const std::vector<geometry::Pose> &poses);

      /**
       * During the run: follow the bodies to their new @p poses
       * (deformation::MovingMesh::follow(); a carried vertex moves with the
       * body whose centre was nearest, rigidly, or by its translation alone
       * for a body that looks the same however it turns) and move
       * @p flow's mesh there over the coming step @p time_step (ALE), or,
       * when a carried mesh was adapted afresh, carry the flow over to the
       * new mesh (fluid::NavierStokes::transfer_to_moved_mesh()).
       */
      deformation::DeformationReport
      follow(const std::vector<geometry::Pose> &poses,
             fluid::NavierStokes<dim>          &flow,
             const double                       time_step);

      /** Put the positions of save() into the distributed mesh (restart,
       *  before the flow solver is set up). */
      void
      load(std::istream &in);
      void
      save(std::ostream &out) const;

      const deformation::MovingMesh<dim> &
      mesh() const
      {
        return moving_mesh;
      }

    private:
      /** The bodies at @p poses as distance fields. */
      deformation::ShapeDistanceField<dim>
      distance_field(const std::vector<geometry::Pose> &poses) const;

      /** Where a vertex at @p x moves when the body nearest to it moves
       *  from poses to @p now. */
      dealii::Tensor<1, dim>
      carried_displacement(const dealii::Point<dim>          &x,
                           const std::vector<geometry::Pose> &now) const;

      deformation::MovingMesh<dim> moving_mesh;
      dealii::Triangulation<dim>  &tria;
      /// the shapes as the mesh sees them, one per body
      std::vector<std::shared_ptr<const geometry::Shape>> shapes;
      /// whether each body looks the same however it turns
      std::vector<bool> rotation_invariant;
      /// where the mesh last saw the bodies
      std::vector<geometry::Pose> poses;
    };
  } // namespace fbm
} // namespace particulate

#endif
