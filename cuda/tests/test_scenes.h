// Test and benchmark data built in place, so that nothing needs CGAL: analytic
// signed distances (sphere, box, torus) sampled onto distance maps, inner-
// sphere sets carved from them, random sphere packs, random poses and points.
#ifndef particulate_cuda_tests_test_scenes_h
#define particulate_cuda_tests_test_scenes_h

#include <particulate/cuda/containment_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <vector>

namespace particulate {
  namespace cuda {
    namespace testing {
      /** A signed distance function of a body-frame point [m]. */
      using Sdf = std::function<double(double, double, double)>;

      inline Sdf
      sphere_sdf(const double radius)
      {
        return [=](double x, double y, double z) {
          return std::sqrt(x * x + y * y + z * z) - radius;
        };
      }

      /** Box with half-widths a, b, c, centred at the origin. */
      inline Sdf
      box_sdf(const double a, const double b, const double c)
      {
        return [=](double x, double y, double z) {
          const double qx = std::abs(x) - a, qy = std::abs(y) - b,
                       qz = std::abs(z) - c;
          const double ox = std::max(qx, 0.), oy = std::max(qy, 0.),
                       oz = std::max(qz, 0.);
          return std::sqrt(ox * ox + oy * oy + oz * oz)
                 + std::min(std::max({qx, qy, qz}), 0.);
        };
      }

      /** Torus around the z axis: ring radius R, tube radius r. */
      inline Sdf
      torus_sdf(const double R, const double r)
      {
        return [=](double x, double y, double z) {
          const double q = std::sqrt(x * x + y * y) - R;
          return std::sqrt(q * q + z * z) - r;
        };
      }

      /**
       * Ellipsoid with semi-axes a, b, c: Quilez's first-order estimate
       * k0 (k0 - 1) / k1, exact on the surface and of the right sign
       * everywhere (a stand-in for the exact distance a CGAL map would hold).
       */
      inline Sdf
      ellipsoid_sdf(const double a, const double b, const double c)
      {
        return [=](double x, double y, double z) {
          const double k0
            = std::sqrt(x * x / (a * a) + y * y / (b * b) + z * z / (c * c));
          const double k1
            = std::sqrt(x * x / (a * a * a * a) + y * y / (b * b * b * b)
                        + z * z / (c * c * c * c));
          if (k1 == 0.)
            return -std::min({a, b, c});
          return k0 * (k0 - 1.) / k1;
        };
      }

      /** Capsule: the segment p q thickened by r. */
      inline Sdf
      capsule_sdf(const std::array<double, 3> p,
                  const std::array<double, 3> q,
                  const double                r)
      {
        return [=](double x, double y, double z) {
          const double e[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
          const double w[3] = {x - p[0], y - p[1], z - p[2]};
          const double s
            = std::min(1.,
                       std::max(0.,
                                (w[0] * e[0] + w[1] * e[1] + w[2] * e[2])
                                  / (e[0] * e[0] + e[1] * e[1] + e[2] * e[2])));
          const double d[3]
            = {w[0] - s * e[0], w[1] - s * e[1], w[2] - s * e[2]};
          return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - r;
        };
      }

      /**
       * A non-convex "elephant-like" body of length about 2 s along x: an
       * ellipsoidal trunk of the body, a head, a curled trunk and four legs
       * (the union of the parts, the minimum of their distances).
       */
      inline Sdf
      elephant_sdf(const double s)
      {
        std::vector<Sdf> parts;
        const Sdf        torso = ellipsoid_sdf(0.55 * s, 0.32 * s, 0.3 * s);
        parts.push_back([=](double x, double y, double z) {
          return torso(x + 0.1 * s, y, z - 0.1 * s);
        });
        const Sdf head = sphere_sdf(0.22 * s);
        parts.push_back([=](double x, double y, double z) {
          return head(x - 0.5 * s, y, z - 0.25 * s);
        });
        parts.push_back(capsule_sdf({0.65 * s, 0., 0.2 * s},
                                    {0.8 * s, 0., -0.15 * s},
                                    0.07 * s));
        parts.push_back(capsule_sdf({0.8 * s, 0., -0.15 * s},
                                    {0.9 * s, 0., -0.35 * s},
                                    0.05 * s));
        for (const double lx : {-0.45, 0.2})
          for (const double ly : {-0.17, 0.17})
            parts.push_back(capsule_sdf({lx * s, ly * s, 0.},
                                        {lx * s, ly * s, -0.4 * s},
                                        0.1 * s));
        return [=](double x, double y, double z) {
          double d = HUGE_VAL;
          for (const Sdf &f : parts)
            d = std::min(d, f(x, y, z));
          return d;
        };
      }

      /**
       * Samples sdf on a grid of spacing h over the box [-half, half]
       * (per axis, body frame), rounded up to whole cells: a map of an
       * elongated body as the geometry module builds it (a bounding box with
       * a margin, the same spacing along every axis).
       */
      inline DistanceMapData
      sample_map_box(const Sdf                  &sdf,
                     const std::array<double, 3> half,
                     const double                h)
      {
        DistanceMapData m;
        int             n[3];
        for (int a = 0; a < 3; ++a)
          {
            n[a]         = 1 + static_cast<int>(std::ceil(2. * half[a] / h));
            m.origin[a]  = static_cast<float>(-0.5 * (n[a] - 1) * h);
            m.spacing[a] = static_cast<float>(h);
          }
        m.nx = n[0];
        m.ny = n[1];
        m.nz = n[2];
        m.values.resize(std::size_t(n[0]) * n[1] * n[2]);
        for (int k = 0; k < n[2]; ++k)
          for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i)
              m.values[i + std::size_t(n[0]) * (j + std::size_t(n[1]) * k)]
                = static_cast<float>(
                  sdf(double(m.origin[0]) + i * double(m.spacing[0]),
                      double(m.origin[1]) + j * double(m.spacing[1]),
                      double(m.origin[2]) + k * double(m.spacing[2])));
        return m;
      }

