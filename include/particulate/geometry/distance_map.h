#ifndef particulate_geometry_distance_map_h
#define particulate_geometry_distance_map_h

#include <particulate/geometry/bounding_box.h>
#include <particulate/geometry/distance_map_data.h>
#include <particulate/geometry/pose.h>
#include <particulate/geometry/shape.h>
#include <particulate/geometry/triangle_mesh.h>

#include <Eigen/Core>

#if defined(__SSE2__)
#  include <emmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace particulate {
  namespace geometry {

    /**
     * A signed distance map (thesis §3.4.2, Algorithm 5): a Cartesian grid with
     * spacing h over the body's bounding box enlarged by a margin lambda,
     * storing at every grid point the exact signed distance to the surface
     * (negative inside) and the outward unit normal of the closest surface
     * point. Queries locate the cell in O(1) and interpolate both trilinearly,
     * so the distance error is O(h^2) where the distance is smooth.
     *
     * All coordinates are in the body frame, the frame the shape was given in;
     * the overloads taking a Pose bring world points into it (b = R^T (x - t)).
     * A built map is immutable and safe to query from several threads.
     *
     * The grid values are stored in single precision: their rounding error
     * (6e-8 of the largest distance in the map) is far below the interpolation
     * error (about h^2 times the curvature) for any grid of fewer than a few
     * thousand points per side, and the half-size grid stays in cache longer.
     * Interpolation is done in double precision, so a query is a smooth
     * function of the point. For many points, distances() is faster than one
     * distance() call per point: it locates a group of points first and
     * prefetches their cells, so that the memory accesses overlap.
     */
    class DistanceMap
    {
    public:
      /** Parameters of the grid. */
      struct Parameters
      {
        /** Grid spacing h [m], the same in all directions; > 0. */
        double spacing = 0.;
        /** Margin lambda [m] added on every side of the bounding box (Algorithm
         *  5); >= 0. Distances are accurate inside the enlarged box. */
        double margin = 0.;
        /** Threads used to fill the grid (1 = serial). */
        unsigned int n_threads = 1;
      };

      /** An empty map (no grid points); build() or load() one. */
      DistanceMap() = default;

      /**
       * Algorithm 5: build the map of @p shape.
       * @param shape a bounded solid (finite bounding box)
       * @param parameters spacing, margin, threads
       * @throw GeometryError for a non-positive spacing, negative margin, an
       *   unbounded shape, or more than 2^31 grid points
       */
      static DistanceMap
      build(const Shape &shape, const Parameters &parameters);

      /**
       * Build the map of the solid bounded by @p mesh, or read it from
       * @p cache_dir if a map of the same mesh contents (TriangleMesh::
       * content_hash), spacing and margin was built before. A corrupt or stale
       * cache file is rebuilt and overwritten.
       * @param mesh closed outward surface (see read_surface_mesh)
       * @param parameters spacing, margin, threads
       * @param cache_dir folder for the cache files (created if missing)
       * @param loaded_from_cache if not null, set to true when read from disk
       */
      static DistanceMap
      build_cached(const TriangleMesh &mesh,
                   const Parameters   &parameters,
                   const std::string  &cache_dir,
                   bool               *loaded_from_cache = nullptr);

      /**
       * The bytes a map of a solid with bounding box @p shape_box would take
       * with @p parameters (the grid build() would lay out), known before
       * any work.
       */
      static std::size_t
      planned_memory_bytes(const BoundingBox &shape_box,
                           const Parameters  &parameters);

      /** The file name build_cached() uses for these inputs (no folder). */
      static std::string
      cache_file_name(const TriangleMesh &mesh, const Parameters &parameters);

      /**
       * Signed distance at the body-frame point @p p [m], trilinearly
       * interpolated. Outside the grid the point is clamped to the grid box and
       * the distance from the box added (an upper bound of the true distance
       * for points outside the body, good enough far away; cf. §3.4.2).
       * @param p body-frame point [m]
       * @param normal if not null, receives the interpolated, normalised
       *   outward normal (body frame)
       */
      double
      distance(const Eigen::Vector3d &p,
               Eigen::Vector3d       *normal = nullptr) const;

      /**
       * Signed distance of the world point @p x for a body placed at @p pose
       * [m]; the normal, if asked for, is returned in world coordinates.
       */
      double
      distance(const Eigen::Vector3d &x,
               const Pose            &pose,
               Eigen::Vector3d       *normal = nullptr) const;

      /**
       * Signed distances (and normals) of @p count body-frame points at once:
       * the same values as distance() per point, at a lower cost per point.
       * @param points body-frame points [m]
       * @param count number of points
       * @param distances receives @p count signed distances [m]
       * @param normals if not null, receives @p count interpolated, normalised
       *   outward normals (body frame)
       */
      void
      distances(const Eigen::Vector3d *points,
                std::size_t            count,
                double                *distances,
                Eigen::Vector3d       *normals = nullptr) const;

      /** True if @p p (body frame) lies inside the grid box. */
      bool
      covers(const Eigen::Vector3d &p) const;

      /** The largest depth inside the solid over the grid points [m]:
       *  about half the thickness of its thickest part, as the grid
       *  resolves it (0 if no grid point is inside). */
      double
      deepest_inside() const;

      /** Number of grid points in each direction. */
      const std::array<int, 3> &
      n_points() const
      {
        return n;
      }

      /** Body-frame position of grid point (0, 0, 0) [m]. */
      const Eigen::Vector3d &
      origin() const
      {
        return x0;
      }

      /** Grid spacing h [m]. */
      double
      spacing() const
      {
        return h;
      }

      /** The grid box [origin, origin + (n - 1) h] [m]. */
      BoundingBox
      grid_box() const;

      /** Position of grid point (i, j, k) [m]. */
      Eigen::Vector3d
      point(const int i, const int j, const int k) const
      {
        return x0 + h * Eigen::Vector3d(i, j, k);
      }

      /** Linear index of grid point (i, j, k): i + nx (j + ny k). */
      std::size_t
      index(const int i, const int j, const int k) const
      {
        return i
               + static_cast<std::size_t>(n[0])
                   * (j + static_cast<std::size_t>(n[1]) * k);
      }

      /** Stored signed distance at grid point (i, j, k) [m] (single
       *  precision). */
      double
      value(const int i, const int j, const int k) const
      {
        return values[index(i, j, k)];
      }

      /** Stored outward normal at grid point (i, j, k). */
      Eigen::Vector3d
      normal(const int i, const int j, const int k) const;

      /** The raw arrays for the CUDA kernels (single precision). */
      DistanceMapData
      export_data() const;

      /** Write the map to a binary file. @throw GeometryError on failure */
      void
      save(const std::string &path) const;

      /**
       * Read a map written by save().
       * @throw GeometryError if the file is missing, truncated or not a map
       */
      static DistanceMap
      load(const std::string &path);

      /** Memory held by the grid values and normals [bytes]: 16 per grid
       *  point. */
      std::size_t
      memory_bytes() const;

    private:
      // A located query point: the grid index of its cell's lowest corner,
      // its local coordinates in the cell (in [0, 1]) and, for points outside
      // the grid box, the squared distance to the box in units of h.
      struct CellPosition
      {
        std::size_t base;
        double      f[3];
        double      outside2;
      };

      std::array<int, 3> n  = {0, 0, 0};
      Eigen::Vector3d    x0 = Eigen::Vector3d::Zero();
      double             h  = 0.;
      std::vector<float> values;
      std::vector<float> normals; // 3 per grid point
      std::uint64_t      key = 0; // cache key, 0 if not from build_cached
      // Derived from n and h by finish_setup(): 1 / h, the largest grid
      // coordinate and the largest cell index per direction (as doubles), and
      // the index steps from a grid point to its neighbours in y (n[0]) and z
      // (n[0] n[1]).
      double                inv_h      = 0.;
      std::array<double, 3> last_point = {0., 0., 0.};
      std::array<double, 3> last_cell  = {0., 0., 0.};
      std::size_t           stride_y   = 0;
      std::size_t           stride_z   = 0;

      void
      finish_setup();

      // The hot path of a query, defined below so that it is inlined into the
      // callers' loops (a call and its set-up cost about as much as the
      // lookup of a cached cell).
      void
      check_not_empty(const char *caller) const;

      /** Grid points along each axis over @p box (already enlarged) at
       *  spacing @p h, at least two. */
      static std::array<int, 3>
      grid_counts(const BoundingBox &box, const double h);

      [[noreturn]] static void
      throw_empty(const char *caller);

      CellPosition
      locate(const Eigen::Vector3d &p) const;

      double
      interpolate_distance(const CellPosition &c) const;

      Eigen::Vector3d
      interpolate_normal(const CellPosition &c) const;

      // The two values (or normals) of an edge along x: grid points (i, j, k)
      // and (i + 1, j, k) are adjacent in memory, so the interpolation works on
      // these pairs (two lanes of a SIMD register).
      static Eigen::Array2d
      x_pair(const float *v)
      {
        return Eigen::Array2d(v[0], v[1]);
      }

      // Trilinear interpolation from the four x-edges of a cell, (y, z) =
      // (0, 0), (1, 0), (0, 1), (1, 1): along z, then y, leaving the two ends
      // of one x-edge.
      static Eigen::Array2d
      interpolate_yz(const Eigen::Array2d &e00,
                     const Eigen::Array2d &e10,
                     const Eigen::Array2d &e01,
                     const Eigen::Array2d &e11,
                     const double         *f)
      {
        const Eigen::Array2d e0 = e00 + f[2] * (e01 - e00);
        const Eigen::Array2d e1 = e10 + f[2] * (e11 - e10);
        return e0 + f[1] * (e1 - e0);
      }

      static DistanceMap
      load_checked(const std::string &path, const std::uint64_t expected_key);
    };

    // -------------------------------------------------------------------------

    inline void
    DistanceMap::check_not_empty(const char *caller) const
    {
      if (__builtin_expect(values.empty(), 0))
        throw_empty(caller);
    }

    inline DistanceMap::CellPosition
    DistanceMap::locate(const Eigen::Vector3d &p) const
    {
      // O(1) cell location: clamp the grid coordinate s to the grid box
      // (points outside get the value at the nearest box point plus their
      // distance to the box, computed only for them). std::max(0., s) is 0 for
      // s = NaN, so a NaN point reads a valid cell and returns NaN, never
      // memory outside. The cell index is the truncation of
      // min(clamped, last cell), which equals min(floor(clamped), last cell)
      // for clamped >= 0: the last grid point belongs to the last cell.
      CellPosition c;
      double       s[3], clamped[3];
      bool         outside;
#if defined(__SSE2__)
      // The same operations as the loop below (so the same results, bit for
      // bit), x and y in the two lanes of one register and z in a third, which
      // halves the instructions of the hot path: maxpd(s, 0) and minpd(s, l)
      // are std::max(0., s) and std::min(s, l), also for NaN and -0.
      const __m128d s_xy = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(p.data()),
                                                 _mm_loadu_pd(x0.data())),
                                      _mm_set1_pd(inv_h));
      const __m128d s_z  = _mm_mul_sd(_mm_sub_sd(_mm_load_sd(p.data() + 2),
                                                _mm_load_sd(x0.data() + 2)),
                                     _mm_set_sd(inv_h));
      const __m128d c_xy = _mm_min_pd(_mm_max_pd(s_xy, _mm_setzero_pd()),
                                      _mm_loadu_pd(last_point.data()));
      const __m128d c_z  = _mm_min_sd(_mm_max_sd(s_z, _mm_setzero_pd()),
                                     _mm_load_sd(last_point.data() + 2));
      const __m128i i_xy
        = _mm_cvttpd_epi32(_mm_min_pd(c_xy, _mm_loadu_pd(last_cell.data())));
      const int i_z
        = _mm_cvttsd_si32(_mm_min_sd(c_z, _mm_load_sd(last_cell.data() + 2)));
      _mm_storeu_pd(c.f, _mm_sub_pd(c_xy, _mm_cvtepi32_pd(i_xy)));
      c.f[2] = _mm_cvtsd_f64(c_z) - i_z;
      // s != clamped in any direction (true for NaN): outside the grid box.
      // (The upper lane of the z comparison is s_z's, 0.)
      outside = _mm_movemask_pd(
                  _mm_or_pd(_mm_cmpneq_pd(s_xy, c_xy), _mm_cmpneq_sd(s_z, c_z)))
                != 0;
      c.base = static_cast<std::size_t>(_mm_cvtsi128_si32(i_xy))
               + stride_y
                   * static_cast<std::size_t>(
                     _mm_cvtsi128_si32(_mm_srli_si128(i_xy, 4)))
               + stride_z * static_cast<std::size_t>(i_z);
      if (outside)
        {
          _mm_storeu_pd(s, s_xy);
          _mm_storeu_pd(clamped, c_xy);
          s[2]       = _mm_cvtsd_f64(s_z);
          clamped[2] = _mm_cvtsd_f64(c_z);
        }
