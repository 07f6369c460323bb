#include <particulate/geometry/box.h>
#include <particulate/geometry/capsule.h>
#include <particulate/geometry/half_space.h>
#include <particulate/geometry/sphere.h>
#include <particulate/rigid/gjk_epa.h>
#include <particulate/rigid/narrow_phase.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "collide_detail.h"

namespace particulate {
  namespace rigid {
    namespace {
      using detail::make_point;
      using Points = std::vector<ContactPoint>;

      /** Radius of a sphere body. */
      double
      sphere_radius(const RigidBody &S)
      {
        return static_cast<const geometry::Sphere &>(S.shape()).radius();
      }

      /** World plane n . x = c of a half-space body. */
      void
      world_plane(const RigidBody &H, Eigen::Vector3d &n, double &c)
      {
        const auto &hs = static_cast<const geometry::HalfSpace &>(H.shape());
        n              = H.orientation * hs.normal();
        c              = hs.offset() + n.dot(H.position);
      }

      /** Sphere (centre ca, radius ra, body A) against sphere (cb, rb). */
      void
      sphere_sphere(const RigidBody       &A,
                    const Eigen::Vector3d &ca,
                    const double           ra,
                    const Eigen::Vector3d &cb,
                    const double           rb,
                    const double           margin,
                    Points                &out)
      {
        const Eigen::Vector3d d    = cb - ca;
        const double          dist = d.norm();
        const double          gap  = dist - ra - rb;
        if (gap > margin)
          return;
        const Eigen::Vector3d n
          = dist > 0. ? Eigen::Vector3d(d / dist) : Eigen::Vector3d::UnitZ();
        out.push_back(make_point(A, ca + ra * n, cb - rb * n, n, gap));
      }

      /** Point-like feature with radius r of body A against the plane of the
       * half-space body (which is B). */
      void
      sphere_plane(const RigidBody       &A,
                   const Eigen::Vector3d &c,
                   const double           r,
                   const Eigen::Vector3d &n_plane,
                   const double           offset,
                   const double           margin,
                   Points                &out)
      {
        const double gap = n_plane.dot(c) - offset - r;
        if (gap > margin)
          return;
        // Normal from A (above the plane) to B (the solid below): -n_plane.
        out.push_back(make_point(A,
                                 c - r * n_plane,
                                 c - (r + gap) * n_plane,
                                 -n_plane,
                                 gap));
      }

      void
      sphere_box(const RigidBody &A,
                 const RigidBody &B,
                 const double     margin,
                 Points          &out)
      {
        const double          r = sphere_radius(A);
        const Eigen::Vector3d e
          = static_cast<const geometry::Box &>(B.shape()).half_extents();
        const Eigen::Vector3d c = B.to_body(A.position);
        const Eigen::Vector3d q = c.cwiseMax(-e).cwiseMin(e);
        Eigen::Vector3d       nb; // box -> sphere, body frame of B
        Eigen::Vector3d       on_box;
        double                gap;
        if ((c - q).squaredNorm() > 0.)
          {
            const double d = (c - q).norm();
            nb             = (c - q) / d;
            on_box         = q;
            gap            = d - r;
          }
        else
          {
            const Eigen::Vector3d depth = e - c.cwiseAbs();
            int                   k;
            depth.minCoeff(&k);
            nb        = Eigen::Vector3d::Zero();
            nb[k]     = c[k] >= 0. ? 1. : -1.;
            on_box    = c;
            on_box[k] = nb[k] * e[k];
            gap       = -depth[k] - r;
          }
        if (gap > margin)
          return;
        const Eigen::Vector3d n = -(B.orientation * nb); // sphere -> box
        out.push_back(
          make_point(A, A.position + r * n, B.to_world(on_box), n, gap));
      }

      /** The core segment of a capsule in world coordinates. */
      void
      capsule_segment(const RigidBody &C,
                      Eigen::Vector3d &p,
                      Eigen::Vector3d &q,
                      double          &r)
      {
        const auto &cs = static_cast<const geometry::Capsule &>(C.shape());
        p              = C.to_world(Eigen::Vector3d(0., 0., -cs.half_length()));
        q              = C.to_world(Eigen::Vector3d(0., 0., cs.half_length()));
        r              = cs.radius();
      }

      void
      sphere_capsule(const RigidBody &A,
                     const RigidBody &B,
                     const double     margin,
                     Points          &out)
      {
        Eigen::Vector3d p, q;
        double          rb;
        capsule_segment(B, p, q, rb);
        const Eigen::Vector3d pq = q - p;
        const double          t  = std::clamp((A.position - p).dot(pq)
                                      / std::max(pq.squaredNorm(), 1.e-300),
                                    0.,
                                    1.);
        sphere_sphere(A,
                      A.position,
                      sphere_radius(A),
                      p + t * pq,
                      rb,
                      margin,
                      out);
      }

