#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/point_containment.h>

#include <cmath>
#include <limits>

namespace particulate::geometry {

  BoundingBox
  world_bounding_box(const PlacedShape &body)
  {
    const BoundingBox b = body.shape->bounding_box();
    if (!b.lower.allFinite() || !b.upper.allFinite())
      {
        const double inf = std::numeric_limits<double>::infinity();
        return BoundingBox(Eigen::Vector3d::Constant(-inf),
                           Eigen::Vector3d::Constant(inf));
      }
    // Rounding in the transformation may move a point on the surface just
    // outside the transformed box; a relative pad keeps the answer equal to
    // the brute-force one.
    BoundingBox  w   = body.pose.to_world(b);
    const double pad = 1e-12 * (1. + w.extent().norm() + w.center().norm());
    return w.enlarged(pad);
  }

  namespace {
    void
    check_bodies(const std::vector<PlacedShape> &bodies)
    {
      for (std::size_t b = 0; b < bodies.size(); ++b)
        if (bodies[b].shape == nullptr)
          throw GeometryError("classify_points: body " + std::to_string(b)
                              + " has no shape.");
    }
  } // namespace

  std::vector<int>
  classify_points(const PointHashGrid            &grid,
                  const std::vector<PlacedShape> &bodies,
                  std::vector<double>            *distances,
                  ContainmentStatistics          *statistics)
  {
    check_bodies(bodies);
    const auto      &pts = grid.points();
    std::vector<int> inside(pts.size(), -1);
    if (distances)
      distances->assign(pts.size(), std::numeric_limits<double>::infinity());
    std::vector<char> touched(statistics ? pts.size() : 0, 0);
    std::size_t       tests = 0;
    for (std::size_t b = 0; b < bodies.size(); ++b)
      {
        const PlacedShape &body = bodies[b];
        grid.for_each_in_box(world_bounding_box(body), [&](std::size_t i) {
          ++tests;
          if (statistics)
            touched[i] = 1;
          const Eigen::Vector3d p = body.pose.to_body(pts[i]);
          if (distances)
            {
              const double d  = body.shape->signed_distance(p);
              (*distances)[i] = std::min((*distances)[i], d);
            }
          // The first body wins, as in the brute-force loop; a point already
          // inside an earlier body needs no further inside test.
          if (inside[i] < 0 && body.shape->contains(p))
            inside[i] = static_cast<int>(b);
        });
      }
    if (statistics)
      {
        statistics->n_points         = pts.size();
        statistics->n_tests          = tests;
        statistics->n_points_touched = 0;
        for (const char t : touched)
          statistics->n_points_touched += t;
      }
    return inside;
  }

  std::vector<int>
  classify_points_brute_force(const std::vector<Eigen::Vector3d> &points,
                              const std::vector<PlacedShape>     &bodies)
  {
    check_bodies(bodies);
    std::vector<int> inside(points.size(), -1);
    for (std::size_t i = 0; i < points.size(); ++i)
      for (std::size_t b = 0; b < bodies.size(); ++b)
        if (bodies[b].shape->contains(bodies[b].pose.to_body(points[i])))
          {
            inside[i] = static_cast<int>(b);
            break;
          }
    return inside;
  }

} // namespace particulate::geometry
