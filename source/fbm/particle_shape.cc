#include <particulate/fbm/particle_shape.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/sphere.h>

namespace particulate {
  namespace fbm {
    std::shared_ptr<const geometry::Shape>
    make_particle_shape(const ParticleParameters &particles)
    {
      switch (particles.shape)
        {
          case ParticleParameters::Shape::disk:
            return std::make_shared<geometry::Cylinder>(particles.radius, 0.5);
          case ParticleParameters::Shape::cylinder:
            return std::make_shared<geometry::Cylinder>(particles.radius,
                                                        0.5 * particles.length);
          case ParticleParameters::Shape::sphere:
            break;
        }
      return std::make_shared<geometry::Sphere>(particles.radius);
    }



    bool
    is_rotation_invariant(const geometry::Shape &shape, const unsigned int dim)
    {
      return shape.kind() == geometry::ShapeKind::sphere
             || (dim == 2 && shape.kind() == geometry::ShapeKind::cylinder);
    }
  } // namespace fbm
} // namespace particulate