      void
      box_plane(const RigidBody &A,
                const RigidBody &H,
                const double     margin,
                Points          &out)
      {
        Eigen::Vector3d n;
        double          off;
        world_plane(H, n, off);
        const Eigen::Vector3d e
          = static_cast<const geometry::Box &>(A.shape()).half_extents();
        Points pts;
        for (int i = -1; i <= 1; i += 2)
          for (int j = -1; j <= 1; j += 2)
            for (int k = -1; k <= 1; k += 2)
              sphere_plane(A,
                           A.to_world(e.cwiseProduct(Eigen::Vector3d(i, j, k))),
                           0.,
                           n,
                           off,
                           margin,
                           pts);
        detail::reduce_points(pts, 4);
        out.insert(out.end(), pts.begin(), pts.end());
      }

      void
      capsule_plane(const RigidBody &A,
                    const RigidBody &H,
                    const double     margin,
                    Points          &out)
      {
        Eigen::Vector3d n, p, q;
        double          off, r;
        world_plane(H, n, off);
        capsule_segment(A, p, q, r);
        sphere_plane(A, p, r, n, off, margin, out);
        sphere_plane(A, q, r, n, off, margin, out);
      }

      /** Any convex shape against a plane: the support point against the
       * plane normal, plus support points in a fan of 8 directions tilted by
       * ~17 degrees, which finds the rim of a flat face (reduced contact
       * set for cylinders, §3.4.1 and Fig. 3.20). */
      void
      convex_plane(const RigidBody &A,
                   const RigidBody &H,
                   const double     margin,
                   Points          &out)
      {
        Eigen::Vector3d n;
        double          off;
        world_plane(H, n, off);
        const Eigen::Matrix3d R  = A.rotation();
        const Eigen::Vector3d nb = R.transpose() * (-n);
        Eigen::Vector3d       t1 = nb.unitOrthogonal(), t2 = nb.cross(t1);
        Points                pts;
        auto                  add = [&](const Eigen::Vector3d &dir) {
          const Eigen::Vector3d p = A.to_world(A.shape().support(dir));
          const double          gap = n.dot(p) - off;
          if (gap > margin)
            return;
          for (const auto &c : pts)
            if ((c.local_a - A.to_body(p)).squaredNorm()
                < 1.e-12 * A.bounding_radius() * A.bounding_radius())
              return;
          pts.push_back(make_point(A, p, p - gap * n, -n, gap));
        };
        add(nb);
        for (int k = 0; k < 8; ++k)
          {
            const double a = 2. * M_PI * k / 8.;
            add(nb + 0.3 * (std::cos(a) * t1 + std::sin(a) * t2));
          }
        detail::reduce_points(pts, 4);
        out.insert(out.end(), pts.begin(), pts.end());
      }

      void
      convex_convex(const RigidBody &A,
                    const RigidBody &B,
                    const double     margin,
                    ContactEdge     &edge,
                    Points          &out)
      {
        const ConvexPlacement pa{&A.shape(), A.rotation(), A.position};
        const ConvexPlacement pb{&B.shape(), B.rotation(), B.position};
        const ConvexDistance  r = gjk_epa(pa, pb, edge.gjk_direction);
        edge.gjk_direction      = r.normal;
        if (r.distance > margin)
          return;
        Points pts;
        pts.push_back(
          make_point(A, r.point_a, r.point_b, r.normal, r.distance));
        // GJK/EPA give one point; a flat face resting on another needs the
        // reduced contact set of its rim (Fig. 3.20). Tilt A by a small angle
        // about four axes perpendicular to the normal, query again and map
        // the witness on A back to the untilted body (Bullet's perturbation
        // approach); gaps are measured along the original normal.
        const Eigen::Vector3d n   = r.normal;
        const Eigen::Vector3d t1  = n.unitOrthogonal();
        const double          ang = 0.05;
        for (int k = 0; k < 4; ++k)
          {
            const Eigen::Vector3d axis
              = Eigen::AngleAxisd(k * M_PI / 2., n) * t1;
            const Eigen::Matrix3d Q
              = Eigen::AngleAxisd(ang, axis).toRotationMatrix();
            ConvexPlacement tilted  = pa;
            tilted.rotation         = Q * pa.rotation;
            const ConvexDistance  s = gjk_epa(tilted, pb, n);
            const Eigen::Vector3d on_a
              = A.position + Q.transpose() * (s.point_a - A.position);
            const double gap = (s.point_b - on_a).dot(n);
            if (gap > margin)
              continue;
            const Eigen::Vector3d on_b = on_a + gap * n;
            bool                  dup  = false;
            for (const auto &c : pts)
              dup
                |= (c.position - 0.5 * (on_a + on_b)).norm()
                   < 1.e-3 * std::min(A.bounding_radius(), B.bounding_radius());
            if (!dup)
              pts.push_back(make_point(A, on_a, on_b, n, gap));
          }
        detail::reduce_points(pts, 4);
        out.insert(out.end(), pts.begin(), pts.end());
      }

