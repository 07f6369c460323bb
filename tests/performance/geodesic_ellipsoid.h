#ifndef particulate_tests_performance_geodesic_ellipsoid_h
#define particulate_tests_performance_geodesic_ellipsoid_h

// A closed ellipsoid mesh of any resolution for the benchmarks, generated in
// code so that they need no files: the icosahedron's faces split into
// n x n triangles each (a geodesic sphere of frequency n: 10 n^2 + 2
// vertices, 20 n^2 triangles, nearly uniform), the vertices projected onto
// the unit sphere and scaled by the semi-axes. mesh_generators::icosphere
// only gives n = 2^k; this fills in the sizes between.

#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/triangle_mesh.h>

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

namespace particulate {
  namespace benchmarks {

    /** Vertices of geodesic_ellipsoid(frequency n). */
    inline unsigned int
    geodesic_vertices(const unsigned int n)
    {
      return 10 * n * n + 2;
    }

    /**
     * The ellipsoid with semi-axes @p semi_axes [m] as a geodesic mesh of
     * frequency @p n >= 1 (n = 1: the icosahedron), outward oriented, its
     * vertices on the ellipsoid.
     */
    inline geometry::TriangleMesh
    geodesic_ellipsoid(const Eigen::Vector3d &semi_axes, const unsigned int n)
    {
      const geometry::TriangleMesh ico
        = geometry::mesh_generators::icosphere(1., 0);
      geometry::TriangleMesh mesh;
      // A point is n-ths of the icosahedron's corners: (corner, weight)
      // pairs sorted by corner, so that the faces sharing an edge or corner
      // find (and compute) the same vertex.
      using Key = std::array<int, 6>;
      std::map<Key, int> index;
      auto               vertex = [&](std::array<std::pair<int, int>, 3> w) {
        std::sort(w.begin(), w.end());
        Key             key{{-1, 0, -1, 0, -1, 0}};
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        int             k = 0;
        for (const auto &[corner, weight] : w)
          if (weight > 0)
            {
              key[2 * k]     = corner;
              key[2 * k + 1] = weight;
              p += double(weight) / n * ico.vertices[corner];
              ++k;
            }
        const auto [it, fresh] = index.emplace(key, int(mesh.vertices.size()));
        if (fresh)
          mesh.vertices.push_back(semi_axes.cwiseProduct(p.normalized()));
        return it->second;
      };
      const int m = int(n);
      for (const auto &t : ico.triangles)
        {
          // P(i, j) = A + i/n (B - A) + j/n (C - A)
          auto P = [&](const int i, const int j) {
            return vertex({{{t[0], m - i - j}, {t[1], i}, {t[2], j}}});
          };
          for (int i = 0; i < m; ++i)
            for (int j = 0; i + j < m; ++j)
              {
                mesh.triangles.push_back({{P(i, j), P(i + 1, j), P(i, j + 1)}});
                if (i + j < m - 1)
                  mesh.triangles.push_back(
                    {{P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)}});
              }
        }
      return mesh;
    }

  } // namespace benchmarks
} // namespace particulate

#endif
