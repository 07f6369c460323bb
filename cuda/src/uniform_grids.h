// Host-side construction of the two uniform grids the point query walks:
// the per-shape grid of inner spheres (built once at upload) and the
// per-call world grid over the bodies' bounding boxes (a broad phase).
// Private to the library; both backends use the very same grids, so culling
// never makes the CPU and the GPU disagree.
#ifndef particulate_cuda_src_uniform_grids_h
#define particulate_cuda_src_uniform_grids_h

#include <particulate/cuda/containment_types.h>
#include <particulate/cuda/detail/point_query.h>

#include <array>
#include <utility>
#include <vector>

namespace particulate {
  namespace cuda {
    namespace detail {
      /** Axis-aligned box in double precision [m]. */
      struct Box
      {
        std::array<double, 3> lo, hi;
      };

      /** A uniform grid of spheres of one shape, in the body frame. */
      struct SphereGrid
      {
        int                      n[3];
        float                    origin[3];
        float                    inv_h[3];
        std::vector<int>         cell_start; // n0*n1*n2 + 1
        std::vector<SphereEntry> entries;
        Box                      box; // body-frame box of all spheres
      };

      /**
       * Sorts the spheres into a uniform grid whose cell edge is about the
       * mean sphere diameter; each cell lists every sphere that touches it
       * (with a small safety margin so float rounding of the query point can
       * never miss one).
       */
      SphereGrid
      build_sphere_grid(const InnerSphereData &spheres);

      /** The per-call broad-phase grid and body table. */
      struct SceneGrid
      {
        int                   n[3];
        float                 origin[3];
        float                 inv_h[3];
        int                   n_direct; // see SceneView::n_direct
        std::vector<int>      cell_start;
        std::vector<int>      body_ids;
        std::vector<BodyView> bodies;
        // Scratch space kept between calls.
        std::vector<Box>                 world;
        std::vector<double>              pads;
        std::vector<std::pair<int, int>> pairs;
        std::vector<int>                 fill;
      };

      /**
       * Builds the world grid over the bodies' boxes.
       *
       * @param bodies       the bodies of the call.
       * @param m            their number.
       * @param shape_views  view of each shape (host or device pointers),
       *                     copied into the body records.
       * @param shape_boxes  body-frame box of each shape, indexed by handle.
       * @param grid         the result; its vectors' capacity is reused.
       */
      void
      build_scene_grid(const BodyInstance           *bodies,
                       std::size_t                   m,
                       const std::vector<ShapeView> &shape_views,
                       const std::vector<Box>       &shape_boxes,
                       SceneGrid                    &grid);

      /**
       * The SceneView of a grid whose arrays live at the given addresses
       * (host or device); copies the first bodies into SceneView::direct.
       */
      SceneView
      make_scene_view(const SceneGrid &g,
                      const BodyView  *bodies,
                      const int       *cell_start,
                      const int       *body_ids);
    } // namespace detail
  }   // namespace cuda
} // namespace particulate

#endif
