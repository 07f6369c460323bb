#ifndef particulate_geometry_triangle_mesh_h
#define particulate_geometry_triangle_mesh_h

#include <particulate/geometry/bounding_box.h>
#include <particulate/geometry/pose.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace particulate {
  namespace geometry {

    /**
     * A triangulated surface as plain arrays: vertex positions and triangles of
     * vertex indices, counter-clockwise seen from outside (outward normals by
     * the right-hand rule). This is the exchange type of the module: readers
     * produce it, generators produce it, and the CGAL-based classes copy it
     * into their own structures, so that this header stays free of CGAL.
     */
    class TriangleMesh
    {
    public:
      /** Vertex positions [m]. */
      std::vector<Eigen::Vector3d> vertices;
      /** Triangles as indices into vertices. */
      std::vector<std::array<int, 3>> triangles;

      TriangleMesh() = default;

      /** A mesh from its arrays (no checks; see read_surface_mesh for
       *  those). */
      TriangleMesh(std::vector<Eigen::Vector3d>    vertices,
                   std::vector<std::array<int, 3>> triangles);

      /** Number of vertices. */
      std::size_t
      n_vertices() const
      {
        return vertices.size();
      }

      /** Number of triangles. */
      std::size_t
      n_triangles() const
      {
        return triangles.size();
      }

      /** The box of all vertices. */
      BoundingBox
      bounding_box() const;

      /** The mesh moved by @p pose (each vertex x becomes pose.to_world(x)). */
      TriangleMesh
      transformed(const Pose &pose) const;

      /** The mesh with every coordinate multiplied by @p factor (> 0). */
      TriangleMesh
      scaled(const double factor) const;

      /** Reverse the orientation of every triangle (swap inside and
       *  outside). */
      void
      flip_orientation();

      /**
       * A 64-bit FNV-1a hash of the exact vertex coordinates and triangle
       * indices. Used as the key of the distance-map cache: two meshes with the
       * same hash are the same bytes (up to hash collisions).
       */
      std::uint64_t
      content_hash() const;
    };

  } // namespace geometry
} // namespace particulate

#endif
