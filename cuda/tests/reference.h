// Brute-force reference classification: every body, every sphere, no grids,
// but the same rounded float operations as the library (detail/point_query.h).
// Agreement with it bit for bit shows that the broad-phase grid and the
// sphere grids never drop a body or a sphere.
#ifndef particulate_cuda_tests_reference_h
#define particulate_cuda_tests_reference_h

#include <particulate/cuda/containment_engine.h>
#include <particulate/cuda/detail/point_query.h>

#include <vector>

#include "test_scenes.h"

namespace particulate {
  namespace cuda {
    namespace testing {
      /** A shape kept on the test side, with its engine handle. */
      struct TestShape
      {
        bool            is_map = true;
        DistanceMapData map;
        InnerSphereData spheres;
      };

      /** Uploads every shape to the engine; handle i = shapes[i]. */
      inline void
      upload(ContainmentEngine &engine, const std::vector<TestShape> &shapes)
      {
        for (std::size_t i = 0; i < shapes.size(); ++i)
          {
            const int h = shapes[i].is_map ?
                            engine.add_distance_map(shapes[i].map) :
                            engine.add_inner_spheres(shapes[i].spheres);
            if (h != static_cast<int>(i))
              std::abort();
          }
      }

      inline void
      reference_classify(const std::vector<TestShape>    &shapes,
                         const std::vector<BodyInstance> &bodies,
                         const std::vector<float>        &xyz,
                         std::vector<int>                &first,
                         std::vector<float>              &dist)
      {
        using namespace detail;
        const std::size_t n = xyz.size() / 3;
        first.assign(n, -1);
        dist.assign(n, HUGE_VALF);
        std::vector<ShapeView> views(shapes.size());
        for (std::size_t s = 0; s < shapes.size(); ++s)
          if (shapes[s].is_map)
            {
              const DistanceMapData &m = shapes[s].map;
              ShapeView             &v = views[s];
              v.kind                   = shape_distance_map;
              v.n[0]                   = m.nx;
              v.n[1]                   = m.ny;
              v.n[2]                   = m.nz;
              for (int a = 0; a < 3; ++a)
                {
                  v.origin[a] = m.origin[a];
                  v.inv_h[a]  = 1.f / m.spacing[a];
                }
              v.values = m.values.data();
            }
        for (std::size_t p = 0; p < n; ++p)
          for (std::size_t b = 0; b < bodies.size(); ++b)
            {
              BodyView bv;
              std::copy(bodies[b].R, bodies[b].R + 9, bv.R);
              std::copy(bodies[b].t, bodies[b].t + 3, bv.t);
              bv.shape = views[bodies[b].shape];
              float bx, by, bz;
              to_body_frame(bv,
                            xyz[3 * p],
                            xyz[3 * p + 1],
                            xyz[3 * p + 2],
                            bx,
                            by,
                            bz);
              const TestShape &s = shapes[bodies[b].shape];
              if (s.is_map)
                {
                  float d;
                  if (map_distance(views[bodies[b].shape], bx, by, bz, d))
                    {
                      dist[p] = d < dist[p] ? d : dist[p];
                      if (first[p] < 0 && d <= 0.f)
                        first[p] = static_cast<int>(b);
                    }
                }
              else if (first[p] < 0)
                {
                  const InnerSphereData &sp = s.spheres;
                  for (std::size_t q = 0; q < sp.r.size(); ++q)
                    {
                      const float dx = fsub(bx, sp.cx[q]);
                      const float dy = fsub(by, sp.cy[q]);
                      const float dz = fsub(bz, sp.cz[q]);
                      const float d2
                        = fadd(fadd(fmul(dx, dx), fmul(dy, dy)), fmul(dz, dz));
                      if (d2 <= fmul(sp.r[q], sp.r[q]))
                        {
                          first[p] = static_cast<int>(b);
                          break;
                        }
                    }
                }
            }
      }

      /**
       * A mixed scene of m bodies in the unit cube: shapes 0-2 are distance
       * maps (sphere, torus, box), 3-4 inner-sphere sets (carved torus,
       * random pack), bodies cycle through them with random poses.
       */
      inline void
      mixed_scene(std::mt19937              &rng,
                  const int                  m,
                  const double               body_size,
                  std::vector<TestShape>    &shapes,
                  std::vector<BodyInstance> &bodies)
      {
        const double s    = body_size; // half extent of the shapes
        const int    nmap = 40;
        shapes.clear();
        shapes.resize(5);
        shapes[0].map = sample_map(sphere_sdf(0.7 * s), s, nmap);
        shapes[1].map = sample_map(torus_sdf(0.6 * s, 0.25 * s), s, nmap);
        shapes[2].map = sample_map(box_sdf(0.8 * s, 0.5 * s, 0.3 * s), s, nmap);
        shapes[3].is_map = false;
        shapes[3].spheres
          = carve_spheres(torus_sdf(0.6 * s, 0.3 * s), s, s / 12);
        shapes[4].is_map = false;
        shapes[4].spheres
          = random_sphere_pack(rng, 300, 0.7 * s, 0.02 * s, 0.25 * s);
        std::uniform_real_distribution<double> u(0., 1.);
        bodies.assign(m, BodyInstance());
        for (int b = 0; b < m; ++b)
          {
            bodies[b].shape = b % 5;
            random_rotation(rng, bodies[b].R);
            for (int a = 0; a < 3; ++a)
              bodies[b].t[a] = float(u(rng));
          }
      }
    } // namespace testing
  }   // namespace cuda
} // namespace particulate

#endif
