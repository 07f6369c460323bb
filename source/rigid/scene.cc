#include <particulate/geometry/box.h>
#include <particulate/geometry/capsule.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/sphere.h>
#include <particulate/rigid/scene.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace particulate {
  namespace rigid {
    std::shared_ptr<const geometry::Shape>
    ShapeDescription::create() const
    {
      switch (kind)
        {
          case geometry::ShapeKind::sphere:
            return std::make_shared<geometry::Sphere>(radius);
          case geometry::ShapeKind::box:
            return std::make_shared<geometry::Box>(extents);
          case geometry::ShapeKind::capsule:
            return std::make_shared<geometry::Capsule>(radius, half_length);
          case geometry::ShapeKind::cylinder:
            return std::make_shared<geometry::Cylinder>(radius, half_length);
          case geometry::ShapeKind::ellipsoid:
            return std::make_shared<geometry::Ellipsoid>(extents);
          case geometry::ShapeKind::half_space:
            return std::make_shared<geometry::HalfSpace>(normal, offset);
          case geometry::ShapeKind::general:
            if (!custom)
              throw std::invalid_argument(
                "rigid::ShapeDescription: a signed-distance (mesh) shape needs "
                "the ready-made shape in `custom` (built from the surface mesh).");
            return custom;
        }
      throw std::invalid_argument(
        "rigid::ShapeDescription: unknown shape type");
    }



    std::vector<BodyDescription>
    PouringDescription::generate() const
    {
      if (!(radius_min > 0.) || !(radius_max >= radius_min))
        throw std::invalid_argument(
          "rigid::PouringDescription: need 0 < minimum radius <= maximum radius.");
      const Eigen::Vector3d size = box_max - box_min;
      if (!(size.minCoeff() > 2. * radius_max))
        throw std::invalid_argument(
          "rigid::PouringDescription: the box must be wider than the largest "
          "sphere diameter in every direction.");
      std::vector<BodyDescription> out;
      // Container: floor and four side walls, open at the top.
      const Eigen::Vector3d normals[5] = {Eigen::Vector3d::UnitZ(),
                                          Eigen::Vector3d::UnitX(),
                                          -Eigen::Vector3d::UnitX(),
                                          Eigen::Vector3d::UnitY(),
                                          -Eigen::Vector3d::UnitY()};
      const double          offsets[5]
        = {box_min[2], box_min[0], -box_max[0], box_min[1], -box_max[1]};
      for (int k = 0; k < 5; ++k)
        {
          BodyDescription w;
          w.shape.kind   = geometry::ShapeKind::half_space;
          w.shape.normal = normals[k];
          w.shape.offset = offsets[k];
          w.material     = material;
          w.fixed        = true;
          out.push_back(w);
        }
      // Lattice of spacing slightly above the largest diameter.
      const double spacing = 2.2 * radius_max;
      const int    nx
        = std::max(1, int((size[0] - 2. * radius_max) / spacing) + 1);
      const int ny
        = std::max(1, int((size[1] - 2. * radius_max) / spacing) + 1);
      std::mt19937                           rng(seed);
      std::uniform_real_distribution<double> u(0., 1.);
      const double jitter = 0.5 * (spacing - 2. * radius_max);
      for (unsigned int i = 0; i < n_spheres; ++i)
        {
          const int    ix = i % nx, iy = (i / nx) % ny, iz = i / (nx * ny);
          const double r
            = distribution == SizeDistribution::uniform ?
                radius_min + (radius_max - radius_min) * u(rng) :
                radius_min * std::pow(radius_max / radius_min, u(rng));
          BodyDescription b;
          b.shape.kind   = geometry::ShapeKind::sphere;
          b.shape.radius = r;
          b.material     = material;
          b.position
            = box_min
              + Eigen::Vector3d(radius_max + ix * spacing,
                                radius_max + iy * spacing,
                                radius_max + iz * spacing)
              + jitter
                  * Eigen::Vector3d(2. * u(rng) - 1., 2. * u(rng) - 1., 0.);
          b.velocity = initial_speed
                       * Eigen::Vector3d(2. * u(rng) - 1.,
                                         2. * u(rng) - 1.,
                                         2. * u(rng) - 1.);
          out.push_back(b);
        }
      return out;
    }



    void
    SceneDescription::check() const
    {
      world.check();
      if (materials.empty())
        throw std::invalid_argument(
          "rigid::SceneDescription: define at least one material.");
      for (const auto &m : materials)
        m.check();
      for (unsigned int i = 0; i < bodies.size(); ++i)
        if (bodies[i].material >= materials.size())
          throw std::invalid_argument(
            "rigid::SceneDescription: body " + std::to_string(i)
            + " uses material " + std::to_string(bodies[i].material)
            + ", but only " + std::to_string(materials.size())
            + " are defined.");
      if (pouring.n_spheres > 0 && pouring.material >= materials.size())
        throw std::invalid_argument(
          "rigid::SceneDescription: the pouring material does not exist.");
      if (!(time_step > 0.) || !(end_time >= 0.))
        throw std::invalid_argument(
          "rigid::SceneDescription: the time step must be positive and the end time >= 0 (s).");
    }



    World
    SceneDescription::build_world() const
    {
      check();
      World w(world);
      for (const auto &m : materials)
        w.add_material(m);
      auto add = [&w](const BodyDescription &b) {
        const BodyId id             = w.add_body(b.shape.create(),
                                     b.material,
                                     b.position,
                                     b.orientation,
                                     b.fixed);
        w.body(id).linear_velocity  = b.velocity;
        w.body(id).angular_velocity = b.angular_velocity;
      };
      for (const auto &b : bodies)
        add(b);
      if (pouring.n_spheres > 0)
        for (const auto &b : pouring.generate())
          add(b);
      return w;
    }
  } // namespace rigid
} // namespace particulate
