#include <particulate/geometry/box.h>
#include <particulate/rigid/gjk_epa.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "collide_detail.h"

namespace particulate {
  namespace rigid {
    namespace detail {
      namespace {
        /** A box placed in the world: rotation, half-extents and centre. */
        struct PlacedBox
        {
          Eigen::Matrix3d R;
          Eigen::Vector3d e;
          Eigen::Vector3d c;

          explicit PlacedBox(const RigidBody &body)
            : R(body.rotation())
            , e(static_cast<const geometry::Box &>(body.shape()).half_extents())
            , c(body.position)
          {}

          /** Half-width of the box's projection on the unit axis @p L. */
          double
          extent_along(const Eigen::Vector3d &L) const
          {
            return e[0] * std::abs(L.dot(R.col(0)))
                   + e[1] * std::abs(L.dot(R.col(1)))
                   + e[2] * std::abs(L.dot(R.col(2)));
          }
        };



        /** Where a separating axis comes from. */
        enum class AxisKind
        {
          none,
          face_of_a,
          face_of_b,
          edge_of_a_cross_edge_of_b
        };



        /** The separating axis of largest separation (smallest penetration). */
        struct SeparatingAxis
        {
          double   separation = -std::numeric_limits<double>::infinity();
          AxisKind kind       = AxisKind::none;
          /** The face axis (i), or the edge axes of A (i) and B (j). */
          int i = 0, j = 0;
          /** Unit axis from A to B. */
          Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
        };



        /** Separating-axis test over the 15 axes of two boxes. Face axes win
         * ties so that resting boxes get face contacts (stable stacking). */
        SeparatingAxis
        best_separating_axis(const PlacedBox &a, const PlacedBox &b)
        {
          const Eigen::Vector3d t = b.c - a.c;
          SeparatingAxis        best;
          const auto            test
            = [&](Eigen::Vector3d L, AxisKind kind, int i, int j) {
                const double len = L.norm();
                if (len < 1.e-6)
                  return;
                L /= len;
                const double sep
                  = std::abs(L.dot(t)) - a.extent_along(L) - b.extent_along(L);
                const double tol
                  = kind == AxisKind::edge_of_a_cross_edge_of_b ?
                      1.e-3 * std::min(a.e.minCoeff(), b.e.minCoeff()) :
                      1.e-9 * (a.e.norm() + b.e.norm());
                if (sep > best.separation + tol)
                  {
                    best.separation = sep;
                    best.kind       = kind;
                    best.i          = i;
                    best.j          = j;
                    best.axis       = L.dot(t) >= 0. ? L : Eigen::Vector3d(-L);
                  }
              };
          for (int i = 0; i < 3; ++i)
            test(a.R.col(i), AxisKind::face_of_a, i, 0);
          for (int j = 0; j < 3; ++j)
            test(b.R.col(j), AxisKind::face_of_b, j, 0);
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              test(a.R.col(i).cross(b.R.col(j)),
                   AxisKind::edge_of_a_cross_edge_of_b,
                   i,
                   j);
          return best;
        }



        /** Edge-edge contact: the supporting edges and their closest points. */
        ContactPoint
        edge_edge_point(const RigidBody      &A,
                        const PlacedBox      &a,
                        const PlacedBox      &b,
                        const SeparatingAxis &sat)
        {
          const Eigen::Vector3d &n  = sat.axis;
          Eigen::Vector3d        pa = a.c, pb = b.c;
          for (int k = 0; k < 3; ++k)
            {
              if (k != sat.i)
                pa += (n.dot(a.R.col(k)) >= 0. ? a.e[k] : -a.e[k]) * a.R.col(k);
              if (k != sat.j)
                pb += (n.dot(b.R.col(k)) <= 0. ? b.e[k] : -b.e[k]) * b.R.col(k);
            }
          const Eigen::Vector3d da = a.R.col(sat.i), db = b.R.col(sat.j);
          const Eigen::Vector3d r  = pa - pb;
          const double          b_ = da.dot(db), c = da.dot(r), f = db.dot(r);
          const double          den = 1. - b_ * b_;
          double                s   = den > 1.e-12 ? (b_ * f - c) / den : 0.;
          s                         = std::clamp(s, -a.e[sat.i], a.e[sat.i]);
          double u = std::clamp(b_ * s + f, -b.e[sat.j], b.e[sat.j]);
          s        = std::clamp(b_ * u - c, -a.e[sat.i], a.e[sat.i]);
          return make_point(A, pa + s * da, pb + u * db, n, sat.separation);
        }



