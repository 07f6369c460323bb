#include <particulate/deformation/distance_field.h>
#include <particulate/fbm/body_adapted_mesh.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/sphere.h>

namespace particulate {
  namespace fbm {
    template <int dim>
    BodyAdaptedMesh<dim>::BodyAdaptedMesh(
      const core::MeshParameters               &mesh,
      const deformation::DeformationParameters &parameters,
      const ParticleParameters                 &particles,
      dealii::Triangulation<dim>               &tria)
      : moving_mesh(mesh, parameters)
      , tria(tria)
    {
      if (particles.shape == ParticleParameters::Shape::disk)
        // a 2D point (x, y) is the point (x, y, 0) of the 3D shapes: the
        // disk is a cylinder along z whose caps are far from that plane
        shape = std::make_unique<geometry::Cylinder>(particles.radius,
                                                     1e3 * particles.radius);
      else
        shape = std::make_unique<geometry::Sphere>(particles.radius);
    }



    template <int dim>
    deformation::DeformationReport
    BodyAdaptedMesh<dim>::adapt_hierarchy(
      const std::vector<Eigen::Vector3d> &centres)
    {
      std::vector<geometry::PlacedShape> bodies;
      for (const auto &c : centres)
        bodies.push_back(
          {shape.get(), geometry::Pose(Eigen::Matrix3d::Identity(), c)});
      return moving_mesh.adapt(
        deformation::ShapeDistanceField<dim>(std::move(bodies)));
    }



    template <int dim>
    deformation::DeformationReport
    BodyAdaptedMesh<dim>::adapt(const std::vector<Eigen::Vector3d> &centres)
    {
      const auto report = adapt_hierarchy(centres);
      moving_mesh.copy_vertices_to(tria);
      return report;
    }



    template <int dim>
    deformation::DeformationReport
    BodyAdaptedMesh<dim>::follow(const std::vector<Eigen::Vector3d> &centres,
                                 fluid::NavierStokes<dim>           &flow,
                                 const double                        time_step)
    {
      const auto report = adapt_hierarchy(centres);
      flow.move_mesh([&]() { moving_mesh.copy_vertices_to(tria); }, time_step);
      return report;
    }



    template <int dim>
    void
    BodyAdaptedMesh<dim>::load(std::istream &in)
    {
      moving_mesh.load(in);
      moving_mesh.copy_vertices_to(tria);
    }

    template class BodyAdaptedMesh<2>;
    template class BodyAdaptedMesh<3>;
  } // namespace fbm
} // namespace particulate
