// add_mirror_images completes the loads on the part of a body inside a
// symmetric domain. Take point forces f_k at points r_k (relative to the
// body's centre) in the octant x, y, z >= 0, build the full symmetric set by
// reflecting them across the chosen planes, and compare the sum of forces
// and of the torques r x f of the full set with the completed loads of the
// octant's set, for every combination of mirror planes.

#include <particulate/fbm/hydrodynamic_forces.h>

#include <random>

#include "../fluid/test_utilities.h"

using namespace particulate;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  std::mt19937                             random(7);
  std::uniform_real_distribution<double>   uniform(-1., 1.);

  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> points;
  for (int k = 0; k < 5; ++k)
    {
      Eigen::Vector3d r(uniform(random), uniform(random), uniform(random));
      r = r.cwiseAbs();
      points.emplace_back(r,
                          Eigen::Vector3d(uniform(random),
                                          uniform(random),
                                          uniform(random)));
    }

  for (unsigned int mask = 1; mask < 8; ++mask)
    {
      // mirror planes through the centre normal to the axes in mask (the
      // x- face, y- face, z- face of a domain whose corner is the centre)
      std::array<bool, 6> planes{};
      for (unsigned int a = 0; a < 3; ++a)
        planes[2 * a] = (mask >> a) & 1;

      // the full set: reflect every point force across every subset
      std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> full = points;
      for (unsigned int a = 0; a < 3; ++a)
        if (planes[2 * a])
          {
            const std::size_t n = full.size();
            for (std::size_t k = 0; k < n; ++k)
              {
                auto image      = full[k];
                image.first[a]  = -image.first[a];
                image.second[a] = -image.second[a];
                full.push_back(image);
              }
          }
      Eigen::Vector3d force  = Eigen::Vector3d::Zero(),
                      torque = Eigen::Vector3d::Zero();
      for (const auto &[r, f] : full)
        {
          force += f;
          torque += r.cross(f);
        }

      std::vector<fbm::HydrodynamicLoad> loads(1);
      for (const auto &[r, f] : points)
        {
          loads[0].force += f;
          loads[0].torque += r.cross(f);
        }
      fbm::add_mirror_images(loads, planes);
      const double error
        = (loads[0].force - force).norm() + (loads[0].torque - torque).norm();
      checker.check(error < 1e-12 * (force.norm() + torque.norm() + 1.),
                    "mirror planes (x, y, z) = (" + std::to_string(mask & 1)
                      + ", " + std::to_string((mask >> 1) & 1) + ", "
                      + std::to_string((mask >> 2) & 1)
                      + "): force and torque of the full set");
    }
  return checker.exit_code();
}
