#include <particulate/deformation/surface_resolution.h>

#include <deal.II/base/array_view.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/numerics/rtree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    namespace {
      Eigen::Vector3d
      eigen(const Point<3> &p)
      {
        return {p[0], p[1], p[2]};
      }

      /** What the rank's own cells contribute. */
      struct LocalSolid
      {
        unsigned long long    cells  = 0;
        double                volume = 0.;
        std::vector<Point<3>> face_points;
      };

      /** The rank's solid cells and the points of their faces that border
       *  fluid or the domain's boundary. */
      LocalSolid
      collect_solid_cells(const Triangulation<3> &tria,
                          const geometry::Shape  &shape,
                          const geometry::Pose   &pose)
      {
        const geometry::BoundingBox box   = pose.to_world(shape.bounding_box());
        const auto                  solid = [&](const auto &cell) {
          const Point<3> c = cell->center();
          for (unsigned int d = 0; d < 3; ++d)
            if (c[d] < box.lower[d] || c[d] > box.upper[d])
              return false;
          return shape.signed_distance(pose.to_body(eigen(c))) < 0.;
        };
        LocalSolid local;
        for (const auto &cell : tria.active_cell_iterators())
          {
            if (!cell->is_locally_owned() || !solid(cell))
              continue;
            ++local.cells;
            local.volume += cell->measure();
            for (const unsigned int f : cell->face_indices())
              if (cell->at_boundary(f) || !solid(cell->neighbor(f)))
                {
                  local.face_points.push_back(cell->face(f)->center());
                  for (const unsigned int v : cell->face(f)->vertex_indices())
                    local.face_points.push_back(cell->face(f)->vertex(v));
                }
          }
        return local;
      }

      /** The vertices and centroids of the shape's surface triangles,
       *  placed at @p pose. */
      std::vector<Point<3>>
      surface_points(const geometry::Shape &shape, const geometry::Pose &pose)
      {
        const geometry::TriangleMesh mesh = shape.surface_mesh();
        std::vector<Point<3>>        points;
        const auto                   add = [&](const Eigen::Vector3d &b) {
          const Eigen::Vector3d x = pose.to_world(b);
          points.emplace_back(x[0], x[1], x[2]);
        };
        for (const auto &v : mesh.vertices)
          add(v);
        for (const auto &t : mesh.triangles)
          add((mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]])
              / 3.);
        return points;
      }

      /** For each of @p targets, the distance to the nearest of @p points
       *  (infinite when there are none). */
      std::vector<double>
      nearest_distances(const std::vector<Point<3>> &points,
                        const std::vector<Point<3>> &targets)
      {
        std::vector<double> distances(targets.size(),
                                      std::numeric_limits<double>::infinity());
        if (points.empty())
          return distances;
        const auto            tree = pack_rtree(points);
        std::vector<Point<3>> nearest;
        for (std::size_t i = 0; i < targets.size(); ++i)
          {
            nearest.clear();
            tree.query(boost::geometry::index::nearest(targets[i], 1),
                       std::back_inserter(nearest));
            distances[i] = nearest.front().distance(targets[i]);
          }
        return distances;
      }
    } // namespace



    SurfaceResolution
    measure_surface_resolution(const Triangulation<3> &tria,
                               const geometry::Shape  &shape,
                               const geometry::Pose   &pose,
                               MPI_Comm                communicator)
    {
      const LocalSolid local   = collect_solid_cells(tria, shape, pose);
      double           largest = 0., sum = 0.;
      for (const Point<3> &x : local.face_points)
        {
          const double d
            = std::abs(shape.signed_distance(pose.to_body(eigen(x))));
          largest = std::max(largest, d);
          sum += d;
        }
      // each surface point's nearest face point over all ranks
      const std::vector<double> local_to_faces
        = nearest_distances(local.face_points, surface_points(shape, pose));
      std::vector<double> to_faces(local_to_faces.size());
      Utilities::MPI::min(make_array_view(local_to_faces),
                          communicator,
                          make_array_view(to_faces));
      for (const double d : to_faces)
        largest = std::max(largest, d);

      SurfaceResolution r;
      r.solid_cells = Utilities::MPI::sum(local.cells, communicator);
      r.hausdorff   = Utilities::MPI::max(largest, communicator);
      const double n_points
        = Utilities::MPI::sum(double(local.face_points.size()), communicator);
      r.mean_face_distance
        = n_points > 0. ? Utilities::MPI::sum(sum, communicator) / n_points :
                          0.;
      r.volume_error
        = Utilities::MPI::sum(local.volume, communicator) / shape.volume() - 1.;
      return r;
    }
  } // namespace deformation
} // namespace particulate
