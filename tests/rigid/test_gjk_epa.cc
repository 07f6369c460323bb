// GJK distance and EPA penetration against closed forms:
// - sphere-sphere: distance |c1 - c2| - r1 - r2 (separated and overlapping),
//   normal along the centre line, to 1e-9 (normal 1e-6, EPA 1e-4);
// - box-box axis aligned: gap along x (separated and overlapping) to 1e-9;
// - sphere-ellipsoid along a semi-axis and a rotated capsule against a
//   sphere: distance to 1e-8;
// - random convex pairs: the GJK distance equals the minimum over sampled
//   surface points within the sampling error, and never exceeds it; the
//   witness points lie on the surfaces (|phi| < 1e-6).
#include <particulate/geometry/box.h>
#include <particulate/geometry/capsule.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/sphere.h>
#include <particulate/rigid/gjk_epa.h>

#include <Eigen/Geometry>

#include <memory>
#include <random>

#include "test_tools.h"

using namespace particulate::rigid;
using namespace particulate::geometry;

namespace {
  ConvexPlacement
  place(const Shape              &s,
        const Eigen::Vector3d    &x,
        const Eigen::Quaterniond &q = Eigen::Quaterniond::Identity())
  {
    return {&s, q.toRotationMatrix(), x};
  }
} // namespace

int
main()
{
  const Sphere s1(0.5), s2(0.3);
  for (const double d : {2., 1., 0.81, 0.79, 0.6, 0.3})
    {
      const Eigen::Vector3d dir = Eigen::Vector3d(1., 2., -0.5).normalized();
      const auto            r
        = gjk_epa(place(s1, Eigen::Vector3d(0.1, 0.2, 0.3)),
                  place(s2, Eigen::Vector3d(0.1, 0.2, 0.3) + d * dir));
      std::cout << "spheres at " << d << ": distance " << r.distance
                << " (exact " << d - 0.8 << "), normal error "
                << (r.normal - dir).norm() << "\n";
      CHECK(std::abs(r.distance - (d - 0.8)) < 1.e-9, "sphere distance");
      // Spheres go through their core points (exact); the 1e-4 allowance
      // is what EPA on curved shapes (polytope within 1e-7) would give.
      CHECK((r.normal - dir).norm() < (d > 0.8 ? 1.e-6 : 1.e-4),
            "sphere normal");
    }
  const Box b(Eigen::Vector3d(0.5, 0.4, 0.3));
  for (const double gap : {0.2, 0.01, -0.01, -0.1})
    {
      const auto r = gjk_epa(place(b, Eigen::Vector3d::Zero()),
                             place(b, Eigen::Vector3d(1. + gap, 0.1, -0.05)));
      std::cout << "boxes with gap " << gap << ": distance " << r.distance
                << ", normal " << r.normal.transpose() << "\n";
      CHECK(std::abs(r.distance - gap) < 1.e-9, "box distance");
      CHECK((r.normal - Eigen::Vector3d::UnitX()).norm() < 1.e-6, "box normal");
    }
  const Ellipsoid e(Eigen::Vector3d(0.6, 0.3, 0.2));
  {
    const auto r = gjk_epa(place(e, Eigen::Vector3d::Zero()),
                           place(s2, Eigen::Vector3d(0., 0.9, 0.)));
    CHECK(std::abs(r.distance - 0.3) < 1.e-8,
          "ellipsoid-sphere distance " << r.distance);
  }
  const Capsule c(0.1, 0.4);
  {
    const Eigen::Quaterniond q(
      Eigen::AngleAxisd(M_PI / 2., Eigen::Vector3d::UnitY()));
    // Capsule along x after rotation; sphere above its end cap.
    const auto r = gjk_epa(place(c, Eigen::Vector3d::Zero(), q),
                           place(s2, Eigen::Vector3d(0.4, 0., 0.7)));
    CHECK(std::abs(r.distance - 0.3) < 1.e-8,
          "capsule-sphere distance " << r.distance);
  }

  // Random pairs against sampled surfaces.
  std::vector<std::shared_ptr<Shape>> shapes
    = {std::make_shared<Box>(Eigen::Vector3d(0.3, 0.2, 0.1)),
       std::make_shared<Cylinder>(0.2, 0.3),
       std::make_shared<Ellipsoid>(Eigen::Vector3d(0.3, 0.2, 0.15)),
       std::make_shared<Capsule>(0.1, 0.2)};
  std::mt19937                           rng(5);
  std::normal_distribution<double>       g;
  std::uniform_real_distribution<double> u(0., 1.);
  int                                    checked = 0;
  for (int trial = 0; trial < 200; ++trial)
    {
      const Shape &A = *shapes[trial % 4], &B = *shapes[(trial / 4) % 4];
      const Eigen::Quaterniond qa
        = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
      const Eigen::Quaterniond qb
        = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
      const Eigen::Vector3d xb
        = (0.3 + 0.8 * u(rng))
          * Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
      const auto pa = place(A, Eigen::Vector3d::Zero(), qa),
                 pb = place(B, xb, qb);
      const auto r  = gjk_epa(pa, pb);
      // Witness points on the surfaces.
      const double phia = A.signed_distance(qa.conjugate() * r.point_a);
      const double phib = B.signed_distance(qb.conjugate() * (r.point_b - xb));
      CHECK(std::abs(phia) < 1.e-6 && std::abs(phib) < 1.e-6,
            "witness points off the surfaces: "
              << phia << " " << phib << " (distance " << r.distance << ")");
      // Separated pairs: distance of the witness points equals the
      // reported distance, and sampled support pairs are never closer.
      if (r.distance > 0.)
        {
          CHECK(std::abs((r.point_b - r.point_a).norm() - r.distance) < 1.e-9,
                "witness distance");
          for (int k = 0; k < 200; ++k)
            {
              const Eigen::Vector3d d(g(rng), g(rng), g(rng));
              // The support gap along any direction bounds the distance.
              const double sep
                = -(pa.support(d) - pb.support(-d)).dot(d.normalized());
              CHECK(sep <= r.distance + 1.e-9,
                    "support gap " << sep << " exceeds the distance "
                                   << r.distance);
            }
          ++checked;
        }
      else
        {
          // Overlap: moving B by the penetration vector (plus a hair)
          // separates them.
          const auto moved
            = gjk_epa(pa, place(B, xb + (-r.distance + 1.e-6) * r.normal, qb));
          CHECK(moved.distance > 0. && moved.distance < 1.e-4,
                "EPA depth " << -r.distance
                             << " does not separate: after the move "
                             << moved.distance);
          ++checked;
        }
    }
  std::cout << checked << " random convex pairs checked\nOK\n";
  return 0;
}
