#ifndef particulate_fbm_particle_shape_h
#define particulate_fbm_particle_shape_h

#include <particulate/fbm/particle_parameters.h>
#include <particulate/geometry/shape.h>

#include <memory>

namespace particulate {
  namespace fbm {
    /**
     * The body-frame shape of the particles that @p particles describes: the
     * one object the rigid body, the fictitious boundary's containment and
     * the mesh deformation all read (geometry::Shape).
     *
     * A 2D disk is a cylinder along z of unit length: the rigid engine is 3D,
     * so its volume and inertia are those per unit depth, and the flow's
     * nodes lie in the plane z = 0, the cylinder's mid-plane.
     */
    std::shared_ptr<const geometry::Shape>
    make_particle_shape(const ParticleParameters &particles);

    /**
     * Whether a body of shape @p shape looks the same however it turns in a
     * run of dimension @p dim: a sphere, and in 2D a disk, which can only
     * spin about its axis. A mesh carried with such a body moves with its
     * translation alone.
     */
    bool
    is_rotation_invariant(const geometry::Shape &shape, const unsigned int dim);
  } // namespace fbm
} // namespace particulate

#endif
