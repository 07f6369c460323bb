#include <particulate/rigid/gjk_epa.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <vector>

namespace particulate {
  namespace rigid {
    namespace {
      /** A vertex of the Minkowski difference A - B with its origins. */
      struct Vertex
      {
        Eigen::Vector3d w, a, b;
      };

      Vertex
      support(const ConvexPlacement &A,
              const ConvexPlacement &B,
              const Eigen::Vector3d &d)
      {
        Vertex v;
        v.a = A.support(d);
        v.b = B.support(-d);
        v.w = v.a - v.b;
        return v;
      }

      /** The simplex with barycentric weights of its closest point. */
      struct Simplex
      {
        std::array<Vertex, 4> v;
        std::array<double, 4> lambda{};
        int                   n = 0;

        Eigen::Vector3d
        closest() const
        {
          Eigen::Vector3d p = Eigen::Vector3d::Zero();
          for (int i = 0; i < n; ++i)
            p += lambda[i] * v[i].w;
          return p;
        }
        void
        keep(std::initializer_list<std::pair<int, double>> items)
        {
          std::array<Vertex, 4> nv = v;
          int                   k  = 0;
          for (const auto &it : items)
            {
              nv[k]     = v[it.first];
              lambda[k] = it.second;
              ++k;
            }
          v = nv;
          n = k;
        }
      };

      /** Closest point of a segment to the origin (reduces the simplex). */
      void
      solve2(Simplex &s)
      {
        const Eigen::Vector3d a = s.v[0].w, b = s.v[1].w, ab = b - a;
        const double t = -a.dot(ab) / std::max(ab.squaredNorm(), 1.e-300);
        if (t <= 0.)
          s.keep({{0, 1.}});
        else if (t >= 1.)
          s.keep({{1, 1.}});
        else
          s.keep({{0, 1. - t}, {1, t}});
      }

      /** Closest point of a triangle to the origin (Ericson, RTCD §5.1.5). */
      void
      solve3(Simplex &s, const int i0 = 0, const int i1 = 1, const int i2 = 2)
      {
        const Eigen::Vector3d a = s.v[i0].w, b = s.v[i1].w, c = s.v[i2].w;
        const Eigen::Vector3d ab = b - a, ac = c - a;
        const double          d1 = -ab.dot(a), d2 = -ac.dot(a);
        if (d1 <= 0. && d2 <= 0.)
          return s.keep({{i0, 1.}});
        const double d3 = -ab.dot(b), d4 = -ac.dot(b);
        if (d3 >= 0. && d4 <= d3)
          return s.keep({{i1, 1.}});
        const double vc = d1 * d4 - d3 * d2;
        if (vc <= 0. && d1 >= 0. && d3 <= 0.)
          {
            const double t = d1 / (d1 - d3);
            return s.keep({{i0, 1. - t}, {i1, t}});
          }
        const double d5 = -ab.dot(c), d6 = -ac.dot(c);
        if (d6 >= 0. && d5 <= d6)
          return s.keep({{i2, 1.}});
        const double vb = d5 * d2 - d1 * d6;
        if (vb <= 0. && d2 >= 0. && d6 <= 0.)
          {
            const double t = d2 / (d2 - d6);
            return s.keep({{i0, 1. - t}, {i2, t}});
          }
        const double va = d3 * d6 - d5 * d4;
        if (va <= 0. && (d4 - d3) >= 0. && (d5 - d6) >= 0.)
          {
            const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            return s.keep({{i1, 1. - t}, {i2, t}});
          }
        const double den = 1. / (va + vb + vc);
        const double v = vb * den, w = vc * den;
        s.keep({{i0, 1. - v - w}, {i1, v}, {i2, w}});
      }

      /** Closest point of a tetrahedron to the origin; returns true when the
       * origin is inside (the simplex is then left unchanged). */
      bool
      solve4(Simplex &s)
      {
        const int faces[4][4]
          = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
        double  best = std::numeric_limits<double>::infinity();
        Simplex best_s;
        bool    outside_any = false;
        for (const auto &f : faces)
          {
            const Eigen::Vector3d a = s.v[f[0]].w, b = s.v[f[1]].w,
                                  c = s.v[f[2]].w, d = s.v[f[3]].w;
            const Eigen::Vector3d n  = (b - a).cross(c - a);
            const double          so = -a.dot(n), sd = (d - a).dot(n);
            // Origin on the other side of the face plane than the 4th vertex,
            // or a degenerate (flat) tetrahedron: examine this face.
            if (so * sd < 0.
                || std::abs(sd) < 1.e-14 * n.norm() * (d - a).norm() + 1.e-300)
              {
                outside_any = true;
                Simplex t   = s;
                solve3(t, f[0], f[1], f[2]);
                const double dist = t.closest().squaredNorm();
                if (dist < best)
                  {
                    best   = dist;
                    best_s = t;
                  }
              }
          }
        if (!outside_any)
          {
            // Inside: barycentric weights do not matter for EPA.
            return true;
          }
        s = best_s;
        return false;
      }