      /**
       * Samples sdf on an n^3 grid covering the cube [-half, half]^3 (body
       * frame), in the layout the geometry module exports.
       */
      inline DistanceMapData
      sample_map(const Sdf &sdf, const double half, const int n)
      {
        DistanceMapData m;
        m.nx = m.ny = m.nz = n;
        const double h     = 2. * half / (n - 1);
        for (int a = 0; a < 3; ++a)
          {
            m.origin[a]  = static_cast<float>(-half);
            m.spacing[a] = static_cast<float>(h);
          }
        m.values.resize(std::size_t(n) * n * n);
        for (int k = 0; k < n; ++k)
          for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
              m.values[i + std::size_t(n) * (j + std::size_t(n) * k)]
                = static_cast<float>(
                  sdf(double(m.origin[0]) + i * double(m.spacing[0]),
                      double(m.origin[1]) + j * double(m.spacing[1]),
                      double(m.origin[2]) + k * double(m.spacing[2])));
        return m;
      }

      /**
       * Inner spheres from an SDF (thesis §3.4.2: the bounding spheres of the
       * cells that lie inside): lattice of edge h over [-half, half]^3, one
       * sphere of radius h*sqrt(3)/2 per cell whose centre is at least that
       * deep inside.
       */
      inline InnerSphereData
      carve_spheres(const Sdf &sdf, const double half, const double h)
      {
        InnerSphereData s;
        const int       n = static_cast<int>(std::floor(2. * half / h));
        const double    r = 0.5 * std::sqrt(3.) * h;
        for (int k = 0; k < n; ++k)
          for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
              {
                const double x = -half + (i + 0.5) * h,
                             y = -half + (j + 0.5) * h,
                             z = -half + (k + 0.5) * h;
                if (sdf(x, y, z) <= -r)
                  {
                    s.cx.push_back(float(x));
                    s.cy.push_back(float(y));
                    s.cz.push_back(float(z));
                    s.r.push_back(float(r));
                  }
              }
        return s;
      }

      /** count random spheres, radii in [rmin, rmax], centres in [-half,
       * half]^3. */
      inline InnerSphereData
      random_sphere_pack(std::mt19937 &rng,
                         const int     count,
                         const double  half,
                         const double  rmin,
                         const double  rmax)
      {
        std::uniform_real_distribution<double> u(-half, half), ur(rmin, rmax);
        InnerSphereData                        s;
        for (int q = 0; q < count; ++q)
          {
            s.cx.push_back(float(u(rng)));
            s.cy.push_back(float(u(rng)));
            s.cz.push_back(float(u(rng)));
            s.r.push_back(float(ur(rng)));
          }
        return s;
      }

