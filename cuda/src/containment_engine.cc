#include <particulate/cuda/containment_engine.h>

#include "cpu_backend.h"
#include "uniform_grids.h"
#if PARTICULATE_CONTAINMENT_WITH_CUDA
#  include "cuda_backend.h"
#endif

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace particulate {
  namespace cuda {
    const char *
    to_string(const Backend backend)
    {
      switch (backend)
        {
          case Backend::cpu:
            return "cpu";
          case Backend::cuda:
            return "cuda";
          default:
            return "automatic";
        }
    }

    namespace {
      [[noreturn]] void
      bad_input(const std::string &where, const std::string &what)
      {
        throw std::invalid_argument("particulate containment, " + where + ": "
                                    + what);
      }

      bool
      finite(const float x)
      {
        return std::isfinite(x);
      }
    } // namespace

    struct ContainmentEngine::Impl
    {
      Backend  backend     = Backend::cpu;
      unsigned cpu_threads = 0;

      /** Host copy of a shape (kept for the CPU path, which reads it directly).
       */
      struct HostShape
      {
        std::vector<float> values;
        detail::SphereGrid grid;
      };
      std::vector<std::unique_ptr<HostShape>> host_shapes;
      std::vector<detail::ShapeView>          views; // host or device pointers
      std::vector<detail::Box>                boxes; // body-frame boxes
      detail::SceneGrid                       scene; // reused every call

#if PARTICULATE_CONTAINMENT_WITH_CUDA
      std::unique_ptr<detail::CudaBackend> gpu;
#endif

      void
      check_bodies(const BodyInstance *bodies, const std::size_t m) const
      {
        for (std::size_t b = 0; b < m; ++b)
          {
            const BodyInstance &in = bodies[b];
            // Built only on error: this check runs for every body, every call.
            const auto where
              = [b] { return "classify(), body " + std::to_string(b); };
            if (in.shape < 0
                || static_cast<std::size_t>(in.shape) >= views.size())
              bad_input(where(),
                        "shape handle " + std::to_string(in.shape)
                          + " was not returned by add_distance_map() or "
                            "add_inner_spheres() of this engine ("
                          + std::to_string(views.size()) + " shapes uploaded)");
            for (int i = 0; i < 9; ++i)
              if (!finite(in.R[i]))
                bad_input(where(),
                          "the rotation matrix holds a NaN or infinity");
            for (int i = 0; i < 3; ++i)
              if (!finite(in.t[i]))
                bad_input(where(), "the translation holds a NaN or infinity");
            // R R^T = I up to float noise: catches scaled or garbage matrices.
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j)
                {
                  double dot = 0.;
                  for (int k = 0; k < 3; ++k)
                    dot += double(in.R[3 * i + k]) * double(in.R[3 * j + k]);
                  if (std::abs(dot - (i == j ? 1. : 0.)) > 1e-4)
                    bad_input(
                      where(),
                      "the rotation matrix is not orthonormal (R R^T differs "
                      "from the identity by more than 1e-4); pass a proper "
                      "rotation, row-major, body to world");
                }
          }
      }
    };

    ContainmentEngine::ContainmentEngine(const Backend  backend,
                                         const unsigned cpu_threads)
      : impl(new Impl)
    {
      impl->cpu_threads      = cpu_threads;
      const bool have_device = cuda_device_available();
      if (backend == Backend::cuda && !have_device)
        throw std::runtime_error(
          cuda_compiled() ?
            "particulate containment: the CUDA backend was requested but no CUDA device "
            "is visible; use Backend::cpu or Backend::automatic" :
            "particulate containment: the CUDA backend was requested but this library "
            "was built without CUDA (nvcc was not found at configure time)");
      impl->backend = (backend == Backend::cpu || !have_device) ? Backend::cpu :
                                                                  Backend::cuda;
#if PARTICULATE_CONTAINMENT_WITH_CUDA
      if (impl->backend == Backend::cuda)
        impl->gpu.reset(new detail::CudaBackend());
#endif
    }

    ContainmentEngine::~ContainmentEngine() = default;
    ContainmentEngine::ContainmentEngine(
      ContainmentEngine &&) noexcept = default;
    ContainmentEngine &
    ContainmentEngine::operator=(ContainmentEngine &&) noexcept = default;

    bool
    ContainmentEngine::cuda_compiled()
    {
      return PARTICULATE_CONTAINMENT_WITH_CUDA != 0;
    }

    bool
    ContainmentEngine::cuda_device_available()
    {
#if PARTICULATE_CONTAINMENT_WITH_CUDA
      return detail::cuda_device_count() > 0;
#else
      return false;
#endif
    }

    Backend
    ContainmentEngine::backend() const
    {
      return impl->backend;
    }

    std::string
    ContainmentEngine::device_name() const
    {
#if PARTICULATE_CONTAINMENT_WITH_CUDA
      if (impl->gpu)
        return impl->gpu->device_name();
#endif
      const unsigned t = impl->cpu_threads ?
                           impl->cpu_threads :
                           std::max(1u, std::thread::hardware_concurrency());
      return "CPU, " + std::to_string(t) + " thread(s)";
    }

    void
    ContainmentEngine::set_cpu_threads(const unsigned n)
    {
      impl->cpu_threads = n;
    }

    std::size_t
    ContainmentEngine::n_shapes() const
    {
      return impl->views.size();
    }

    int
    ContainmentEngine::add_distance_map(const DistanceMapData &map)
    {
      const std::string where = "add_distance_map()";
      if (map.nx < 2 || map.ny < 2 || map.nz < 2)
        bad_input(where,
                  "a distance map needs at least 2 grid points per axis, got "
                    + std::to_string(map.nx) + " x " + std::to_string(map.ny)
                    + " x " + std::to_string(map.nz));
      const double count = double(map.nx) * map.ny * map.nz;
      if (count > double(std::numeric_limits<int>::max()))
        bad_input(where, "more than 2^31-1 grid points; coarsen the map");
      if (map.values.size() != static_cast<std::size_t>(count))
        bad_input(where,
                  "values holds " + std::to_string(map.values.size())
                    + " samples but nx*ny*nz = "
                    + std::to_string(static_cast<std::size_t>(count)));
      for (int a = 0; a < 3; ++a)
        {
          if (!(map.spacing[a] > 0.f) || !finite(map.spacing[a]))
            bad_input(where,
                      "spacing must be positive and finite along every axis");
          if (!finite(map.origin[a]))
            bad_input(where, "origin holds a NaN or infinity");
        }
      for (std::size_t q = 0; q < map.values.size(); ++q)
        if (!finite(map.values[q]))
          bad_input(where,
                    "value " + std::to_string(q) + " is NaN or infinite");

      detail::ShapeView v{};
      v.kind = detail::shape_distance_map;
      v.n[0] = map.nx;
      v.n[1] = map.ny;
      v.n[2] = map.nz;
      detail::Box box;
      for (int a = 0; a < 3; ++a)
        {
          v.origin[a] = map.origin[a];
          // One reciprocal, rounded once on the host, shared by both paths.
          v.inv_h[a] = 1.f / map.spacing[a];
          box.lo[a]  = map.origin[a];
          box.hi[a]
            = double(map.origin[a]) + double(v.n[a] - 1) / double(v.inv_h[a]);
        }
#if PARTICULATE_CONTAINMENT_WITH_CUDA
      if (impl->gpu)
        {
          v.values = map.values.data();
          v        = impl->gpu->upload_map(v, map.values.size());
        }
      else
#endif
        {
          impl->host_shapes.emplace_back(new Impl::HostShape);
          impl->host_shapes.back()->values = map.values;
          v.values = impl->host_shapes.back()->values.data();
        }
      impl->views.push_back(v);
      impl->boxes.push_back(box);
      return static_cast<int>(impl->views.size() - 1);
    }

    int
    ContainmentEngine::add_inner_spheres(const InnerSphereData &s)
    {
      const std::string where = "add_inner_spheres()";
      const std::size_t ns    = s.r.size();
      if (s.cx.size() != ns || s.cy.size() != ns || s.cz.size() != ns)
        bad_input(where, "cx, cy, cz and r must have the same length");
      if (ns == 0)
        bad_input(where, "the sphere set is empty");
      if (ns > std::size_t(std::numeric_limits<int>::max()))
        bad_input(where, "more than 2^31-1 spheres");
      for (std::size_t q = 0; q < ns; ++q)
        {
          if (!finite(s.cx[q]) || !finite(s.cy[q]) || !finite(s.cz[q])
              || !finite(s.r[q]))
            bad_input(where,
                      "sphere " + std::to_string(q)
                        + " holds a NaN or infinity");
          if (s.r[q] < 0.f)
            bad_input(where,
                      "sphere " + std::to_string(q) + " has a negative radius");
        }

      std::unique_ptr<Impl::HostShape> host(new Impl::HostShape);
      host->grid                  = detail::build_sphere_grid(s);
      const detail::SphereGrid &g = host->grid;
      detail::ShapeView         v{};
      v.kind = detail::shape_inner_spheres;
      for (int a = 0; a < 3; ++a)
        {
          v.n[a]      = g.n[a];
          v.origin[a] = g.origin[a];
          v.inv_h[a]  = g.inv_h[a];
        }
      v.cell_start          = g.cell_start.data();
      v.entries             = g.entries.data();
      const detail::Box box = g.box;
#if PARTICULATE_CONTAINMENT_WITH_CUDA
      if (impl->gpu)
        v = impl->gpu->upload_spheres(v, g);
      else
#endif
        impl->host_shapes.push_back(std::move(host));
      impl->views.push_back(v);
      impl->boxes.push_back(box);
      return static_cast<int>(impl->views.size() - 1);
    }

    void
    ContainmentEngine::classify(const float        *xyz,
                                const std::size_t   n,
                                const BodyInstance *bodies,
                                const std::size_t   m,
                                int                *first_body,
                                float              *distance)
    {
      if (n > 0 && first_body == nullptr && distance == nullptr)
        bad_input("classify()",
                  "both outputs are null: pass first_body, distance or both");
      if (n > 0 && xyz == nullptr)
        bad_input("classify()", "xyz is null but n > 0");
      if (m > 0 && bodies == nullptr)
        bad_input("classify()", "bodies is null but m > 0");
      if (m > std::size_t(std::numeric_limits<int>::max()))
        bad_input("classify()", "more than 2^31-1 bodies");
      impl->check_bodies(bodies, m);
      if (n == 0)
        return;

      detail::SceneGrid &g = impl->scene;
      detail::build_scene_grid(bodies, m, impl->views, impl->boxes, g);
#if PARTICULATE_CONTAINMENT_WITH_CUDA
      if (impl->gpu)
        {
          impl->gpu->classify(g, xyz, n, first_body, distance);
          return;
        }
#endif
      const detail::SceneView view
        = detail::make_scene_view(g,
                                  g.bodies.data(),
                                  g.cell_start.data(),
                                  g.body_ids.data());
      detail::classify_cpu(view,
                           xyz,
                           n,
                           first_body,
                           distance,
                           impl->cpu_threads);
    }

    void
    ContainmentEngine::pin_host_memory(const void *ptr, const std::size_t bytes)
    {
#if PARTICULATE_CONTAINMENT_WITH_CUDA
      if (impl->gpu)
        impl->gpu->pin(ptr, bytes);
#else
      (void)ptr;
      (void)bytes;
#endif
    }

    void
    ContainmentEngine::unpin_host_memory(const void *ptr)
    {
#if PARTICULATE_CONTAINMENT_WITH_CUDA
      if (impl->gpu)
        impl->gpu->unpin(ptr);
#else
      (void)ptr;
#endif
    }

    KernelTiming
    ContainmentEngine::time_kernel(const float        *xyz,
                                   const std::size_t   n,
                                   const BodyInstance *bodies,
                                   const std::size_t   m,
                                   const bool          with_distance,
                                   const int           single_launches,
                                   const int           batch,
                                   const int           batches)
    {
#if PARTICULATE_CONTAINMENT_WITH_CUDA
      if (impl->gpu)
        {
          impl->check_bodies(bodies, m);
          detail::SceneGrid &g = impl->scene;
          detail::build_scene_grid(bodies, m, impl->views, impl->boxes, g);
          return impl->gpu->time_kernel(g,
                                        xyz,
                                        n,
                                        with_distance,
                                        single_launches,
                                        batch,
                                        batches);
        }
#else
      (void)xyz;
      (void)n;
      (void)bodies;
      (void)m;
      (void)with_distance;
      (void)single_launches;
      (void)batch;
      (void)batches;
#endif
      throw std::logic_error("time_kernel() needs the CUDA backend");
    }

    double
    ContainmentEngine::measure_copy_bandwidth(const std::size_t bytes)
    {
#if PARTICULATE_CONTAINMENT_WITH_CUDA
      if (impl->gpu)
        return impl->gpu->measure_copy_bandwidth(bytes);
#else
      (void)bytes;
#endif
      throw std::logic_error("measure_copy_bandwidth() needs the CUDA backend");
    }
  } // namespace cuda
} // namespace particulate
