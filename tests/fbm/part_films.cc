// 'Films between parts = cover': FictitiousBoundary::cover_films gives a
// free velocity node within one node spacing of two parts of one joint the
// motion of the nearer part. A head (disk, radius 0.03 m) with two shells
// (0.01 x 0.19 m) hinged at its centre and 12 degrees apart, in the DFG 2D
// channel at refinement 2, away from its cylinder: the shells' inner faces
// meet 0.048 m from the hinge and open to 0.03 m at the tips, a wedge of
// liquid that narrows below a cell. Checked against a recomputation from the
// shapes' signed distances:
// - there are film nodes, and every node cover_films takes was free,
//   has two parts within its spacing and now carries the nearer of them;
// - no node left free has two parts within its spacing, and no node that
//   classify() covered changes;
// - the same parts in two different joints (or none) keep every node as
//   classify() left it: films are only covered within one body.
#include <particulate/fbm/fictitious_boundary.h>
#include <particulate/geometry/box.h>
#include <particulate/geometry/cylinder.h>

#include <cmath>
#include <limits>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  testing::Checker checker;

  /** The parts within node @p i's spacing, and the nearest of them. */
  std::pair<unsigned int, int>
  parts_near(const fbm::FictitiousBoundary<2>                    &boundary,
             const std::vector<fbm::FictitiousBoundary<2>::Body> &bodies,
             const unsigned int                                   i)
  {
    unsigned int close    = 0;
    int          nearest  = -1;
    double       shortest = std::numeric_limits<double>::max();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const rigid::RigidBody &part = *bodies[b].body;
        const double            d    = part.shape().signed_distance(
          part.to_body(boundary.node_position(i)));
        close += d < boundary.node_spacing(i);
        if (d < shortest)
          {
            shortest = d;
            nearest  = b;
          }
      }
    return {close, nearest};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::CaseFlow<2>    channel(testing::library_case("dfg-2d-1", ""));
  fluid::NavierStokes<2> &flow = channel.flow;

  rigid::World               world;
  const auto                 material = world.add_material({});
  const Eigen::Vector3d      hinge(1.2, 0.2, 0.);
  const double               half_angle = 6. * M_PI / 180.;
  std::vector<rigid::BodyId> ids;
  ids.push_back(world.add_body(std::make_shared<geometry::Cylinder>(0.03, 0.5),
                               material,
                               hinge,
                               Eigen::Quaterniond::Identity(),
                               false));
  for (const double sign : {1., -1.})
    {
      // the shell points backwards (-x) from the hinge, turned by
      // +-half_angle
      const Eigen::Quaterniond turn(
        Eigen::AngleAxisd(sign * half_angle, Eigen::Vector3d::UnitZ()));
      ids.push_back(world.add_body(
        std::make_shared<geometry::Box>(Eigen::Vector3d(0.095, 0.005, 0.5)),
        material,
        hinge + turn * Eigen::Vector3d(-0.095, 0., 0.),
        turn,
        false));
    }
  std::vector<fbm::FictitiousBoundary<2>::Body> bodies;
  for (const rigid::BodyId id : ids)
    bodies.push_back({&world.body(id)});

  fbm::FictitiousBoundary<2> boundary(flow);
  boundary.setup();
  boundary.classify(bodies);
  std::vector<int> marked(boundary.n_nodes());
  for (unsigned int i = 0; i < boundary.n_nodes(); ++i)
    marked[i] = boundary.body_of_node(i);

  boundary.cover_films(bodies, {0, 0, 0});
  unsigned int film = 0, wrong_film = 0, missed = 0, changed_covered = 0;
  for (unsigned int i = 0; i < boundary.n_nodes(); ++i)
    {
      const auto [close, nearest] = parts_near(boundary, bodies, i);
      const int now               = boundary.body_of_node(i);
      if (marked[i] >= 0)
        changed_covered += now != marked[i];
      else if (now >= 0)
        {
          ++film;
          wrong_film += close < 2 || now != nearest;
        }
      else
        missed += close >= 2;
    }
  checker.check(film > 0,
                "the parts enclose film nodes (" + std::to_string(film) + ")");
  checker.check(wrong_film == 0,
                "every film node has two parts within its spacing and the "
                "nearer one's motion ("
                  + std::to_string(wrong_film) + " do not)");
  checker.check(missed == 0,
                "no free node is left with two parts within its spacing ("
                  + std::to_string(missed) + " are)");
  checker.check(changed_covered == 0,
                "the nodes classify() covered keep their body ("
                  + std::to_string(changed_covered) + " changed)");

  for (const std::vector<int> &joints :
       {std::vector<int>{0, 1, 2}, std::vector<int>{-1, -1, -1}})
    {
      boundary.classify(bodies);
      boundary.cover_films(bodies, joints);
      unsigned int changed = 0;
      for (unsigned int i = 0; i < boundary.n_nodes(); ++i)
        changed += boundary.body_of_node(i) != marked[i];
      checker.check(changed == 0,
                    "parts of different bodies: no film covered ("
                      + std::to_string(changed) + " nodes changed)");
    }
  return checker.exit_code();
}