      /** A uniformly random rotation (Shoemake's quaternion), row-major. */
      inline void
      random_rotation(std::mt19937 &rng, float R[9])
      {
        std::uniform_real_distribution<double> u(0., 1.);
        const double u1 = u(rng), u2 = u(rng), u3 = u(rng);
        const double a = std::sqrt(1. - u1), b = std::sqrt(u1);
        const double w    = a * std::sin(2. * M_PI * u2),
                     x    = a * std::cos(2. * M_PI * u2),
                     y    = b * std::sin(2. * M_PI * u3),
                     z    = b * std::cos(2. * M_PI * u3);
        const double m[9] = {1 - 2 * (y * y + z * z),
                             2 * (x * y - z * w),
                             2 * (x * z + y * w),
                             2 * (x * y + z * w),
                             1 - 2 * (x * x + z * z),
                             2 * (y * z - x * w),
                             2 * (x * z - y * w),
                             2 * (y * z + x * w),
                             1 - 2 * (x * x + y * y)};
        for (int i = 0; i < 9; ++i)
          R[i] = static_cast<float>(m[i]);
      }

      /**
       * m bodies at random poses in the unit cube, placed one after the
       * other (random sequential addition): centres in [r, 1 - r]^3 and at
       * least d_min apart, so bodies of size about r overlap little; shape
       * handle b % n_shapes for body b. Returns fewer bodies only if a place
       * cannot be found in 10^6 tries (then the packing is too dense).
       */
      inline std::vector<BodyInstance>
      scatter_bodies(std::mt19937 &rng,
                     const int     m,
                     const double  r,
                     const double  d_min,
                     const int     n_shapes)
      {
        std::uniform_real_distribution<double> u(r, 1. - r);
        std::vector<BodyInstance>              bodies;
        std::vector<std::array<double, 3>>     centres;
        for (long tries = 0;
             static_cast<int>(bodies.size()) < m && tries < 1000000;
             ++tries)
          {
            const std::array<double, 3> c          = {u(rng), u(rng), u(rng)};
            bool                        free_place = true;
            for (const auto &o : centres)
              {
                const double dx = c[0] - o[0], dy = c[1] - o[1],
                             dz = c[2] - o[2];
                if (dx * dx + dy * dy + dz * dz < d_min * d_min)
                  {
                    free_place = false;
                    break;
                  }
              }
            if (!free_place)
              continue;
            BodyInstance b;
            b.shape = static_cast<int>(bodies.size()) % n_shapes;
            random_rotation(rng, b.R);
            for (int a = 0; a < 3; ++a)
              b.t[a] = static_cast<float>(c[a]);
            centres.push_back(c);
            bodies.push_back(b);
          }
        return bodies;
      }

      /** Body-frame coordinates of a world point, in double (for references).
       */
      inline void
      to_body_double(const BodyInstance &b, const double x[3], double xb[3])
      {
        const double d[3] = {x[0] - b.t[0], x[1] - b.t[1], x[2] - b.t[2]};
        for (int i = 0; i < 3; ++i)
          xb[i] = double(b.R[i]) * d[0] + double(b.R[3 + i]) * d[1]
                  + double(b.R[6 + i]) * d[2];
      }

      /** n random points, uniform in [lo, hi]^3, interleaved xyz. */
      inline std::vector<float>
      random_points(std::mt19937     &rng,
                    const std::size_t n,
                    const double      lo,
                    const double      hi)
      {
        std::uniform_real_distribution<double> u(lo, hi);
        std::vector<float>                     p(3 * n);
        for (float &v : p)
          v = static_cast<float>(u(rng));
        return p;
      }

      /** The (n x n x n) lattice of the unit cube, x fastest, interleaved xyz.
       */
      inline std::vector<float>
      unit_cube_lattice(const int n)
      {
        std::vector<float> p;
        p.reserve(3 * std::size_t(n) * n * n);
        for (int k = 0; k < n; ++k)
          for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
              {
                p.push_back(float(double(i) / (n - 1)));
                p.push_back(float(double(j) / (n - 1)));
                p.push_back(float(double(k) / (n - 1)));
              }
        return p;
      }

      /** Counts failed checks and prints each; main returns failures() != 0. */
      inline int &
      failures()
      {
        static int f = 0;
        return f;
      }

#define PARTICULATE_CHECK(cond, ...)                                    \
  do                                                                    \
    {                                                                   \
      if (!(cond))                                                      \
        {                                                               \
          std::printf("FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond); \
          std::printf(__VA_ARGS__);                                     \
          std::printf("\n");                                            \
          ++::particulate::cuda::testing::failures();                   \
        }                                                               \
  } while (false)
    } // namespace testing
  }   // namespace cuda
} // namespace particulate

#endif