      /** Surface samples of @p P tested against the signed distance of @p Q.
       * @p flip: whether P is body b of the pair (normals then reversed). */
      void
      sample_against(const RigidBody &first,
                     const RigidBody &P,
                     const RigidBody &Q,
                     const bool       flip,
                     const double     margin,
                     Points          &out)
      {
        const Eigen::Matrix3d       RQ  = Q.rotation();
        const geometry::BoundingBox box = Q.shape().bounding_box();
        for (const Eigen::Vector3d &pb : P.shape().surface_points())
          {
            const Eigen::Vector3d p  = P.to_world(pb);
            const Eigen::Vector3d pq = Q.to_body(p);
            // Q lies in its box: a point farther than the margin from the
            // box is farther from Q (and its distance query, beyond a
            // distance map's grid an exact one, is not needed)
            if ((box.lower - pq).cwiseMax(pq - box.upper).cwiseMax(0.).norm()
                > margin)
              continue;
            Eigen::Vector3d gq;
            const double    gap = Q.shape().signed_distance(pq, &gq);
            if (gap > margin)
              continue;
            const Eigen::Vector3d g  = RQ * gq;     // out of Q
            const Eigen::Vector3d on = p - gap * g; // on Q
            // Normal from P to Q is -g.
            if (!flip)
              out.push_back(make_point(first, p, on, -g, gap));
            else
              out.push_back(make_point(first, on, p, g, gap));
          }
      }
    } // namespace



    unsigned int
    NarrowPhase::collide(const RigidBody &a,
                         const RigidBody &b,
                         const double     margin,
                         ContactEdge     &edge)
    {
      Points &out = edge.manifold.points;
      out.clear();
      const bool       swap = a.shape().kind() > b.shape().kind();
      const RigidBody &A = swap ? b : a, &B = swap ? a : b;
      using T    = geometry::ShapeKind;
      const T ta = A.shape().kind(), tb = B.shape().kind();

      if (ta == T::sphere && tb == T::sphere)
        sphere_sphere(A,
                      A.position,
                      sphere_radius(A),
                      B.position,
                      sphere_radius(B),
                      margin,
                      out);
      else if (ta == T::sphere && tb == T::box)
        sphere_box(A, B, margin, out);
      else if (ta == T::sphere && tb == T::capsule)
        sphere_capsule(A, B, margin, out);
      else if (tb == T::half_space && ta == T::half_space)
        ; // two walls never collide
      else if (ta == T::sphere && tb == T::half_space)
        {
          Eigen::Vector3d n;
          double          off;
          world_plane(B, n, off);
          sphere_plane(A, A.position, sphere_radius(A), n, off, margin, out);
        }
      else if (ta == T::box && tb == T::box)
        detail::box_box(A, B, margin, out);
      else if (ta == T::box && tb == T::half_space)
        box_plane(A, B, margin, out);
      else if (ta == T::capsule && tb == T::half_space)
        capsule_plane(A, B, margin, out);
      else if (ta == T::sphere && tb == T::general)
        {
          // Exact for a sphere: its centre against the distance field. Kept
          // for convex general shapes too, rather than GJK/EPA: the distance
          // of the centre minus r is the exact gap and depth whenever the
          // shape's signed distance is exact, and its normal is the exact
          // gradient, where EPA's would carry the polytope tolerance.
          const double          r  = sphere_radius(A);
          const Eigen::Vector3d pq = B.to_body(A.position);
          Eigen::Vector3d       gb;
          const double          gap = B.shape().signed_distance(pq, &gb) - r;
          if (gap <= margin)
            {
              const Eigen::Vector3d g = B.rotation() * gb;
              out.push_back(make_point(A,
                                       A.position - r * g,
                                       A.position - (r + gap) * g,
                                       -g,
                                       gap));
            }
        }
      else if ((ta == T::general && !A.shape().is_convex())
               || (tb == T::general && !B.shape().is_convex()))
        {
          // Surface points of each body against the other's distance
          // function (a half-space has no surface points of its own).
          sample_against(A, A, B, false, margin, out);
          if (tb != T::half_space)
            sample_against(A, B, A, true, margin, out);
          detail::reduce_points(out, 8);
        }
      // Every other pair is convex, general shapes with a support function
      // (e.g. the elliptic cylinder) included.
      else if (tb == T::half_space)
        convex_plane(A, B, margin, out);
      else
        convex_convex(A, B, margin, edge, out);

      if (swap)
        for (auto &c : out)
          {
            // Points were generated with A = b: flip normals and re-anchor
            // the cache key on body a.
            c.normal  = -c.normal;
            c.local_a = a.to_body(c.position - 0.5 * c.distance * c.normal);
          }
      return out.size();
    }
  } // namespace rigid
} // namespace particulate
