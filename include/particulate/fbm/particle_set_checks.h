#ifndef particulate_fbm_particle_set_checks_h
#define particulate_fbm_particle_set_checks_h

#include <particulate/fbm/domain_box.h>
#include <particulate/fbm/particle_description.h>
#include <particulate/rigid/world.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * Refuse initial particles that overlap: each pair whose bounding
     * balls meet is tested with the rigid engine's narrow phase (exact for
     * the analytic shapes); a penetration deeper than 1e-9 of the smaller
     * body's size stops the run. Touching is allowed, and so are overlaps
     * among the parts of an articulated body.
     * @throw std::runtime_error naming both particles, where each was
     *   described, and the depth
     */
    void
    check_no_overlap(const std::vector<ParticleDescription> &particles,
                     const unsigned int                      dim);

    /**
     * Refuse a particle that reaches outside the @p domain: its bounding
     * box, placed, must lie inside the mesh's box, except across the
     * faces that are mirror planes (x-, x+, y-, y+, z-, z+), on which
     * bodies of a symmetric set-up are cut; in a column, the body must
     * also lie inside the mantle (reach_from_axis()). A 2D run checks x
     * and y.
     * @throw std::runtime_error naming the particle and where it was
     *   described
     */
    void
    check_inside_domain(const std::vector<ParticleDescription> &particles,
                        const DomainBox                        &domain);

    /**
     * Refuse a particle whose centre is off one of the @p mirror_planes
     * (x-, x+, y-, y+, z-, z+ of the box [lower, upper]): a symmetric
     * set-up computes the part of each body on one side of the plane and
     * mirrors it, which describes the body only if the plane cuts it
     * through its centre. Tolerance 1e-9 of the box's extent.
     * @throw std::runtime_error naming the particle, where it was described,
     *   and the plane
     */
    void
    check_on_mirror_planes(const std::vector<ParticleDescription> &particles,
                           const Eigen::Vector3d                  &lower,
                           const Eigen::Vector3d                  &upper,
                           const std::array<bool, 6> &mirror_planes,
                           const unsigned int         dim);

    /**
     * Refuse a free particle that starts closer than @p clearance (the
     * rigid engine's contact distance) to another particle or to a domain
     * wall: the contact model holds surfaces that far apart, so it would
     * push them apart in the first step, at speeds of the order of the
     * shortfall over the time step that the case never asked for. The
     * bodies of @p world that are not in @p particle_ids are its walls;
     * pairs of which neither is free are not checked.
     * @throw std::runtime_error naming the bodies, where each particle was
     *   described, the gap and the contact distance
     */
    void
    check_contact_clearance(const rigid::World               &world,
                            const std::vector<rigid::BodyId> &particle_ids,
                            const std::vector<ParticleDescription> &particles,
                            const double                            clearance);
  } // namespace fbm
} // namespace particulate

#endif
