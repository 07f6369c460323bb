#include <particulate/core/checkpoint.h>
#include <particulate/core/mesh.h>
#include <particulate/deformation/distance_field.h>
#include <particulate/fbm/body_adapted_mesh.h>
#include <particulate/fbm/particle_shape.h>
#include <particulate/geometry/cylinder.h>

#include <limits>

namespace particulate {
  namespace fbm {
    namespace {
      /**
       * The shape the mesh adapts to: the body's own, except for a cylinder
       * along z that reaches through the domain, which shows the mesh its
       * lateral surface alone. That is every 2D disk (the nodes lie in its
       * mid-plane) and a 3D cylinder at least as long as the domain along
       * z, as in the oscillating-cylinder slab: its caps lie on the end
       * walls or outside. With the caps in the distance field, a vertex of
       * an end wall inside the disk lies on the body's surface (a cap)
       * already and is never projected onto the lateral one: in a short
       * piece of the slab 12 vertices of each end wall came to lie on the
       * lateral surface against 18 of the middle layer, 16 on every layer
       * without the caps (tests/fbm/cylinder_adapted_mesh.cc).
       */
      template <int dim>
      std::shared_ptr<const geometry::Shape>
      shape_seen_by_mesh(std::shared_ptr<const geometry::Shape> shape,
                         const dealii::Triangulation<dim>      &tria)
      {
        if (shape->kind() != geometry::ShapeKind::cylinder)
          return shape;
        const auto  &cylinder = static_cast<const geometry::Cylinder &>(*shape);
        const double radius   = cylinder.radius();
        if (dim == 2)
          return std::make_shared<geometry::Cylinder>(radius, 1e3 * radius);
        const auto [lower, upper]
          = core::global_bounding_box(tria, tria.get_communicator());
        const double span = upper[dim - 1] - lower[dim - 1];
        if (2. * cylinder.half_height() < span * (1. - 1e-9))
          return shape;
        return std::make_shared<geometry::Cylinder>(radius,
                                                    1e3 * (span + radius));
      }
    } // namespace



    template <int dim>
    BodyAdaptedMesh<dim>::BodyAdaptedMesh(
      const core::MeshParameters                                &mesh,
      const deformation::DeformationParameters                  &parameters,
      const std::vector<std::shared_ptr<const geometry::Shape>> &body_shapes,
      dealii::Triangulation<dim>                                &tria)
      : moving_mesh(mesh, parameters)
      , tria(tria)
    {
      for (const auto &shape : body_shapes)
        {
          shapes.push_back(shape_seen_by_mesh(shape, tria));
          rotation_invariant.push_back(is_rotation_invariant(*shape, dim));
        }
    }



    template <int dim>
    deformation::ShapeDistanceField<dim>
    BodyAdaptedMesh<dim>::distance_field(
      const std::vector<geometry::Pose> &at) const
    {
      AssertDimension(at.size(), shapes.size());
      std::vector<geometry::PlacedShape> bodies;
      for (unsigned int b = 0; b < shapes.size(); ++b)
        bodies.push_back({shapes[b].get(), at[b]});
      return deformation::ShapeDistanceField<dim>(std::move(bodies));
    }



    template <int dim>
    deformation::DeformationReport
    BodyAdaptedMesh<dim>::adapt(const std::vector<geometry::Pose> &now)
    {
      const auto report = moving_mesh.adapt(distance_field(now));
      poses             = now;
      moving_mesh.copy_vertices_to(tria);
      return report;
    }



    template <int dim>
    dealii::Tensor<1, dim>
    BodyAdaptedMesh<dim>::carried_displacement(
      const dealii::Point<dim>          &x,
      const std::vector<geometry::Pose> &now) const
    {
      unsigned int nearest  = 0;
      double       smallest = std::numeric_limits<double>::max();
      for (unsigned int b = 0; b < poses.size(); ++b)
        {
          double r2 = 0.;
          for (unsigned int d = 0; d < dim; ++d)
            r2 += (x[d] - poses[b].translation()[d])
                  * (x[d] - poses[b].translation()[d]);
          if (r2 < smallest)
            {
              smallest = r2;
              nearest  = b;
            }
        }
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = x[d];
      const Eigen::Vector3d move
        = rotation_invariant[nearest] ?
            Eigen::Vector3d(now[nearest].translation()
                            - poses[nearest].translation()) :
            Eigen::Vector3d(now[nearest].to_world(poses[nearest].to_body(p))
                            - p);
      dealii::Tensor<1, dim> shift;
      for (unsigned int d = 0; d < dim; ++d)
        shift[d] = move[d];
      return shift;
    }



    template <int dim>
    deformation::DeformationReport
    BodyAdaptedMesh<dim>::follow(const std::vector<geometry::Pose> &now,
                                 fluid::NavierStokes<dim>          &flow,
                                 const double                       time_step)
    {
      AssertDimension(now.size(), poses.size());
      const auto before = distance_field(poses);
      const auto report = moving_mesh.follow(
        distance_field(now),
        [&](const dealii::Point<dim> &x) {
          return carried_displacement(x, now);
        },
        &before);
      poses                    = now;
      const auto move_vertices = [&]() { moving_mesh.copy_vertices_to(tria); };
      // A mesh carried with the bodies moves little per step, and the ALE
      // term accounts for it; a fresh adaptation among carried meshes is a
      // jump that would show as a spike of the mesh velocity: interpolate.
      // A fresh start where the step starts is followed by the step's
      // carry, with its mesh velocity.
      const auto &fresh_start = moving_mesh.fresh_start_vertices();
      if (moving_mesh.carries_mesh() && report.readapted)
        {
          if (fresh_start.empty())
            flow.transfer_to_moved_mesh(move_vertices);
          else
            {
              flow.transfer_to_moved_mesh(
                [&]() { moving_mesh.copy_vertices_to(tria, fresh_start); });
              flow.move_mesh(move_vertices, time_step);
            }
        }
      else
        flow.move_mesh(move_vertices, time_step);
      return report;
    }



    template <int dim>
    void
    BodyAdaptedMesh<dim>::save(std::ostream &out) const
    {
      moving_mesh.save(out);
      std::vector<double> placement;
      for (const auto &pose : poses)
        {
          const Eigen::Matrix3d &R = pose.rotation();
          placement.insert(placement.end(), R.data(), R.data() + 9);
          placement.insert(placement.end(),
                           pose.translation().data(),
                           pose.translation().data() + 3);
        }
      core::write_binary_vector(out, placement);
    }



    template <int dim>
    void
    BodyAdaptedMesh<dim>::load(std::istream &in)
    {
      moving_mesh.load(in);
      const auto placement = core::read_binary_vector<double>(in);
      AssertThrow(placement.size() == 12 * shapes.size(),
                  dealii::ExcMessage(
                    "The checkpoint's adapted mesh holds "
                    + std::to_string(placement.size() / 12)
                    + " bodies, the case " + std::to_string(shapes.size())
                    + ": restart with the case file that wrote it."));
      poses.clear();
      for (unsigned int b = 0; b < shapes.size(); ++b)
        poses.emplace_back(Eigen::Matrix3d(Eigen::Map<const Eigen::Matrix3d>(
                             &placement[12 * b])),
                           Eigen::Vector3d(Eigen::Map<const Eigen::Vector3d>(
                             &placement[12 * b + 9])));
      moving_mesh.copy_vertices_to(tria);
    }

    template class BodyAdaptedMesh<2>;
    template class BodyAdaptedMesh<3>;
  } // namespace fbm
} // namespace particulate