      /** EPA on a tetrahedron that contains the origin. */
      bool
      epa(const ConvexPlacement &A,
          const ConvexPlacement &B,
          std::vector<Vertex>    verts,
          ConvexDistance        &out)
      {
        struct Face
        {
          int             i, j, k;
          Eigen::Vector3d n;
          double          d;
          bool            alive;
        };
        Eigen::Vector3d inner = Eigen::Vector3d::Zero();
        for (const auto &v : verts)
          inner += v.w;
        inner /= verts.size();
        std::vector<Face> faces;
        auto              make_face = [&](int i, int j, int k) {
          Eigen::Vector3d n
            = (verts[j].w - verts[i].w).cross(verts[k].w - verts[i].w);
          const double nn = n.norm();
          if (!(nn > 1.e-300))
            return false;
          n /= nn;
          if (n.dot(verts[i].w - inner) < 0.)
            {
              n = -n;
              std::swap(j, k);
            }
          faces.push_back({i, j, k, n, n.dot(verts[i].w), true});
          return true;
        };
        if (!make_face(0, 1, 2) || !make_face(0, 1, 3) || !make_face(0, 2, 3)
            || !make_face(1, 2, 3))
          return false;
        double scale = 0.;
        for (const auto &v : verts)
          scale = std::max(scale, v.w.norm());
        const double tol = 1.e-7 * std::max(scale, 1.e-300);

        for (int iter = 0; iter < 64; ++iter)
          {
            int best = -1;
            for (unsigned int f = 0; f < faces.size(); ++f)
              if (faces[f].alive && (best < 0 || faces[f].d < faces[best].d))
                best = f;
            if (best < 0)
              return false;
            const Face   F = faces[best];
            const Vertex s = support(A, B, F.n);
            if (s.w.dot(F.n) - F.d < tol || iter == 63)
              {
                // Barycentric coordinates of the origin's projection.
                const Eigen::Vector3d p = F.d * F.n;
                const Eigen::Vector3d a = verts[F.i].w, b = verts[F.j].w,
                                      c  = verts[F.k].w;
                const Eigen::Vector3d v0 = b - a, v1 = c - a, v2 = p - a;
                const double          d00 = v0.dot(v0), d01 = v0.dot(v1),
                             d11 = v1.dot(v1), d20 = v2.dot(v0),
                             d21 = v2.dot(v1);
                const double den = d00 * d11 - d01 * d01;
                double       l1 = 1. / 3., l2 = 1. / 3.;
                if (std::abs(den) > 1.e-300)
                  {
                    l1 = (d11 * d20 - d01 * d21) / den;
                    l2 = (d00 * d21 - d01 * d20) / den;
                  }
                const double l0 = 1. - l1 - l2;
                out.point_a
                  = l0 * verts[F.i].a + l1 * verts[F.j].a + l2 * verts[F.k].a;
                out.point_b
                  = l0 * verts[F.i].b + l1 * verts[F.j].b + l2 * verts[F.k].b;
                out.normal    = F.n;
                out.distance  = -F.d;
                out.converged = iter < 63;
                return true;
              }
            // Remove the faces that see the new vertex and stitch the horizon.
            const int                        id = verts.size();
            std::vector<std::pair<int, int>> edges;
            for (auto &f : faces)
              if (f.alive && f.n.dot(s.w - verts[f.i].w) > 0.)
                {
                  f.alive = false;
                  for (auto e : {std::make_pair(f.i, f.j),
                                 std::make_pair(f.j, f.k),
                                 std::make_pair(f.k, f.i)})
                    {
                      bool found = false;
                      for (auto it = edges.begin(); it != edges.end(); ++it)
                        if (it->first == e.second && it->second == e.first)
                          {
                            edges.erase(it);
                            found = true;
                            break;
                          }
                      if (!found)
                        edges.push_back(e);
                    }
                }
            verts.push_back(s);
            for (const auto &e : edges)
              make_face(e.first, e.second, id);
          }
        return false;
      }
    } // namespace



    namespace {
      ConvexDistance
      gjk_epa_full(const ConvexPlacement &A,
                   const ConvexPlacement &B,
                   const Eigen::Vector3d &guess,
                   const bool             penetration);
    }



    ConvexDistance
    gjk_epa(const ConvexPlacement &A,
            const ConvexPlacement &B,
            const Eigen::Vector3d &guess)
    {
      // Round shapes: distance between the cores minus the radii, exact for
      // shallow overlaps; EPA on the full shapes only when the cores touch.
      const double ca = A.shape->core_radius(), cb = B.shape->core_radius();
      if (ca > 0. || cb > 0.)
        {
          ConvexPlacement Ac = A, Bc = B;
          Ac.shrink        = ca;
          Bc.shrink        = cb;
          ConvexDistance r = gjk_epa_full(Ac, Bc, guess, false);
          if (r.converged && r.distance > 1.e-12 * (ca + cb))
            {
              r.point_a += ca * r.normal;
              r.point_b -= cb * r.normal;
              r.distance -= ca + cb;
              return r;
            }
        }
      return gjk_epa_full(A, B, guess, true);
    }



