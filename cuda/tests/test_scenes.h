// Test and benchmark data built in place, so that nothing needs CGAL: analytic
// signed distances (sphere, box, torus) sampled onto distance maps, inner-
// sphere sets carved from them, random sphere packs, random poses and points.
#ifndef particulate_cuda_tests_test_scenes_h
#define particulate_cuda_tests_test_scenes_h

#include <particulate/cuda/containment_types.h>

#include <algorithm>
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
