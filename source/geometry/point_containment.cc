#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/point_containment.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace particulate {
  namespace geometry {

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
      // A body's candidate points (those in its box) are answered in groups by
      // the shape's batched queries, Shape::contains_points and
      // Shape::signed_distances, so that shapes with a faster batched query
      // (distance maps) get it. Small groups keep the buffers in the L1 cache.
      constexpr std::size_t        group = 256;
      std::vector<std::size_t>     test_ids, distance_ids;
      std::vector<Eigen::Vector3d> test_points, distance_points;
      std::vector<double>          body_distances;
      bool                         test_inside[group];
      test_ids.reserve(group);
      test_points.reserve(group);
      for (std::size_t b = 0; b < bodies.size(); ++b)
        {
          const PlacedShape &body = bodies[b];
          auto               test = [&] {
            body.shape->contains_points(test_points.data(),
                                        test_points.size(),
                                        test_inside);
            for (std::size_t q = 0; q < test_ids.size(); ++q)
              if (test_inside[q])
                inside[test_ids[q]] = static_cast<int>(b);
            test_ids.clear();
            test_points.clear();
          };
          auto measure = [&] {
            body.shape->signed_distances(distance_points, body_distances);
            for (std::size_t q = 0; q < distance_ids.size(); ++q)
              (*distances)[distance_ids[q]]
                = std::min((*distances)[distance_ids[q]], body_distances[q]);
            distance_ids.clear();
            distance_points.clear();
          };
          grid.for_each_in_box(world_bounding_box(body), [&](std::size_t i) {
            ++tests;
            if (statistics)
              touched[i] = 1;
            const Eigen::Vector3d p = body.pose.to_body(pts[i]);
            if (distances)
              {
                distance_ids.push_back(i);
                distance_points.push_back(p);
                if (distance_ids.size() == group)
                  measure();
              }
            // The first body wins, as in the brute-force loop; a point already
            // inside an earlier body needs no further inside test (each point
            // is a candidate of a body at most once, so this body's own
            // answers cannot change the condition).
            if (inside[i] < 0)
              {
                test_ids.push_back(i);
                test_points.push_back(p);
                if (test_ids.size() == group)
                  test();
              }
          });
          if (!distance_ids.empty())
            measure();
          if (!test_ids.empty())
            test();
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

  } // namespace geometry
} // namespace particulate
