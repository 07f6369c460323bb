#include <particulate/geometry/triangle_mesh.h>

#include <cstring>
#include <utility>

namespace particulate {
  namespace geometry {

    TriangleMesh::TriangleMesh(std::vector<Eigen::Vector3d>    vertices_in,
                               std::vector<std::array<int, 3>> triangles_in)
      : vertices(std::move(vertices_in))
      , triangles(std::move(triangles_in))
    {}

    BoundingBox
    TriangleMesh::bounding_box() const
    {
      BoundingBox box;
      for (const auto &v : vertices)
        box.extend(v);
      return box;
    }

    TriangleMesh
    TriangleMesh::transformed(const Pose &pose) const
    {
      TriangleMesh out = *this;
      for (auto &v : out.vertices)
        v = pose.to_world(v);
      return out;
    }

    TriangleMesh
    TriangleMesh::scaled(const double factor) const
    {
      TriangleMesh out = *this;
      for (auto &v : out.vertices)
        v *= factor;
      return out;
    }

    void
    TriangleMesh::flip_orientation()
    {
      for (auto &t : triangles)
        std::swap(t[1], t[2]);
    }

    namespace {
      // FNV-1a over raw bytes: simple, stable across platforms with the same
      // endianness and double layout (IEEE 754), which is all the cache needs.
      void
      fnv1a(std::uint64_t &h, const void *data, const std::size_t n)
      {
        const auto *bytes = static_cast<const unsigned char *>(data);
        for (std::size_t i = 0; i < n; ++i)
          {
            h ^= bytes[i];
            h *= 1099511628211ull;
          }
      }
    } // namespace

    std::uint64_t
    TriangleMesh::content_hash() const
    {
      std::uint64_t       h  = 14695981039346656037ull;
      const std::uint64_t nv = vertices.size(), nt = triangles.size();
      fnv1a(h, &nv, sizeof(nv));
      fnv1a(h, &nt, sizeof(nt));
      for (const auto &v : vertices)
        {
          double c[3] = {v[0], v[1], v[2]};
          // +0 and -0 are the same position; make them the same bytes.
          for (double &x : c)
            if (x == 0.)
              x = 0.;
          fnv1a(h, c, sizeof(c));
        }
      for (const auto &t : triangles)
        {
          const std::int32_t c[3] = {t[0], t[1], t[2]};
          fnv1a(h, c, sizeof(c));
        }
      return h;
    }

  } // namespace geometry
} // namespace particulate