#else
      std::int64_t i[3];
      outside = false;
      for (int d = 0; d < 3; ++d)
        {
          s[d]       = (p[d] - x0[d]) * inv_h;
          clamped[d] = std::min(std::max(0., s[d]), last_point[d]);
          outside |= s[d] != clamped[d]; // true for NaN
          const double cell = std::min(clamped[d], last_cell[d]);
          i[d]              = static_cast<std::int64_t>(cell);
          c.f[d]            = clamped[d] - static_cast<double>(i[d]);
        }
      c.base
        = static_cast<std::size_t>(i[0]) + stride_y * i[1] + stride_z * i[2];
#endif
      c.outside2 = 0.;
      if (outside)
        for (int d = 0; d < 3; ++d)
          c.outside2 += (s[d] - clamped[d]) * (s[d] - clamped[d]);
      return c;
    }

    inline double
    DistanceMap::interpolate_distance(const CellPosition &c) const
    {
      const float         *v = values.data() + c.base;
      const Eigen::Array2d edge
        = interpolate_yz(x_pair(v),
                         x_pair(v + stride_y),
                         x_pair(v + stride_z),
                         x_pair(v + stride_y + stride_z),
                         c.f);
      const double d = edge[0] + c.f[0] * (edge[1] - edge[0]);
      // Outside the grid box (rare, so a predictable branch; NaN takes it).
      return c.outside2 != 0. ? d + h * std::sqrt(c.outside2) : d;
    }

    inline Eigen::Vector3d
    DistanceMap::interpolate_normal(const CellPosition &c) const
    {
      const std::size_t sy = 3 * stride_y, sz = 3 * stride_z;
      const float      *g = normals.data() + 3 * c.base;
      Eigen::Vector3d   m;
      for (int d = 0; d < 3; ++d)
        {
          // Component d of the two normals of each x-edge: g[d] and g[d + 3].
          auto pair = [&](const std::size_t offset) {
            return Eigen::Array2d(g[offset + d], g[offset + d + 3]);
          };
          const Eigen::Array2d edge
            = interpolate_yz(pair(0), pair(sy), pair(sz), pair(sy + sz), c.f);
          m[d] = edge[0] + c.f[0] * (edge[1] - edge[0]);
        }
      const double len2 = m.squaredNorm();
      // Zero only where the normals of the corners cancel (on a medial
      // surface); any unit vector is as good as another there.
      return len2 > 0. ? Eigen::Vector3d(m / std::sqrt(len2)) :
                         Eigen::Vector3d::UnitX();
    }

    inline double
    DistanceMap::distance(const Eigen::Vector3d &p,
                          Eigen::Vector3d       *normal) const
    {
      check_not_empty("distance");
      const CellPosition c = locate(p);
      if (normal)
        *normal = interpolate_normal(c);
      return interpolate_distance(c);
    }

  } // namespace geometry
} // namespace particulate

#endif
