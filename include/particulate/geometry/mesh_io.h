#ifndef particulate_geometry_mesh_io_h
#define particulate_geometry_mesh_io_h

#include <particulate/geometry/triangle_mesh.h>

#include <cstddef>
#include <string>

namespace particulate {
  namespace geometry {

    /**
     * What check_surface_mesh() found wrong with a triangulated surface. A mesh
     * that bounds a solid (what the signed distance, the distance map, the
     * inside test and the mass properties need) has every count zero.
     */
    struct MeshCheck
    {
      /** Vertex indices outside [0, n_vertices). */
      std::size_t invalid_indices = 0;
      /** Vertices with a NaN or infinite coordinate. */
      std::size_t non_finite_vertices = 0;
      /** Triangles with a repeated vertex or three collinear vertices. */
      std::size_t degenerate_triangles = 0;
      /** Edges used by exactly one triangle (holes: the surface is open). */
      std::size_t border_edges = 0;
      /** Edges shared by more than two triangles. */
      std::size_t non_manifold_edges = 0;
      /** Vertices whose triangles form more than one fan (pinched vertices). */
      std::size_t non_manifold_vertices = 0;
      /** Edges whose two triangles traverse them the same way (flipped
       *  faces). */
      std::size_t inconsistent_edges = 0;
      /** Pairs of triangles that intersect other than in a shared
       *  edge/vertex. */
      std::size_t self_intersecting_pairs = 0;
      /** True if the self-intersection test ran (it is skipped when the surface
       *  is already known to be unusable, and can be switched off). */
      bool self_intersections_checked = false;

      /** Vertex count of the checked mesh. */
      std::size_t n_vertices = 0;
      /** Triangle count of the checked mesh. */
      std::size_t n_triangles = 0;

      /** A short example of the first problem found (vertex ids, positions). */
      std::string first_problem;

      /** True if the surface bounds a solid: closed, manifold, consistently
       *  oriented, without self-intersections, nothing degenerate, not
       *  empty. */
      bool
      bounds_a_solid() const;

      /** One line per problem, e.g. "open: 12 border edges". Empty if none. */
      std::string
      describe() const;
    };

    /** Options of read_surface_mesh(). */
    struct MeshReadOptions
    {
      /** Test every pair of triangles for intersection (CGAL box intersection,
       *  about a second per 100k triangles). */
      bool check_self_intersections = true;
      /** Repair a consistent orientation by flipping triangles, and flip the
       *  whole surface if it encloses a negative volume. If false, a wrongly
       *  oriented surface is an error. */
      bool orient = true;
    };

    /**
     * Check a triangulated surface for the defects listed in MeshCheck.
     *
     * @param mesh the surface
     * @param check_self_intersections run the (more expensive)
     *   intersection test
     */
    MeshCheck
    check_surface_mesh(const TriangleMesh &mesh,
                       const bool          check_self_intersections = true);

    /**
     * Read a closed triangulated surface from an OFF, STL (ASCII or binary),
     * OBJ or PLY file (chosen by the file extension) with CGAL's readers.
     * Polygons with more than three vertices are split into triangle fans. The
     * surface is checked with check_surface_mesh(); its triangles are oriented
     * consistently and outward (positive enclosed volume). Vertices used by no
     * triangle are dropped.
     *
     * @param path file to read
     * @param options what to check and repair
     * @throw GeometryError if the file is missing, unreadable, empty, or the
     *   surface does not bound a solid; the message names the file and the
     *   defect ("open: 12 border edges", "3 self-intersecting triangle pairs").
     */
    TriangleMesh
    read_surface_mesh(const std::string     &path,
                      const MeshReadOptions &options = MeshReadOptions());

    /**
     * Write @p mesh to @p path (OFF, STL, OBJ or PLY by the extension, ASCII).
     * @throw GeometryError if the file cannot be written.
     */
    void
    write_surface_mesh(const std::string &path, const TriangleMesh &mesh);

  } // namespace geometry
} // namespace particulate

#endif
