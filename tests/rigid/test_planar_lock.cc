// Disks of a planar (2D) simulation are long cylinders along z whose
// rotation about x and y is locked. Stacked under gravity in the x-y plane,
// the upper disk must rest on the lower one with the gap the contact offset
// asks for, for every contact solver: the contact points GJK finds lie
// anywhere along the cylinders' length, and without the lock their impulses
// tilt the bodies instead of stopping them (the stack then falls over).
#include <particulate/geometry/cylinder.h>

#include <cmath>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

int
main()
{
  const double r = 0.001, offset = 2.5e-4;
  for (const auto type : all_solvers())
    {
      WorldParameters prm;
      prm.contact_solver = type;
      prm.contact_offset = offset;
      prm.gravity        = Eigen::Vector3d(0., -9.81, 0.);
      World    w(prm);
      Material m;
      m.density       = 1000.;
      m.restitution   = 0.;
      m.dem_stiffness = 1.e4;
      w.add_material(m);
      w.add_body(std::make_shared<HalfSpace>(Eigen::Vector3d::UnitY(), 0.),
                 0,
                 Eigen::Vector3d::Zero(),
                 Eigen::Quaterniond::Identity(),
                 true);
      const auto   cylinder = std::make_shared<Cylinder>(r, 0.5);
      const BodyId lower
        = w.add_body(cylinder, 0, Eigen::Vector3d(0., r + offset, 0.));
      const BodyId upper
        = w.add_body(cylinder,
                     0,
                     Eigen::Vector3d(0., 3. * r + 3. * offset, 0.));
      for (const BodyId b : {lower, upper})
        w.body(b).lock_rotation({{true, true, false}});
      for (int step = 0; step < 200; ++step)
        w.step(1.e-3);
      const Eigen::Vector3d d = w.body(upper).position - w.body(lower).position;
      const double          gap = std::hypot(d[0], d[1]) - 2. * r;
      std::cout << to_string(type) << ": gap " << gap << " m (offset " << offset
                << "), tilt of the upper disk's axis "
                << (w.body(upper).orientation * Eigen::Vector3d::UnitZ())
                     .head<2>()
                     .norm()
                << ", z drift " << d[2] << " m\n";
      const double squeeze = type == ContactSolverType::dem ? 0.1 * offset : 0.;
      CHECK(gap > offset - 0.05 * offset - squeeze && gap < 1.05 * offset,
            "gap " << gap << " instead of the offset " << offset);
      CHECK(
        (w.body(upper).orientation * Eigen::Vector3d::UnitZ()).head<2>().norm()
          < 1e-12,
        "the locked axes must not turn");
    }
  std::cout << "OK\n";
  return 0;
}
