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
    containment_engine_takes(const geometry::Shape &shape,
                             const unsigned int     dim)
    {
      return is_rotation_invariant(shape, dim)
             || dynamic_cast<const geometry::MappedSurface *>(&shape);
    }
  } // namespace fbm
} // namespace particulate
