#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mass_properties.h>
#include <particulate/geometry/mesh_body.h>
#include <particulate/geometry/mesh_io.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>

namespace particulate {
  namespace geometry {

    namespace {
      /** @p bytes in MiB or GiB, three digits. */
      std::string
      in_memory_units(const double bytes)
      {
        const double       mib = bytes / (1024. * 1024.);
        std::ostringstream text;
        text.precision(3);
        if (mib < 1024.)
          text << mib << " MiB";
        else
          text << mib / 1024. << " GiB";
        return text.str();
      }

      std::string
      in_three_digits(const double x)
      {
        std::ostringstream text;
        text.precision(3);
        text << x;
        return text.str();
      }

      /** The map's spacing: the one asked for, or the automatic one. */
      double
      map_spacing(const BoundingBox &box, const MeshBodyOptions &options)
      {
        if (options.map_spacing > 0.)
          return options.map_spacing;
        return box.extent().minCoeff()
               / std::max(1u, options.automatic_cells_across);
      }

      /** The vertices of @p mesh in the frame @p frame: b = R^T (x - t). */
      void
      move_to_frame(TriangleMesh &mesh, const Pose &frame)
      {
        for (auto &v : mesh.vertices)
          v = frame.to_body(v);
      }

      DistanceMap
      build_map(const TriangleMesh            &mesh,
                const TriangulatedSurface     &surface,
                const DistanceMap::Parameters &parameters,
                const MeshBodyOptions         &options,
                bool                          &from_cache)
      {
        from_cache = false;
        if (options.cache_folder.empty())
          return DistanceMap::build(surface, parameters);
        return DistanceMap::build_cached(mesh,
                                         parameters,
                                         options.cache_folder,
                                         &from_cache);
      }

    } // namespace



    Eigen::Matrix3d
    principal_axes_nearest_identity(const Eigen::Matrix3d &inertia)
    {
      const double          size = inertia.diagonal().cwiseAbs().maxCoeff();
      const Eigen::Matrix3d off
        = inertia - Eigen::Matrix3d(inertia.diagonal().asDiagonal());
      if (off.cwiseAbs().maxCoeff() <= 1e-12 * size)
        return Eigen::Matrix3d::Identity();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
      const Eigen::Matrix3d axes = eig.eigenvectors();
      // Of the 48 orderings and signs of the axes, the right-handed one with
      // the largest trace: the smallest rotation away from the file's axes.
      std::array<int, 3> order{0, 1, 2};
      Eigen::Matrix3d    best  = axes;
      double             trace = -4.;
      do
        for (int signs = 0; signs < 8; ++signs)
          {
            Eigen::Matrix3d R;
            for (int c = 0; c < 3; ++c)
              R.col(c) = ((signs >> c) & 1 ? -1. : 1.) * axes.col(order[c]);
            if (R.determinant() > 0. && R.trace() > trace)
              {
                trace = R.trace();
                best  = R;
              }
          }
      while (std::next_permutation(order.begin(), order.end()));
      return best;
    }



    MeshBody
    load_mesh_body(const std::string &path, const MeshBodyOptions &options)
    {
      return make_mesh_body(read_surface_mesh(path), options, "'" + path + "'");
    }



    MeshBody
    make_mesh_body(TriangleMesh           mesh,
                   const MeshBodyOptions &options,
                   const std::string     &source)
    {
      if (!(options.scale > 0.) || !std::isfinite(options.scale))
        throw GeometryError(source
                            + ": the scale must be positive (it multiplies "
                              "the mesh's coordinates).");
      for (auto &v : mesh.vertices)
        v *= options.scale;

      // the principal frame, its axes as near the file's as they can be
      const MassProperties mass = compute_mass_properties(mesh);
      MeshBody             body;
      body.file_frame
        = Pose(principal_axes_nearest_identity(mass.inertia), mass.centre);
      move_to_frame(mesh, body.file_frame);
      auto surface = std::make_shared<const TriangulatedSurface>(mesh);

      DistanceMap::Parameters parameters;
      const BoundingBox       box = surface->bounding_box();
      parameters.spacing          = map_spacing(box, options);
      parameters.margin           = options.margin_cells * parameters.spacing;
      parameters.n_threads        = std::max(1u, options.n_threads);
      const std::size_t bytes
        = DistanceMap::planned_memory_bytes(box, parameters);
      if (options.memory_limit > 0 && bytes > options.memory_limit)
        throw GeometryError(
          source + ": its distance map at spacing "
          + in_three_digits(parameters.spacing) + " m would need "
          + in_memory_units(double(bytes)) + ", more than the "
          + in_memory_units(double(options.memory_limit))
          + " this run may use; give a larger map spacing (the memory falls "
            "with its cube).");

      auto map = std::make_shared<const DistanceMap>(
        build_map(mesh, *surface, parameters, options, body.from_cache));
      body.shape = std::make_shared<const MappedSurface>(surface, map);
      return body;
    }

  } // namespace geometry
} // namespace particulate
