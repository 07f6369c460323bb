#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_generators.h>

#include <cmath>
#include <map>
#include <utility>

namespace particulate {
  namespace geometry {
    namespace mesh_generators {

      TriangleMesh
      icosphere(const double radius, const unsigned int refinements)
      {
        if (!(radius > 0.))
          throw GeometryError("icosphere: the radius must be positive.");
        if (refinements > 9)
          throw GeometryError(
            "icosphere: more than 9 refinements (5 million triangles) requested; "
            "use fewer.");

        const double                 g = (1. + std::sqrt(5.)) / 2.;
        std::vector<Eigen::Vector3d> v = {{-1, g, 0},
                                          {1, g, 0},
                                          {-1, -g, 0},
                                          {1, -g, 0},
                                          {0, -1, g},
                                          {0, 1, g},
                                          {0, -1, -g},
                                          {0, 1, -g},
                                          {g, 0, -1},
                                          {g, 0, 1},
                                          {-g, 0, -1},
                                          {-g, 0, 1}};
        for (auto &p : v)
          p.normalize();
        std::vector<std::array<int, 3>> t
          = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

        for (unsigned int r = 0; r < refinements; ++r)
          {
            // One midpoint per edge, shared by the two triangles of the edge.
            std::map<std::pair<int, int>, int> midpoint;
            auto                               mid = [&](int a, int b) {
              const auto key = std::minmax(a, b);
              auto       it  = midpoint.find(key);
              if (it != midpoint.end())
                return it->second;
              v.push_back((v[a] + v[b]).normalized());
              const int id = static_cast<int>(v.size()) - 1;
              midpoint.emplace(key, id);
              return id;
            };
            std::vector<std::array<int, 3>> refined;
            refined.reserve(4 * t.size());
            for (const auto &tri : t)
              {
                const int a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]),
                          c = mid(tri[2], tri[0]);
                refined.push_back({tri[0], a, c});
                refined.push_back({tri[1], b, a});
                refined.push_back({tri[2], c, b});
                refined.push_back({a, b, c});
              }
            t = std::move(refined);
          }
        for (auto &p : v)
          p *= radius;
        return TriangleMesh(std::move(v), std::move(t));
      }

