#include <particulate/fbm/particle_shape.h>

namespace particulate {
  namespace fbm {
    bool
    is_rotation_invariant(const geometry::Shape &shape, const unsigned int dim)
    {
      return shape.kind() == geometry::ShapeKind::sphere
             || (dim == 2 && shape.kind() == geometry::ShapeKind::cylinder);
    }
  } // namespace fbm
} // namespace particulate
