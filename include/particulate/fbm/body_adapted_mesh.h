#ifndef particulate_fbm_body_adapted_mesh_h
#define particulate_fbm_body_adapted_mesh_h

#include <particulate/deformation/moving_mesh.h>
#include <particulate/fbm/particle_parameters.h>
#include <particulate/fluid/navier_stokes.h>
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
       * from @p mesh. Nothing moves yet.
       */
      BodyAdaptedMesh(const core::MeshParameters               &mesh,
                      const deformation::DeformationParameters &parameters,
                      const ParticleParameters                 &particles,
                      dealii::Triangulation<dim>               &tria);

      /**
       * Before the flow solver is set up: adapt to particles centred at
       * @p centres and move @p tria there.
       */
      deformation::DeformationReport
      adapt(const std::vector<Eigen::Vector3d> &centres);

      /**
       * During the run: follow the particles to their new @p centres
       * (deformation::MovingMesh::follow(); carried vertices move
       * with the nearest particle's translation: the shapes are spheres
       * and disks, which look the same however they turn) and move
       * @p flow's mesh there over the coming step @p time_step (ALE), or,
       * when a carried mesh was adapted afresh, carry the flow over to the
       * new mesh (fluid::NavierStokes::transfer_to_moved_mesh()).
       */
      deformation::DeformationReport
      follow(const std::vector<Eigen::Vector3d> &centres,
             fluid::NavierStokes<dim>           &flow,
             const double                        time_step);

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
      /** The particles at @p centres as distance fields. */
      deformation::ShapeDistanceField<dim>
      distance_field(const std::vector<Eigen::Vector3d> &centres) const;

      deformation::MovingMesh<dim>           moving_mesh;
      dealii::Triangulation<dim>            &tria;
      std::unique_ptr<const geometry::Shape> shape;
      /// where the mesh last saw the particles
      std::vector<Eigen::Vector3d> centres;
    };
  } // namespace fbm
} // namespace particulate

#endif