      TriangleMesh
      box(const Eigen::Vector3d &half_extents, const unsigned int subdivisions)
      {
        if (!(half_extents.array() > 0.).all())
          throw GeometryError("box: all half extents must be positive.");
        if (subdivisions < 1 || subdivisions > 1000)
          throw GeometryError("box: subdivisions must lie in [1, 1000].");
        const int n = static_cast<int>(subdivisions);

        // Vertices on the surface of the (n+1)^3 lattice, indexed through a map
        // so that faces share their edge vertices.
        std::map<std::array<int, 3>, int> index;
        std::vector<Eigen::Vector3d>      v;
        auto                              vertex = [&](int i, int j, int k) {
          const std::array<int, 3> key = {i, j, k};
          auto                     it = index.find(key);
          if (it != index.end())
            return it->second;
          v.emplace_back(half_extents[0] * (2. * i / n - 1.),
                         half_extents[1] * (2. * j / n - 1.),
                         half_extents[2] * (2. * k / n - 1.));
          const int id = static_cast<int>(v.size()) - 1;
          index.emplace(key, id);
          return id;
        };

        std::vector<std::array<int, 3>> t;
        // For each axis d and side s (0: lower, 1: upper) the face is spanned
        // by the two other axes (d1, d2) in right-handed order; the lower face
        // is traversed the other way round so that normals point outward.
        for (int d = 0; d < 3; ++d)
          for (int s = 0; s < 2; ++s)
            {
              const int d1 = (d + 1) % 3, d2 = (d + 2) % 3;
              for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b)
                  {
                    auto at = [&](int p, int q) {
                      std::array<int, 3> c;
                      c[d]  = s * n;
                      c[d1] = p;
                      c[d2] = q;
                      return vertex(c[0], c[1], c[2]);
                    };
                    const int v00 = at(a, b), v10 = at(a + 1, b),
                              v11 = at(a + 1, b + 1), v01 = at(a, b + 1);
                    if (s == 1)
                      {
                        t.push_back({v00, v10, v11});
                        t.push_back({v00, v11, v01});
                      }
                    else
                      {
                        t.push_back({v00, v11, v10});
                        t.push_back({v00, v01, v11});
                      }
                  }
            }
        return TriangleMesh(std::move(v), std::move(t));
      }

      TriangleMesh
      torus(const double       major_radius,
            const double       minor_radius,
            const unsigned int n_major,
            const unsigned int n_minor)
      {
        if (!(minor_radius > 0.) || !(major_radius > minor_radius))
          throw GeometryError(
            "torus: need 0 < minor radius < major radius (a ring torus).");
        if (n_major < 3 || n_minor < 3)
          throw GeometryError(
            "torus: need at least 3 segments in each direction.");
        std::vector<Eigen::Vector3d>    v;
        std::vector<std::array<int, 3>> t;
        const double                    pi = std::acos(-1.);
        for (unsigned int i = 0; i < n_major; ++i)
          for (unsigned int j = 0; j < n_minor; ++j)
            {
              const double u = 2. * pi * i / n_major, w = 2. * pi * j / n_minor;
              const double rho = major_radius + minor_radius * std::cos(w);
              v.emplace_back(rho * std::cos(u),
                             rho * std::sin(u),
                             minor_radius * std::sin(w));
            }
        auto id = [&](unsigned int i, unsigned int j) {
          return static_cast<int>((i % n_major) * n_minor + (j % n_minor));
        };
        for (unsigned int i = 0; i < n_major; ++i)
          for (unsigned int j = 0; j < n_minor; ++j)
            {
              const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1),
                        d = id(i, j + 1);
              t.push_back({a, b, c});
              t.push_back({a, c, d});
            }
        return TriangleMesh(std::move(v), std::move(t));
      }

      namespace {
        /** Triangles that join the ring of @p n vertices starting at @p upper
         *  to the ring below it starting at @p lower, outward for rings
         *  ordered counter-clockwise seen from +z. */
        void
        join_rings(std::vector<std::array<int, 3>> &t,
                   const int                        upper,
                   const int                        lower,
                   const int                        n)
        {
          for (int k = 0; k < n; ++k)
            {
              const int k1 = (k + 1) % n;
              t.push_back({upper + k, lower + k, lower + k1});
              t.push_back({upper + k, lower + k1, upper + k1});
            }
        }

        /** The fan from the apex @p apex to the ring of @p n vertices at
         *  @p ring; @p on_top: the apex lies above the ring (+z). */
        void
        close_ring(std::vector<std::array<int, 3>> &t,
                   const int                        apex,
                   const int                        ring,
                   const int                        n,
                   const bool                       on_top)
        {
          for (int k = 0; k < n; ++k)
            {
              const int k1 = (k + 1) % n;
              if (on_top)
                t.push_back({apex, ring + k, ring + k1});
              else
                t.push_back({apex, ring + k1, ring + k});
            }
        }
      } // namespace



      TriangleMesh
      elliptic_prism(const double       semi_axis_x,
                     const double       semi_axis_y,
                     const double       half_height,
                     const unsigned int n_around)
      {
        if (!(semi_axis_x > 0.) || !(semi_axis_y > 0.) || !(half_height > 0.))
          throw GeometryError(
            "elliptic_prism: semi-axes and half height must be positive.");
        if (n_around < 3)
          throw GeometryError(
            "elliptic_prism: need at least 3 segments around.");
        const int                       n  = static_cast<int>(n_around);
        const double                    pi = std::acos(-1.);
        std::vector<Eigen::Vector3d>    v;
        std::vector<std::array<int, 3>> t;
        for (const double z : {half_height, -half_height})
          for (int k = 0; k < n; ++k)
            v.emplace_back(semi_axis_x * std::cos(2. * pi * k / n),
                           semi_axis_y * std::sin(2. * pi * k / n),
                           z);
        v.emplace_back(0., 0., half_height);
        v.emplace_back(0., 0., -half_height);
        join_rings(t, 0, n, n);
        close_ring(t, 2 * n, 0, n, true);
        close_ring(t, 2 * n + 1, n, n, false);
        return TriangleMesh(std::move(v), std::move(t));
      }



      TriangleMesh
      capsule(const double       radius,
              const double       half_length,
              const unsigned int n_around)
      {
        if (!(radius > 0.) || !(half_length >= 0.))
          throw GeometryError("capsule: need radius > 0 and half length >= 0.");
        if (n_around < 4 || n_around % 2 != 0)
          throw GeometryError(
            "capsule: the number of segments around must be even and at least "
            "4.");
        const int                       n  = static_cast<int>(n_around);
        const int                       m  = n / 2; // rings per hemisphere
        const double                    pi = std::acos(-1.);
        std::vector<Eigen::Vector3d>    v;
        std::vector<std::array<int, 3>> t;
        // rings j = 1 .. m of the polar angle j pi / (2 m) over each
        // hemisphere, the northern one shifted up, the southern one down
        for (const double side : {1., -1.})
          for (int j = 1; j <= m; ++j)
            {
              const int    jj    = side > 0. ? j : m + 1 - j;
              const double theta = 0.5 * pi * jj / m;
              for (int k = 0; k < n; ++k)
                v.emplace_back(radius * std::sin(theta)
                                 * std::cos(2. * pi * k / n),
                               radius * std::sin(theta)
                                 * std::sin(2. * pi * k / n),
                               side * (half_length + radius * std::cos(theta)));
            }
        v.emplace_back(0., 0., half_length + radius);
        v.emplace_back(0., 0., -half_length - radius);
        for (int ring = 0; ring + 1 < 2 * m; ++ring)
          join_rings(t, ring * n, (ring + 1) * n, n);
        close_ring(t, 2 * m * n, 0, n, true);
        close_ring(t, 2 * m * n + 1, (2 * m - 1) * n, n, false);
        return TriangleMesh(std::move(v), std::move(t));
      }

    } // namespace mesh_generators
  }   // namespace geometry
} // namespace particulate
