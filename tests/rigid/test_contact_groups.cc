// Contact groups by the modified connected components of Algorithm 3
// (thesis §3.3): two piles on one floor form two groups although the
// floor connects them (fixed bodies never join groups), a falling sphere
// in the air and the fixed bodies belong to no group, and each group's
// edges start at the body resting on the fixed one (shock-propagation
// order). Also checks that the contact graph keeps the warm-start cache of
// persistent pairs (edge state persistent_contact, cached impulse > 0).
#include <particulate/geometry/box.h>
#include <particulate/geometry/sphere.h>

#include "scene_tools.h"
#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

int
main()
{
  World    w;
  Material m;
  m.static_friction = m.dynamic_friction = 0.5;
  w.add_material(m);
  const BodyId floor = add_floor(w);
  auto         box   = std::make_shared<Box>(Eigen::Vector3d::Constant(0.05));
  auto         ball  = std::make_shared<Sphere>(0.05);
  // Pile 1: three boxes; pile 2: two spheres on a fixed box obstacle.
  const BodyId a0       = w.add_body(box, 0, Eigen::Vector3d(0., 0., 0.05));
  const BodyId a1       = w.add_body(box, 0, Eigen::Vector3d(0., 0., 0.15));
  const BodyId a2       = w.add_body(box, 0, Eigen::Vector3d(0., 0., 0.25));
  const BodyId obstacle = w.add_body(box,
                                     0,
                                     Eigen::Vector3d(1., 0., 0.05),
                                     Eigen::Quaterniond::Identity(),
                                     true);
  const BodyId b0       = w.add_body(ball, 0, Eigen::Vector3d(1., 0., 0.15));
  const BodyId b1       = w.add_body(ball, 0, Eigen::Vector3d(1., 0., 0.25));
  const BodyId free     = w.add_body(ball, 0, Eigen::Vector3d(3., 0., 2.));
  for (int s = 0; s < 20; ++s)
    w.step(1.e-3);
  w.contact_graph().validate(w.n_bodies());
  const auto &g = w.contact_graph().group_of_body();
  std::cout << "groups:";
  for (unsigned int i = 0; i < w.n_bodies(); ++i)
    std::cout << " " << g[i];
  std::cout << "\n";
  CHECK(w.contact_graph().group_edges().size() == 2,
        "expected two contact groups");
  CHECK(g[a0] >= 0 && g[a0] == g[a1] && g[a1] == g[a2], "pile 1 is one group");
  CHECK(g[b0] >= 0 && g[b0] == g[b1], "pile 2 is one group");
  CHECK(g[a0] != g[b0], "the floor must not connect the piles");
  CHECK(g[floor] == -1 && g[obstacle] == -1 && g[free] == -1,
        "fixed and free bodies are in no group");
  // Propagation order: the first edge of pile 1 touches the floor.
  const auto &edges = w.contact_graph().edges();
  const auto &e0
    = edges[w.contact_graph().group_edges()[g[a0]].front()].manifold;
  CHECK((e0.a == floor && e0.b == a0) || (e0.a == a0 && e0.b == floor),
        "edge order starts at the floor");
  unsigned int persistent = 0;
  for (const auto &e : edges)
    if (e.state == EdgeState::persistent_contact)
      {
        ++persistent;
        double cached = 0.;
        for (const auto &c : e.manifold.points)
          cached += c.normal_impulse;
        CHECK(cached > 0., "persistent contacts carry cached impulses");
      }
  CHECK(persistent >= 5, "persistent edges " << persistent);
  std::cout << persistent << " persistent edges\nOK\n";
  return 0;
}
