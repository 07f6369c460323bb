#ifndef PARTICULATE_GEOMETRY_DISTANCE_MAP_H
#define PARTICULATE_GEOMETRY_DISTANCE_MAP_H

#include <particulate/geometry/bounding_box.h>
#include <particulate/geometry/distance_map_data.h>
#include <particulate/geometry/pose.h>
#include <particulate/geometry/shape.h>
#include <particulate/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace particulate::geometry {

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
    distance(const Eigen::Vector3d &p, Eigen::Vector3d *normal = nullptr) const;

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
    // coordinate and the largest cell index per direction.
    double                inv_h      = 0.;
    std::array<double, 3> last_point = {0., 0., 0.};
    std::array<int, 3>    last_cell  = {0, 0, 0};

    void
    finish_setup();

    CellPosition
    locate(const Eigen::Vector3d &p) const;

    double
    interpolate_distance(const CellPosition &c) const;

    Eigen::Vector3d
    interpolate_normal(const CellPosition &c) const;

    void
    check_not_empty(const char *caller) const;

    static DistanceMap
    load_checked(const std::string &path, const std::uint64_t expected_key);
  };

} // namespace particulate::geometry

#endif
