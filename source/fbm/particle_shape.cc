#include <particulate/fbm/particle_shape.h>
#include <particulate/geometry/mapped_surface.h>

namespace particulate {
  namespace fbm {
    bool
    is_rotation_invariant(const geometry::Shape &shape, const unsigned int dim)
    {
      return shape.kind() == geometry::ShapeKind::sphere
             || (dim == 2 && shape.kind() == geometry::ShapeKind::cylinder);
    }

    bool
    is_surface_mesh(const geometry::Shape &shape)
    {
      return dynamic_cast<const geometry::MappedSurface *>(&shape) != nullptr;
    }

    bool
    containment_engine_takes(const geometry::Shape &shape,
                             const unsigned int     dim)
    {
      return is_rotation_invariant(shape, dim) || is_surface_mesh(shape);
    }
  } // namespace fbm
} // namespace particulate