        /** Face contact: the incident face of one box clipped against the side
         * planes of the other's reference face (Sutherland-Hodgman); the
         * corners of the clipped polygon within the margin. */
        std::vector<ContactPoint>
        clipped_face_points(const RigidBody      &A,
                            const PlacedBox      &a,
                            const PlacedBox      &b,
                            const SeparatingAxis &sat,
                            const double          margin)
        {
          const bool            ref_is_a = sat.kind == AxisKind::face_of_a;
          const PlacedBox      &ref = ref_is_a ? a : b, &inc = ref_is_a ? b : a;
          const Eigen::Vector3d nr
            = ref_is_a ? sat.axis : Eigen::Vector3d(-sat.axis);
          const int fr = sat.i;
          // Incident face: most anti-parallel to nr.
          int    fi  = 0;
          double dmx = -1.;
          for (int k = 0; k < 3; ++k)
            if (std::abs(nr.dot(inc.R.col(k))) > dmx)
              {
                dmx = std::abs(nr.dot(inc.R.col(k)));
                fi  = k;
              }
          const double          sgn = nr.dot(inc.R.col(fi)) > 0. ? -1. : 1.;
          const Eigen::Vector3d fc  = inc.c + sgn * inc.e[fi] * inc.R.col(fi);
          const int             u1 = (fi + 1) % 3, u2 = (fi + 2) % 3;
          const Eigen::Vector3d s1 = inc.e[u1] * inc.R.col(u1),
                                s2 = inc.e[u2] * inc.R.col(u2);
          std::vector<Eigen::Vector3d> poly
            = {fc + s1 + s2, fc - s1 + s2, fc - s1 - s2, fc + s1 - s2};
          const int v1 = (fr + 1) % 3, v2 = (fr + 2) % 3;
          for (const int ax : {v1, v2})
            for (const double side : {1., -1.})
              {
                const Eigen::Vector3d        pn = side * ref.R.col(ax);
                const double                 po = pn.dot(ref.c) + ref.e[ax];
                std::vector<Eigen::Vector3d> clipped;
                for (std::size_t k = 0; k < poly.size(); ++k)
                  {
                    const Eigen::Vector3d &p = poly[k],
                                          &q = poly[(k + 1) % poly.size()];
                    const double dp = pn.dot(p) - po, dq = pn.dot(q) - po;
                    if (dp <= 0.)
                      clipped.push_back(p);
                    if ((dp < 0. && dq > 0.) || (dp > 0. && dq < 0.))
                      clipped.push_back(p + dp / (dp - dq) * (q - p));
                  }
                poly.swap(clipped);
                if (poly.empty())
                  return {};
              }
          const Eigen::Vector3d     ref_center = ref.c + ref.e[fr] * nr;
          std::vector<ContactPoint> pts;
          for (const auto &p : poly)
            {
              const double gap
                = (p - ref_center).dot(nr); // < 0: inside ref box
              if (gap > margin)
                continue;
              const Eigen::Vector3d on_ref = p - gap * nr;
              pts.push_back(ref_is_a ? make_point(A, on_ref, p, sat.axis, gap) :
                                       make_point(A, p, on_ref, sat.axis, gap));
            }
          return pts;
        }



        /**
         * Boxes that are apart. The separation along the best axis only bounds
         * their distance from below, and the reference face need not face the
         * closest features: two boxes corner to corner have no clipped face
         * points at all, however close they come. The exact distance and its
         * witness points come from GJK; a face contact keeps its clipped points
         * (a flat face resting on a flat face needs several), plus the GJK pair
         * where that is closer than all of them.
         */
        std::vector<ContactPoint>
        separated_points(const RigidBody      &A,
                         const RigidBody      &B,
                         const PlacedBox      &a,
                         const PlacedBox      &b,
                         const SeparatingAxis &sat,
                         const double          margin)
        {
          const ConvexPlacement pa{&A.shape(), a.R, a.c};
          const ConvexPlacement pb{&B.shape(), b.R, b.c};
          const ConvexDistance  r = gjk_epa(pa, pb, sat.axis);
          if (r.distance > margin)
            return {};
          std::vector<ContactPoint> pts;
          if (sat.kind != AxisKind::edge_of_a_cross_edge_of_b)
            pts = clipped_face_points(A, a, b, sat, margin);
          double closest = std::numeric_limits<double>::infinity();
          for (const ContactPoint &c : pts)
            closest = std::min(closest, c.distance);
          const double tol = 1.e-3 * std::min(a.e.minCoeff(), b.e.minCoeff());
          if (r.distance < closest - tol)
            pts.push_back(
              make_point(A, r.point_a, r.point_b, r.normal, r.distance));
          return pts;
        }
      } // namespace



      void
      reduce_points(std::vector<ContactPoint> &pts, const unsigned int n)
      {
        if (pts.size() <= n)
          return;
        std::vector<ContactPoint> keep;
        auto                      take = [&](const std::size_t i) {
          keep.push_back(pts[i]);
          pts.erase(pts.begin() + i);
        };
        // Deepest point first.
        std::size_t best = 0;
        for (std::size_t i = 1; i < pts.size(); ++i)
          if (pts[i].distance < pts[best].distance)
            best = i;
        take(best);
        // Then repeatedly the point furthest from the ones kept.
        while (keep.size() < n && !pts.empty())
          {
            double      far = -1.;
            std::size_t k   = 0;
            for (std::size_t i = 0; i < pts.size(); ++i)
              {
                double dmin = std::numeric_limits<double>::infinity();
                for (const auto &q : keep)
                  dmin = std::min(dmin,
                                  (q.position - pts[i].position).squaredNorm());
                if (dmin > far)
                  {
                    far = dmin;
                    k   = i;
                  }
              }
            take(k);
          }
        pts.swap(keep);
      }



      void
      box_box(const RigidBody           &A,
              const RigidBody           &B,
              const double               margin,
              std::vector<ContactPoint> &out)
      {
        const PlacedBox      a(A), b(B);
        const SeparatingAxis sat = best_separating_axis(a, b);
        if (sat.separation > margin || sat.kind == AxisKind::none)
          return;
        std::vector<ContactPoint> pts;
        if (sat.separation > 0.)
          pts = separated_points(A, B, a, b, sat, margin);
        else if (sat.kind == AxisKind::edge_of_a_cross_edge_of_b)
          pts.push_back(edge_edge_point(A, a, b, sat));
        else
          pts = clipped_face_points(A, a, b, sat, margin);
        reduce_points(pts, 4);
        out.insert(out.end(), pts.begin(), pts.end());
      }
    } // namespace detail
  }   // namespace rigid
} // namespace particulate
