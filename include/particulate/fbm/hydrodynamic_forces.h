#ifndef particulate_fbm_hydrodynamic_forces_h
#define particulate_fbm_hydrodynamic_forces_h

#include <particulate/fbm/fictitious_boundary.h>
#include <particulate/fluid/navier_stokes.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace particulate {
  namespace fbm {
    /** Force [N] and torque [N m] of the fluid on one body (per unit depth
     *  in 2D, where the torque is along z). */
    struct HydrodynamicLoad
    {
      Eigen::Vector3d force  = Eigen::Vector3d::Zero();
      Eigen::Vector3d torque = Eigen::Vector3d::Zero();
    };

    /**
     * Hydrodynamic force and torque on every body by the volume integrals of
     * thesis eq. 5.12-5.13,
     *
     *   F_i = - int sigma . grad alpha_i,
     *   T_i = - int (x - X_i) x (sigma . grad alpha_i),
     *
     * with sigma = -p I + 2 mu D(u) and alpha_i the Q2 interpolant of body
     * i's indicator: 1 at the velocity nodes marked by @p interface as
     * inside body i, 0 elsewhere. Only cells with nodes on both sides (the
     * cut cells) contribute; the result is summed over all ranks.
     *
     * @param centres the reference points X_i of the torques [m]
     */
    template <int dim>
    std::vector<HydrodynamicLoad>
    hydrodynamic_loads(const fluid::NavierStokes<dim>     &flow,
                       const FictitiousBoundary<dim>      &interface,
                       const std::vector<Eigen::Vector3d> &centres);

    /**
     * Complete loads integrated over the part of a body inside a symmetric
     * domain: for every mirror plane (normal to axis a; faces in the order
     * x-, x+, y-, y+, z-, z+) add the reflected image, F + R_a F for the
     * force and T - R_a T for the torque (a pseudo-vector), where R_a flips
     * component a. The body's centre must lie on the planes.
     */
    void
    add_mirror_images(std::vector<HydrodynamicLoad> &loads,
                      const std::array<bool, 6>     &mirror_planes);
  } // namespace fbm
} // namespace particulate

#endif
