#include <particulate/core/checkpoint.h>
#include <particulate/core/mesh.h>
#include <particulate/deformation/distance_field.h>
#include <particulate/fbm/body_adapted_mesh.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/sphere.h>

#include <limits>

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
      else if (particles.shape == ParticleParameters::Shape::cylinder)
        {
          // A cylinder at least as long as the domain along its axis (z)
          // reaches through it, as in the 3D oscillating-cylinder slab: its
          // caps lie on the end walls or outside, and the mesh must see only
          // its lateral surface. With the caps in the distance field, a
          // vertex of an end wall inside the disk lies on the body's surface
          // (a cap) already and is never projected onto the lateral one: in
          // a short piece of the slab 12 vertices of each end wall came to
          // lie on the lateral surface against 18 of the middle layer, 16 on
          // every layer without the caps
          // (tests/fbm/cylinder_adapted_mesh.cc).
          const auto [lower, upper]
            = core::global_bounding_box(tria, tria.get_communicator());
          const double span            = upper[dim - 1] - lower[dim - 1];
          const bool   reaches_through = particles.length >= span * (1. - 1e-9);
          shape                        = std::make_unique<geometry::Cylinder>(
            particles.radius,
            reaches_through ? 1e3 * (span + particles.radius) :
                                                     0.5 * particles.length);
        }
      else
        shape = std::make_unique<geometry::Sphere>(particles.radius);
    }



    template <int dim>
    deformation::ShapeDistanceField<dim>
    BodyAdaptedMesh<dim>::distance_field(
      const std::vector<Eigen::Vector3d> &centres) const
    {
      std::vector<geometry::PlacedShape> bodies;
      for (const auto &c : centres)
        bodies.push_back(
          {shape.get(), geometry::Pose(Eigen::Matrix3d::Identity(), c)});
      return deformation::ShapeDistanceField<dim>(std::move(bodies));
    }



    template <int dim>
    deformation::DeformationReport
    BodyAdaptedMesh<dim>::adapt(const std::vector<Eigen::Vector3d> &centres_)
    {
      const auto report = moving_mesh.adapt(distance_field(centres_));
      centres           = centres_;
      moving_mesh.copy_vertices_to(tria);
      return report;
    }



    template <int dim>
    deformation::DeformationReport
    BodyAdaptedMesh<dim>::follow(const std::vector<Eigen::Vector3d> &now,
                                 fluid::NavierStokes<dim>           &flow,
                                 const double                        time_step)
    {
      AssertDimension(now.size(), centres.size());
      // a point moves with the particle whose centre was nearest
      const auto displacement = [&](const dealii::Point<dim> &x) {
        unsigned int nearest  = 0;
        double       smallest = std::numeric_limits<double>::max();
        for (unsigned int b = 0; b < centres.size(); ++b)
          {
            double r2 = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              r2 += (x[d] - centres[b][d]) * (x[d] - centres[b][d]);
            if (r2 < smallest)
              {
                smallest = r2;
                nearest  = b;
              }
          }
        dealii::Tensor<1, dim> shift;
        for (unsigned int d = 0; d < dim; ++d)
          shift[d] = now[nearest][d] - centres[nearest][d];
        return shift;
      };
      const auto report = moving_mesh.follow(distance_field(now), displacement);
      centres           = now;
      const auto move_vertices = [&]() { moving_mesh.copy_vertices_to(tria); };
      // A mesh carried with the bodies moves little per step, and the ALE
      // term accounts for it; a fresh adaptation among carried meshes is a
      // jump that would show as a spike of the mesh velocity: interpolate.
      if (moving_mesh.carries_mesh() && report.readapted)
        flow.transfer_to_moved_mesh(move_vertices);
      else
        flow.move_mesh(move_vertices, time_step);
      return report;
    }



    template <int dim>
    void
    BodyAdaptedMesh<dim>::save(std::ostream &out) const
    {
      moving_mesh.save(out);
      std::vector<double> xyz;
      for (const auto &c : centres)
        xyz.insert(xyz.end(), c.data(), c.data() + 3);
      core::write_binary_vector(out, xyz);
    }



    template <int dim>
    void
    BodyAdaptedMesh<dim>::load(std::istream &in)
    {
      moving_mesh.load(in);
      const auto xyz = core::read_binary_vector<double>(in);
      centres.resize(xyz.size() / 3);
      for (unsigned int b = 0; b < centres.size(); ++b)
        centres[b]
          = Eigen::Vector3d(xyz[3 * b], xyz[3 * b + 1], xyz[3 * b + 2]);
      moving_mesh.copy_vertices_to(tria);
    }

    template class BodyAdaptedMesh<2>;
    template class BodyAdaptedMesh<3>;
  } // namespace fbm
} // namespace particulate