    namespace {
      ConvexDistance
      gjk_epa_full(const ConvexPlacement &A,
                   const ConvexPlacement &B,
                   const Eigen::Vector3d &guess,
                   const bool             penetration)
      {
        ConvexDistance  out;
        Eigen::Vector3d d = guess.squaredNorm() > 0. ?
                              guess :
                              Eigen::Vector3d(B.position - A.position);
        if (!(d.squaredNorm() > 0.))
          d = Eigen::Vector3d::UnitZ();
        // Search along -v where v = a - b is the current closest point: start
        // with the vertex furthest in the direction from B to A.
        Simplex s;
        s.v[0]                  = support(A, B, -d);
        s.lambda[0]             = 1.;
        s.n                     = 1;
        Eigen::Vector3d v       = s.v[0].w;
        double          scale   = std::max(v.norm(), 1.e-300);
        bool            overlap = false;
        double          prev    = std::numeric_limits<double>::infinity();
        unsigned int    it      = 0;
        for (; it < 64; ++it)
          {
            const double vv = v.squaredNorm();
            if (vv <= 1.e-24 * scale * scale)
              {
                overlap = true;
                break;
              }
            const Vertex w = support(A, B, -v);
            scale          = std::max(scale, w.w.norm());
            if (vv - v.dot(w.w) <= 1.e-12 * vv)
              break;
            bool dup = false;
            for (int i = 0; i < s.n; ++i)
              dup |= (s.v[i].w - w.w).squaredNorm() <= 1.e-28 * scale * scale;
            if (dup)
              break;
            s.v[s.n]      = w;
            s.lambda[s.n] = 0.;
            ++s.n;
            if (s.n == 2)
              solve2(s);
            else if (s.n == 3)
              solve3(s);
            else if (solve4(s))
              {
                overlap = true;
                break;
              }
            v               = s.closest();
            const double nv = v.squaredNorm();
            if (nv >= prev)
              break; // no progress: numerically converged
            prev = nv;
          }
        out.iterations = it;

        if (!overlap)
          {
            out.point_a = Eigen::Vector3d::Zero();
            out.point_b = Eigen::Vector3d::Zero();
            for (int i = 0; i < s.n; ++i)
              {
                out.point_a += s.lambda[i] * s.v[i].a;
                out.point_b += s.lambda[i] * s.v[i].b;
              }
            const double dist = v.norm();
            out.distance      = dist;
            out.normal        = dist > 0. ? Eigen::Vector3d(-v / dist) :
                                            Eigen::Vector3d(d.normalized());
            return out;
          }

        if (!penetration)
          {
            out.converged = false;
            out.distance  = 0.;
            return out;
          }
        // Overlap: blow the simplex up to a tetrahedron around the origin.
        std::vector<Vertex>   verts(s.v.begin(), s.v.begin() + s.n);
        const Eigen::Vector3d axes[6]    = {Eigen::Vector3d::UnitX(),
                                            Eigen::Vector3d::UnitY(),
                                            Eigen::Vector3d::UnitZ(),
                                            -Eigen::Vector3d::UnitX(),
                                            -Eigen::Vector3d::UnitY(),
                                            -Eigen::Vector3d::UnitZ()};
        auto                  add_if_new = [&](const Eigen::Vector3d &dir) {
          const Vertex w = support(A, B, dir);
          for (const auto &x : verts)
            if ((x.w - w.w).squaredNorm() <= 1.e-20 * scale * scale)
              return false;
          verts.push_back(w);
          return true;
        };
        if (verts.size() == 1)
          for (const auto &ax : axes)
            if (add_if_new(ax))
              break;
        if (verts.size() == 2)
          {
            const Eigen::Vector3d e = verts[1].w - verts[0].w;
            int                   k;
            e.cwiseAbs().minCoeff(&k);
            Eigen::Vector3d t       = Eigen::Vector3d::Zero();
            t[k]                    = 1.;
            const Eigen::Vector3d p = e.cross(t).normalized();
            for (int r = 0; r < 6 && verts.size() == 2; ++r)
              add_if_new(Eigen::AngleAxisd(r * M_PI / 3., e.normalized()) * p);
          }
        if (verts.size() == 3)
          {
            const Eigen::Vector3d n
              = (verts[1].w - verts[0].w).cross(verts[2].w - verts[0].w);
            if (!add_if_new(n))
              add_if_new(-n);
          }
        if (verts.size() == 4)
          {
            if (epa(A, B, verts, out))
              return out;
          }
        // Fallback (degenerate polytope): centre-to-centre normal, zero depth.
        out.converged = false;
        out.normal    = (B.position - A.position).normalized();
        if (!out.normal.allFinite())
          out.normal = Eigen::Vector3d::UnitZ();
        out.point_a  = A.support(out.normal);
        out.point_b  = B.support(-out.normal);
        out.distance = (out.point_b - out.point_a).dot(out.normal);
        return out;
      }
    } // namespace
  }   // namespace rigid
} // namespace particulate
