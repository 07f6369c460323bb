#ifndef particulate_fbm_hydrodynamic_forces_h
#define particulate_fbm_hydrodynamic_forces_h

#include <particulate/fbm/fictitious_boundary.h>
#include <particulate/fbm/hydrodynamic_load.h>
#include <particulate/fluid/navier_stokes.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace particulate {
  namespace fbm {
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
     * Both are evaluated node by node: covered node k of body i carries the
     * share g_k = - int sigma . grad phi_k (phi_k its Q2 basis function),
     * F_i = sum g_k and T_i = sum (x_k - X_i) x g_k. The force is the
     * integral above exactly (alpha_i = sum phi_k); the torque is its
     * integrand with (x - X_i) alpha_i replaced by its Q2 interpolant, i.e.
     * the discrete momentum equation tested with the rigid rotation at the
     * covered nodes. Why: the pressure modes of cut cells that the
     * divergence of the free velocities does not see
     * (doc/developer/fbm.md, "Pressure") are then invisible to the torque as
     * they are to the force; with the integrand as written, a 3D cylinder
     * spanning a slab saw a torque a hundred times the 2D disk's from them.
     *
     * @param centres the reference points X_i of the torques [m]
     */
    template <int dim>
    std::vector<HydrodynamicLoad>
    hydrodynamic_loads(const fluid::NavierStokes<dim>     &flow,
                       const FictitiousBoundary<dim>      &interface,
                       const std::vector<Eigen::Vector3d> &centres);

    /** The rigid motion of a body over one time step, as the fluid saw it. */
    struct RigidStepMotion
    {
      /// reference point of the torque (where the interface was marked) [m]
      Eigen::Vector3d centre           = Eigen::Vector3d::Zero();
      Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
      /// accelerations of the step [m/s^2], [1/s^2]
      Eigen::Vector3d acceleration         = Eigen::Vector3d::Zero();
      Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();
    };

    /**
     * The fluid-inertia part of the loads that the stress integral above
     * leaves out (`Force integral = stress and inertia`, subsection
     * `Particles`):
     *
     *   dF_i = - rho_f int (Du/Dt - a_i(x)) alpha_i,
     *   dT_i = - rho_f int (x - X_i) x (Du/Dt - a_i(x)) alpha_i,
     *
     * with Du/Dt = (u - u_start)/k + ((u - w) . grad) u over the step of
     * size k (nodal values, so that on a moving mesh with velocity w the
     * nodal difference is the ALE time derivative) and a_i(x) the rigid
     * acceleration of body i. Why: testing the discrete momentum equation
     * with alpha_i instead of a sharp indicator, the stress integral equals
     * the force on the body only where the fluid moves rigidly with it;
     * in the band of cut cells where alpha_i falls from 1 to 0 the fluid's
     * own acceleration, and the jump of the nodes that the body covers
     * during the step (a jump to the body's velocity), is momentum the
     * body gives the fluid. Both vanish as the band shrinks (first order
     * in h); the sum of the two integrals is the reaction of the discrete
     * momentum equation at the covered nodes, so that body and fluid
     * exchange momentum exactly. Summed over all ranks.
     *
     * @param step_start the flow solution at the start of the step (ghosted)
     * @param time_step k; 0 for steady flow (no time derivative)
     */
    template <int dim>
    std::vector<HydrodynamicLoad>
    fluid_inertia_loads(
      const fluid::NavierStokes<dim>                       &flow,
      const FictitiousBoundary<dim>                        &interface,
      const typename fluid::NavierStokes<dim>::BlockVector &step_start,
      const double                                          time_step,
      const std::vector<RigidStepMotion>                   &motion);

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
