#ifndef particulate_geometry_mesh_body_h
#define particulate_geometry_mesh_body_h

#include <particulate/geometry/mapped_surface.h>
#include <particulate/geometry/pose.h>

#include <cstddef>
#include <memory>
#include <string>

namespace particulate {
  namespace geometry {

    /** How load_mesh_body() makes a body from a surface-mesh file. */
    struct MeshBodyOptions
    {
      /** Factor applied to the file's coordinates (e.g. 0.001 for a file in
       *  millimetres); > 0. */
      double scale = 1.;
      /** Spacing h of the distance map [m]; 0: automatic, the smallest edge
       *  of the scaled mesh's bounding box divided by
       *  automatic_cells_across. */
      double map_spacing = 0.;
      /** Map cells across the thinnest extent of the body when the spacing
       *  is automatic. */
      unsigned int automatic_cells_across = 16;
      /** Map cells of margin added on every side of the bounding box (the
       *  map answers exactly inside it, by a bound outside). */
      unsigned int margin_cells = 4;
      /** Folder where maps are cached by mesh contents, spacing and margin
       *  (created if missing); empty: no cache. */
      std::string cache_folder;
      /** Largest map [bytes] that may be built; a larger one is refused
       *  before any work with what it would need. */
      std::size_t memory_limit = 0;
      /** Threads that fill the map. */
      unsigned int n_threads = 1;
    };

    /** A body made from a surface mesh, and how it relates to the file. */
    struct MeshBody
    {
      /** The body in its principal frame (centroid at the origin, principal
       *  axes along the body axes). */
      std::shared_ptr<const MappedSurface> shape;
      /** The body frame as seen in the (scaled) file's coordinates: its
       *  translation is the centroid, its rotation turns body axes into file
       *  axes. A body placed with this rotation looks as in the file. */
      Pose file_frame;
      /** Whether the map was read from the cache. */
      bool from_cache = false;
    };

    /**
     * Read a closed surface mesh (OFF, STL, OBJ or PLY; see
     * read_surface_mesh(), which orients its triangles outward), scale it,
     * move it to its principal frame and build (or read from the cache) its
     * distance map. The principal axes are ordered and signed to be as close
     * to the file's axes as they can be, so that an aligned body keeps its
     * axes.
     * @throw GeometryError naming the file for a missing, unreadable or
     *   unusable mesh (open, non-manifold, self-intersecting), a scale that
     *   is not positive, or a map larger than MeshBodyOptions::memory_limit
     *   (with the bytes it needs)
     */
    MeshBody
    load_mesh_body(const std::string &path, const MeshBodyOptions &options);

    /**
     * The same for a surface already in memory (closed, outward-oriented).
     * @param source what to call it in messages
     */
    MeshBody
    make_mesh_body(TriangleMesh           mesh,
                   const MeshBodyOptions &options,
                   const std::string     &source);

    /**
     * The rotation whose columns are the principal axes of the symmetric
     * tensor @p inertia, ordered and signed to be nearest the identity (the
     * identity itself when the tensor is diagonal to rounding).
     */
    Eigen::Matrix3d
    principal_axes_nearest_identity(const Eigen::Matrix3d &inertia);

  } // namespace geometry
} // namespace particulate

#endif
