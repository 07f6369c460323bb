#include <particulate/geometry/distance_map.h>
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/triangulated_surface.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace particulate {
  namespace geometry {

    namespace {
      // 02: values in single precision (01 held doubles).
      constexpr char magic[8] = {'P', 'T', 'D', 'M', 'A', 'P', '0', '2'};
      // 2: signs from the exact side test (maps of version 1 may hold wrong
      // signs near thin features); 3: single-precision values. Bump whenever
      // the content would change.
      constexpr std::uint64_t format_version = 3;

      // Points located (and their cells prefetched) at a time by
      // DistanceMap::distances(): enough that the memory accesses of a group
      // overlap, few enough that the group's cells are still in the L1 cache
      // when they are interpolated (16 points x 8 lines x 64 bytes = 8 kB).
      constexpr std::size_t batch = 16;

      std::uint64_t
      mix(std::uint64_t h, const void *data, const std::size_t n)
      {
        const auto *b = static_cast<const unsigned char *>(data);
        for (std::size_t i = 0; i < n; ++i)
          {
            h ^= b[i];
            h *= 1099511628211ull;
          }
        return h;
      }

      std::uint64_t
      cache_key(const TriangleMesh &mesh, const DistanceMap::Parameters &p)
      {
        std::uint64_t h = mesh.content_hash();
        h               = mix(h, &p.spacing, sizeof(double));
        h               = mix(h, &p.margin, sizeof(double));
        h               = mix(h, &format_version, sizeof(format_version));
        return h;
      }
    } // namespace

    std::array<int, 3>
    DistanceMap::grid_counts(const BoundingBox &box, const double h)
    {
      std::array<int, 3> counts{};
      for (int d = 0; d < 3; ++d)
        counts[d]
          = std::max(static_cast<int>(std::ceil(box.extent()[d] / h - 1e-9))
                       + 1,
                     2);
      return counts;
    }

    std::size_t
    DistanceMap::planned_memory_bytes(const BoundingBox &shape_box,
                                      const Parameters  &prm)
    {
      const BoundingBox box    = shape_box.enlarged(prm.margin);
      double            points = 1.;
      for (int d = 0; d < 3; ++d)
        points *= std::ceil(box.extent()[d] / prm.spacing - 1e-9) + 1.;
      // a value and a normal per point, single precision
      const double bytes = points * 4. * sizeof(float);
      return bytes < 1e19 ? static_cast<std::size_t>(bytes) :
                            std::numeric_limits<std::size_t>::max();
    }

    DistanceMap
    DistanceMap::build(const Shape &shape, const Parameters &prm)
    {
      if (!(prm.spacing > 0.) || !std::isfinite(prm.spacing))
        throw GeometryError(
          "DistanceMap::build: the spacing must be positive.");
      if (!(prm.margin >= 0.) || !std::isfinite(prm.margin))
        throw GeometryError(
          "DistanceMap::build: the margin must be zero or positive.");
      const BoundingBox shape_box = shape.bounding_box();
      if (shape_box.empty() || !shape_box.lower.allFinite()
          || !shape_box.upper.allFinite())
        throw GeometryError(
          "DistanceMap::build: the shape is unbounded (e.g. a half-space); a "
          "distance map needs a finite bounding box.");

      // Algorithm 5: box += lambda, then a structured grid over it, centred so
      // that the rounding up of the point count is shared by both sides.
      const BoundingBox box = shape_box.enlarged(prm.margin);
      DistanceMap       map;
      map.h        = prm.spacing;
      map.n        = grid_counts(box, map.h);
      double total = 1.;
      for (int d = 0; d < 3; ++d)
        total *= map.n[d];
      if (total > 2147483647.)
        {
          std::ostringstream msg;
          msg << "DistanceMap::build: " << map.n[0] << " x " << map.n[1]
              << " x " << map.n[2] << " grid points for spacing " << map.h
              << " is too many; use a larger spacing.";
          throw GeometryError(msg.str());
        }
      map.x0 = box.center()
               - 0.5 * map.h
                   * Eigen::Vector3d(map.n[0] - 1, map.n[1] - 1, map.n[2] - 1);
      map.finish_setup();

      const std::size_t np = static_cast<std::size_t>(total);
      map.values.resize(np);
      map.normals.resize(3 * np);
      // Grid lines along x go to the shape in one call, so that meshes can use
      // each closest point as the search hint for the next.
      auto fill = [&](int k_begin, int k_end) {
        std::vector<Eigen::Vector3d> line(map.n[0]), nrm;
        std::vector<double>          dist;
        for (int k = k_begin; k < k_end; ++k)
          for (int j = 0; j < map.n[1]; ++j)
            {
              for (int i = 0; i < map.n[0]; ++i)
                line[i] = map.point(i, j, k);
              shape.signed_distances(line, dist, &nrm);
              for (int i = 0; i < map.n[0]; ++i)
                {
                  const std::size_t id = map.index(i, j, k);
                  map.values[id]       = static_cast<float>(dist[i]);
                  for (int d = 0; d < 3; ++d)
                    map.normals[3 * id + d] = static_cast<float>(nrm[i][d]);
                }
            }
      };
      const int threads = static_cast<int>(
        std::max(1u, std::min<unsigned int>(prm.n_threads, map.n[2])));
      if (threads == 1)
        fill(0, map.n[2]);
      else
        {
          std::vector<std::thread> pool;
          for (int t = 0; t < threads; ++t)
            pool.emplace_back(fill,
                              map.n[2] * t / threads,
                              map.n[2] * (t + 1) / threads);
          for (auto &th : pool)
            th.join();
        }
      return map;
    }

    std::string
    DistanceMap::cache_file_name(const TriangleMesh &mesh,
                                 const Parameters   &prm)
    {
      char name[64];
      std::snprintf(name,
                    sizeof(name),
                    "distance_map_%016llx.bin",
                    static_cast<unsigned long long>(cache_key(mesh, prm)));
      return name;
    }

    DistanceMap
    DistanceMap::build_cached(const TriangleMesh &mesh,
                              const Parameters   &prm,
                              const std::string  &cache_dir,
                              bool               *loaded_from_cache)
    {
      const std::uint64_t key  = cache_key(mesh, prm);
      const std::string   path = cache_dir + "/" + cache_file_name(mesh, prm);
      if (loaded_from_cache)
        *loaded_from_cache = false;
      std::error_code ec;
      if (std::filesystem::is_regular_file(path, ec))
        {
          try
            {
              DistanceMap map = load_checked(path, key);
              if (loaded_from_cache)
                *loaded_from_cache = true;
              return map;
            }
          catch (const GeometryError &)
            {
              // Corrupt or from another version: rebuild below and overwrite.
            }
        }
      DistanceMap map = build(TriangulatedSurface(mesh), prm);
      map.key         = key;
      std::filesystem::create_directories(cache_dir, ec);
      // Write to a private temporary name (process, thread, object), then
      // rename: several processes (MPI ranks) building the same map never
      // see a half-written file.
      const std::string tmp
        = path + ".tmp." + std::to_string(::getpid()) + "."
          + std::to_string(
            std::hash<std::thread::id>()(std::this_thread::get_id()))
          + "." + std::to_string(reinterpret_cast<std::uintptr_t>(&map));
      try
        {
          map.save(tmp);
          std::filesystem::rename(tmp, path);
        }
      catch (const std::exception &)
        {
          // The cache is an optimisation: a read-only folder is not an error.
          std::filesystem::remove(tmp, ec);
        }
      return map;
    }

    void
    DistanceMap::finish_setup()
    {
      inv_h = 1. / h;
      for (int d = 0; d < 3; ++d)
        {
          last_point[d] = n[d] - 1;
          last_cell[d]  = n[d] - 2;
        }
      stride_y = static_cast<std::size_t>(n[0]);
      stride_z = stride_y * static_cast<std::size_t>(n[1]);
    }

    void
    DistanceMap::throw_empty(const char *caller)
    {
      throw GeometryError(std::string("DistanceMap::") + caller
                          + ": the map is empty; build or load it first.");
    }

    void
    DistanceMap::distances(const Eigen::Vector3d *points,
                           const std::size_t      count,
                           double                *out,
                           Eigen::Vector3d       *normal_out) const
    {
      if (count == 0)
        return;
      check_not_empty("distances");
      const std::size_t sy = stride_y, sz = stride_z;
      CellPosition      cells[batch];
      for (std::size_t first = 0; first < count; first += batch)
        {
          const std::size_t m = std::min(batch, count - first);
          // Locate the group and ask for the four x-edges of each cell (and of
          // the normal grid), so that the cache misses of the group overlap
          // instead of stalling one query after the other.
          for (std::size_t q = 0; q < m; ++q)
            {
              cells[q]       = locate(points[first + q]);
              const float *v = values.data() + cells[q].base;
              __builtin_prefetch(v);
              __builtin_prefetch(v + sy);
              __builtin_prefetch(v + sz);
              __builtin_prefetch(v + sy + sz);
              if (normal_out)
                {
                  const float *g = normals.data() + 3 * cells[q].base;
                  __builtin_prefetch(g);
                  __builtin_prefetch(g + 3 * sy);
                  __builtin_prefetch(g + 3 * sz);
                  __builtin_prefetch(g + 3 * (sy + sz));
                }
            }
          for (std::size_t q = 0; q < m; ++q)
            out[first + q] = interpolate_distance(cells[q]);
          if (normal_out)
            for (std::size_t q = 0; q < m; ++q)
              normal_out[first + q] = interpolate_normal(cells[q]);
        }
    }

    double
    DistanceMap::distance(const Eigen::Vector3d &x,
                          const Pose            &pose,
                          Eigen::Vector3d       *normal) const
    {
      const double d = distance(pose.to_body(x), normal);
      if (normal)
        *normal = pose.direction_to_world(*normal);
      return d;
    }

    bool
    DistanceMap::covers(const Eigen::Vector3d &p) const
    {
      return grid_box().contains(p);
    }

    BoundingBox
    DistanceMap::grid_box() const
    {
      return BoundingBox(x0,
                         x0
                           + h * Eigen::Vector3d(n[0] - 1, n[1] - 1, n[2] - 1));
    }

    Eigen::Vector3d
    DistanceMap::normal(const int i, const int j, const int k) const
    {
      const std::size_t id = index(i, j, k);
      return Eigen::Vector3d(normals[3 * id],
                             normals[3 * id + 1],
                             normals[3 * id + 2]);
    }

    DistanceMapData
    DistanceMap::export_data() const
    {
      DistanceMapData data;
      data.nx = n[0];
      data.ny = n[1];
      data.nz = n[2];
      for (int d = 0; d < 3; ++d)
        {
          data.origin[d]  = static_cast<float>(x0[d]);
          data.spacing[d] = static_cast<float>(h);
        }
      data.values.assign(values.begin(), values.end());
      return data;
    }

    double
    DistanceMap::deepest_inside() const
    {
      double deepest = 0.;
      for (const float v : values)
        deepest = std::max(deepest, -double(v));
      return deepest;
    }

    std::size_t
    DistanceMap::memory_bytes() const
    {
      return values.size() * sizeof(float) + normals.size() * sizeof(float);
    }

    void
    DistanceMap::save(const std::string &path) const
    {
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      if (!out)
        throw GeometryError(
          "DistanceMap::save: cannot open '" + path
          + "' for writing; check that the folder exists and is "
            "writable.");
      const std::int32_t dims[3] = {n[0], n[1], n[2]};
      const double       geo[4]  = {x0[0], x0[1], x0[2], h};
      out.write(magic, sizeof(magic));
      out.write(reinterpret_cast<const char *>(&key), sizeof(key));
      out.write(reinterpret_cast<const char *>(dims), sizeof(dims));
      out.write(reinterpret_cast<const char *>(geo), sizeof(geo));
      out.write(reinterpret_cast<const char *>(values.data()),
                values.size() * sizeof(float));
      out.write(reinterpret_cast<const char *>(normals.data()),
                normals.size() * sizeof(float));
      if (!out)
        throw GeometryError("DistanceMap::save: writing '" + path
                            + "' failed (disk full?).");
    }

    DistanceMap
    DistanceMap::load(const std::string &path)
    {
      return load_checked(path, 0);
    }

    DistanceMap
    DistanceMap::load_checked(const std::string  &path,
                              const std::uint64_t expected)
    {
      const std::string where = "DistanceMap::load('" + path + "')";
      std::ifstream     in(path, std::ios::binary);
      if (!in)
        throw GeometryError(where + ": cannot open the file.");
      char         m[8];
      DistanceMap  map;
      std::int32_t dims[3];
      double       geo[4];
      in.read(m, sizeof(m));
      in.read(reinterpret_cast<char *>(&map.key), sizeof(map.key));
      in.read(reinterpret_cast<char *>(dims), sizeof(dims));
      in.read(reinterpret_cast<char *>(geo), sizeof(geo));
      if (!in || std::memcmp(m, magic, sizeof(magic)) != 0)
        throw GeometryError(where
                            + ": not a distance-map file of this version (bad "
                              "header).");
      if (expected != 0 && map.key != expected)
        throw GeometryError(where
                            + ": the file belongs to another mesh or "
                              "resolution (cache key mismatch).");
      double total = 1.;
      for (int d = 0; d < 3; ++d)
        {
          if (dims[d] < 2)
            throw GeometryError(where + ": invalid grid dimensions.");
          map.n[d] = dims[d];
          total *= dims[d];
        }
      if (!(geo[3] > 0.) || total > 2147483647.)
        throw GeometryError(where + ": invalid grid spacing or size.");
      map.x0 = Eigen::Vector3d(geo[0], geo[1], geo[2]);
      map.h  = geo[3];
      map.finish_setup();
      const auto np = static_cast<std::size_t>(total);
      // Check the length before allocating, so a corrupt header cannot ask for
      // gigabytes.
      const auto header = in.tellg();
      in.seekg(0, std::ios::end);
      const auto end = in.tellg();
      if (static_cast<std::size_t>(end - header) != np * 4 * sizeof(float))
        throw GeometryError(where
                            + ": the file is truncated or has extra bytes.");
      in.seekg(header);
      map.values.resize(np);
      map.normals.resize(3 * np);
      in.read(reinterpret_cast<char *>(map.values.data()), np * sizeof(float));
      in.read(reinterpret_cast<char *>(map.normals.data()),
              3 * np * sizeof(float));
      if (!in)
        throw GeometryError(where + ": reading the grid values failed.");
      return map;
    }

  } // namespace geometry
} // namespace particulate
