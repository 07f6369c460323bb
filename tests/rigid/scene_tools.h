// Helpers to set up small test scenes for the rigid tests.
#ifndef particulate_tests_rigid_scene_tools_h
#define particulate_tests_rigid_scene_tools_h

#include <particulate/geometry/half_space.h>
#include <particulate/rigid/world.h>

#include <vector>

inline std::vector<particulate::rigid::ContactSolverType>
all_solvers()
{
  using particulate::rigid::ContactSolverType;
  return {ContactSolverType::projected_gauss_seidel,
          ContactSolverType::sequential_impulses,
          ContactSolverType::dem};
}

/** Adds the fixed floor z <= 0. */
inline particulate::rigid::BodyId
add_floor(particulate::rigid::World &w, const unsigned int material = 0)
{
  return w.add_body(
    std::make_shared<particulate::geometry::HalfSpace>(Eigen::Vector3d::UnitZ(),
                                                       0.),
    material,
    Eigen::Vector3d::Zero(),
    Eigen::Quaterniond::Identity(),
    true);
}

#endif
