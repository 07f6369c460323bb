#include <particulate/geometry/box.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "collide_detail.h"

namespace particulate::rigid::detail {
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
              dmin
                = std::min(dmin, (q.position - pts[i].position).squaredNorm());
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
    const auto           &sa = static_cast<const geometry::Box &>(A.shape());
    const auto           &sb = static_cast<const geometry::Box &>(B.shape());
    const Eigen::Matrix3d Ra = A.rotation(), Rb = B.rotation();
    const Eigen::Vector3d ea = sa.half_extents(), eb = sb.half_extents();
    const Eigen::Vector3d t = B.position - A.position;

    // Separating-axis test over the 15 axes; keep the axis with the largest
    // separation (smallest penetration). Face axes win ties so that resting
    // boxes get face contacts (stable stacking).
    double          best_sep  = -std::numeric_limits<double>::infinity();
    int             best_kind = -1; // 0: face of A, 1: face of B, 2: edge-edge
    int             best_i = 0, best_j = 0;
    Eigen::Vector3d best_axis = Eigen::Vector3d::UnitZ();
    auto            test      = [&](Eigen::Vector3d L, int kind, int i, int j) {
      const double len = L.norm();
      if (len < 1.e-6)
        return;
      L /= len;
      const double ra = ea[0] * std::abs(L.dot(Ra.col(0)))
                        + ea[1] * std::abs(L.dot(Ra.col(1)))
                        + ea[2] * std::abs(L.dot(Ra.col(2)));
      const double rb = eb[0] * std::abs(L.dot(Rb.col(0)))
                        + eb[1] * std::abs(L.dot(Rb.col(1)))
                        + eb[2] * std::abs(L.dot(Rb.col(2)));
      const double sep = std::abs(L.dot(t)) - ra - rb;
      const double tol = kind == 2 ?
                                           1.e-3 * std::min(ea.minCoeff(), eb.minCoeff()) :
                                           1.e-9 * (ea.norm() + eb.norm());
      if (sep > best_sep + tol)
        {
          best_sep  = sep;
          best_kind = kind;
          best_i    = i;
          best_j    = j;
          best_axis = L.dot(t) >= 0. ? L : Eigen::Vector3d(-L);
        }
    };
    for (int i = 0; i < 3; ++i)
      test(Ra.col(i), 0, i, 0);
    for (int j = 0; j < 3; ++j)
      test(Rb.col(j), 1, j, 0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        test(Ra.col(i).cross(Rb.col(j)), 2, i, j);
    if (best_sep > margin || best_kind < 0)
      return;
    const Eigen::Vector3d n = best_axis; // from A to B

    if (best_kind == 2)
      {
        // Edge-edge: the supporting edges and their closest points.
        Eigen::Vector3d pa = A.position, pb = B.position;
        for (int k = 0; k < 3; ++k)
          {
            if (k != best_i)
              pa += (n.dot(Ra.col(k)) >= 0. ? ea[k] : -ea[k]) * Ra.col(k);
            if (k != best_j)
              pb += (n.dot(Rb.col(k)) <= 0. ? eb[k] : -eb[k]) * Rb.col(k);
          }
        const Eigen::Vector3d da = Ra.col(best_i), db = Rb.col(best_j);
        const Eigen::Vector3d r  = pa - pb;
        const double          b_ = da.dot(db), c = da.dot(r), f = db.dot(r);
        const double          den = 1. - b_ * b_;
        double                s   = den > 1.e-12 ? (b_ * f - c) / den : 0.;
        s                         = std::clamp(s, -ea[best_i], ea[best_i]);
        double u = std::clamp(b_ * s + f, -eb[best_j], eb[best_j]);
        s        = std::clamp(b_ * u - c, -ea[best_i], ea[best_i]);
        out.push_back(make_point(A, pa + s * da, pb + u * db, n, best_sep));
        return;
      }

    // Face contact: reference box R (face normal nr pointing towards the
    // other box), incident box I.
    const bool             ref_is_a = best_kind == 0;
    const Eigen::Matrix3d &Rr = ref_is_a ? Ra : Rb, &Ri = ref_is_a ? Rb : Ra;
    const Eigen::Vector3d &er = ref_is_a ? ea : eb, &ei = ref_is_a ? eb : ea;
    const Eigen::Vector3d &cr = ref_is_a ? A.position : B.position,
                          &ci = ref_is_a ? B.position : A.position;
    const Eigen::Vector3d nr  = ref_is_a ? n : Eigen::Vector3d(-n);
    const int             fr  = best_i;
    // Incident face: most anti-parallel to nr.
    int    fi  = 0;
    double dmx = -1.;
    for (int k = 0; k < 3; ++k)
      if (std::abs(nr.dot(Ri.col(k))) > dmx)
        {
          dmx = std::abs(nr.dot(Ri.col(k)));
          fi  = k;
        }
    const double                 sgn = nr.dot(Ri.col(fi)) > 0. ? -1. : 1.;
    const Eigen::Vector3d        fc  = ci + sgn * ei[fi] * Ri.col(fi);
    const int                    u1 = (fi + 1) % 3, u2 = (fi + 2) % 3;
    std::vector<Eigen::Vector3d> poly
      = {fc + ei[u1] * Ri.col(u1) + ei[u2] * Ri.col(u2),
         fc - ei[u1] * Ri.col(u1) + ei[u2] * Ri.col(u2),
         fc - ei[u1] * Ri.col(u1) - ei[u2] * Ri.col(u2),
         fc + ei[u1] * Ri.col(u1) - ei[u2] * Ri.col(u2)};
    // Clip against the four side planes of the reference face.
    const int v1 = (fr + 1) % 3, v2 = (fr + 2) % 3;
    for (const int ax : {v1, v2})
      for (const double side : {1., -1.})
        {
          const Eigen::Vector3d        pn = side * Rr.col(ax);
          const double                 po = pn.dot(cr) + er[ax];
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
            return;
        }
    const Eigen::Vector3d     ref_center = cr + er[fr] * nr;
    std::vector<ContactPoint> pts;
    for (const auto &p : poly)
      {
        const double gap = (p - ref_center).dot(nr); // < 0: inside ref box
        if (gap > margin)
          continue;
        const Eigen::Vector3d on_ref = p - gap * nr;
        pts.push_back(ref_is_a ? make_point(A, on_ref, p, n, gap) :
                                 make_point(A, p, on_ref, n, gap));
      }
    reduce_points(pts, 4);
    out.insert(out.end(), pts.begin(), pts.end());
  }
} // namespace particulate::rigid::detail
