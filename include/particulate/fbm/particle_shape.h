#ifndef particulate_fbm_particle_shape_h
#define particulate_fbm_particle_shape_h

#include <particulate/geometry/shape.h>


namespace particulate {
  namespace fbm {
    /**
     * Whether a body of shape @p shape looks the same however it turns in a
     * run of dimension @p dim: a sphere, and in 2D a disk, which can only
     * spin about its axis. A mesh carried with such a body moves with its
     * translation alone.
     */
    bool
    is_rotation_invariant(const geometry::Shape &shape, const unsigned int dim);

    /** Whether @p shape is a body read from a surface mesh (seen through
     *  its distance map). */
    bool
    is_surface_mesh(const geometry::Shape &shape);

    /**
     * Whether the cuda/ containment engine can mark the nodes inside a body
     * of shape @p shape: a rotation-invariant one (its one-sphere set) or a
     * surface mesh (its distance map).
     */
    bool
    containment_engine_takes(const geometry::Shape &shape,
                             const unsigned int     dim);
  } // namespace fbm
} // namespace particulate

#endif
