#include <particulate/core/parameter_text.h>
#include <particulate/fbm/domain_box.h>
#include <particulate/fbm/particle_parameters.h>
#include <particulate/geometry/pose.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace particulate {
  namespace fbm {
    namespace {
      /** The column's box from the mesh's corners (the refined mesh's
       *  vertices need not reach the circle's extreme points). */
      void
      set_column(DomainBox &domain, const core::MeshParameters &mesh)
      {
        const double radius
          = 0.5
            * std::min(mesh.upper_corner[0] - mesh.lower_corner[0],
                       mesh.upper_corner[1] - mesh.lower_corner[1]);
        for (unsigned int d = 0; d < 2; ++d)
          {
            const double centre
              = 0.5 * (mesh.lower_corner[d] + mesh.upper_corner[d]);
            domain.lower[d] = centre - radius;
            domain.upper[d] = centre + radius;
          }
        domain.column_radius = radius;
      }



      /** A column's side is one surface: its four faces agree, and none
       *  is a mirror plane. */
      void
      check_column_faces(const DomainBox &domain)
      {
        const auto &w = domain.walls;
        if (!(w[0] == w[1] && w[1] == w[2] && w[2] == w[3]))
          throw std::runtime_error(
            "subsection 'Particles': 'Domain walls' names some of the faces "
            "x-, x+, y-, y+ of a 'column' mesh, whose side is one wall, the "
            "mantle: write 'mantle' (or 'all') to make it a wall, or leave "
            "all four out.");
        for (unsigned int f = 0; f < 4; ++f)
          if (domain.mirror_planes[f])
            throw std::runtime_error(
              "subsection 'Particles': 'Symmetry planes' names a face of "
              "the side of a 'column' mesh, which has no flat side: only "
              "z- and z+ can be mirror planes.");
      }



      /** Raise the lowest wall of @p domain to the distributor at
       *  @p height, which must lie inside the domain, on a wall. */
      void
      set_distributor(DomainBox &domain, const double height)
      {
        const unsigned int d    = domain.dim - 1;
        const std::string  face = std::string(d == 2 ? "z" : "y") + "-";
        if (!domain.walls[2 * d])
          throw std::runtime_error(
            "subsection 'Particles': 'Distributor height' raises the wall "
            + face + " to the distributor, and " + face
            + " is not among the 'Domain walls': add it.");
        if (!(height > domain.lower[d] && height < domain.upper[d]))
          throw std::runtime_error(
            "subsection 'Particles': 'Distributor height' = "
            + core::number_text(height) + " m lies outside the mesh, which "
            + "spans " + core::number_text(domain.lower[d]) + " to "
            + core::number_text(domain.upper[d]) + " m along "
            + std::string(d == 2 ? "z" : "y")
            + ": give a height between them, a few cells above the inflow.");
        domain.distributor = height;
      }
    } // namespace



    DomainBox
    make_domain_box(const core::MeshParameters &mesh,
                    const ParticleParameters   &particles,
                    const Eigen::Vector3d      &lower,
                    const Eigen::Vector3d      &upper,
                    const unsigned int          dim)
    {
      DomainBox domain;
      domain.lower         = lower;
      domain.upper         = upper;
      domain.walls         = particles.walls;
      domain.mirror_planes = particles.symmetry_planes;
      domain.dim           = dim;
      if (mesh.type == core::MeshParameters::Type::column)
        {
          set_column(domain, mesh);
          check_column_faces(domain);
        }
      if (particles.distributor_height)
        set_distributor(domain, *particles.distributor_height);
      return domain;
    }



    double
    reach_from_axis(const DomainBox          &domain,
                    const geometry::Shape    &shape,
                    const Eigen::Quaterniond &orientation,
                    const Eigen::Vector3d    &position)
    {
      const geometry::Pose  pose(orientation, position);
      const Eigen::Vector3d radial(
        position[0] - 0.5 * (domain.lower[0] + domain.upper[0]),
        position[1] - 0.5 * (domain.lower[1] + domain.upper[1]),
        0.);
      if (shape.is_convex() && radial.norm() > 0.)
        return domain.distance_from_axis(
          pose.to_world(shape.support(orientation.conjugate() * radial)));
      const std::vector<Eigen::Vector3d> points = shape.surface_points();
      if (points.empty())
        return domain.distance_from_axis(position) + shape.bounding_radius();
      double reach = 0.;
      for (const Eigen::Vector3d &p : points)
        reach = std::max(reach, domain.distance_from_axis(pose.to_world(p)));
      return reach;
    }
  } // namespace fbm
} // namespace particulate
