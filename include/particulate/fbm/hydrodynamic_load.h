#ifndef particulate_fbm_hydrodynamic_load_h
#define particulate_fbm_hydrodynamic_load_h

#include <Eigen/Core>

namespace particulate {
  namespace fbm {
    /** Force [N] and torque [N m] of the fluid on one body (per unit depth
     *  in 2D, where the torque is along z). */
    struct HydrodynamicLoad
    {
      Eigen::Vector3d force  = Eigen::Vector3d::Zero();
      Eigen::Vector3d torque = Eigen::Vector3d::Zero();
    };
  } // namespace fbm
} // namespace particulate

#endif
