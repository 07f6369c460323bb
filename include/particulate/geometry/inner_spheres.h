#ifndef particulate_geometry_inner_spheres_h
#define particulate_geometry_inner_spheres_h

#include <particulate/geometry/bounding_box.h>
#include <particulate/geometry/distance_map.h>
#include <particulate/geometry/inner_sphere_data.h>
#include <particulate/geometry/pose.h>

#include <Eigen/Core>

#include <vector>

namespace particulate {
  namespace geometry {

    /**
     * An inner-sphere representation of a body (thesis §3.4.2, fig. 3.19): a
     * set of spheres in the body frame whose union approximates the body's
     * volume, so that point classification only has to look at the mesh points
     * inside the spheres. Built from a distance map in one of two ways:
     *
     * - from_cells(): the thesis' construction, the bounding sphere (radius
     *   sqrt(3)/2 h) of every map cell whose centre is inside, i.e. whose mean
     *   corner distance is negative. Since a distance function is 1-Lipschitz,
     *   the centre's distance is at most min_corner d + sqrt(3)/2 h; where that
     *   bound would let the sphere reach more than one cell (h) out of the
     *   body, the radius is reduced to h - bound, so the one-cell limit holds
     *   even in features thinner than a cell.
     * - greedy(): largest spheres first. Every interior grid point c carries
     *   the largest sphere inside the body centred there, radius -d(c),
     *   inflated by a fraction of h (default h/2) so that the thin layer
     *   between the last interior grid points and the surface is covered too;
     *   the points are taken by decreasing radius, skipping those already
     *   covered, until the requested fraction of interior grid points is
     *   covered. Since d is the exact distance at grid points, a sphere leaves
     *   the body by at most the inflation, and far fewer spheres are needed
     *   than cells.
     *
     * contains() uses a uniform bucket grid over the spheres, so a query costs
     * the few spheres near the point.
     */
    class InnerSpheres
    {
    public:
      /** One sphere, body frame [m]. */
      struct Ball
      {
        Eigen::Vector3d centre;
        double          radius;
      };

      /** Parameters of greedy(). */
      struct PackingParameters
      {
        /** Stop when this fraction of the interior grid points is covered. */
        double target_coverage = 0.97;
        /** Do not place spheres smaller than this [m]; 0 means a quarter of the
         *  map spacing. */
        double min_radius = 0.;
        /** Radius added to the inscribed radius -d(c), as a fraction of the map
         *  spacing h, in [0, 1): how far a sphere may reach out of the body. */
        double inflation = 0.5;
        /** Upper limit on the number of spheres. */
        std::size_t max_spheres = 1000000;
      };

      InnerSpheres() = default;

      /** Spheres given directly (body frame). */
      explicit InnerSpheres(std::vector<Ball> balls);

      /** The thesis' cell-sphere construction (see the class documentation). */
      static InnerSpheres
      from_cells(const DistanceMap &map);

      /** Greedy largest-sphere packing (see the class documentation). */
      static InnerSpheres
      greedy(const DistanceMap &map, const PackingParameters &parameters);

      /** Same, with default parameters. */
      static InnerSpheres
      greedy(const DistanceMap &map)
      {
        return greedy(map, PackingParameters());
      }

      /** True if the body-frame point @p p is in (or on) some sphere. */
      bool
      contains(const Eigen::Vector3d &p) const;

      /** True if the world point @p x is in some sphere of the body at @p pose.
       */
      bool
      contains(const Eigen::Vector3d &x, const Pose &pose) const
      {
        return contains(pose.to_body(x));
      }

      /** The spheres. */
      const std::vector<Ball> &
      balls() const
      {
        return spheres;
      }

      /** Number of spheres. */
      std::size_t
      size() const
      {
        return spheres.size();
      }

      /** Box around all spheres, body frame [m]. */
      BoundingBox
      bounding_box() const
      {
        return box;
      }

      /** Raw arrays for the CUDA kernels (single precision, body frame). */
      InnerSphereData
      export_data() const;

    private:
      std::vector<Ball> spheres;
      BoundingBox       box;
      // Bucket grid: sphere ids per bucket in CSR form.
      Eigen::Vector3d       bucket_origin = Eigen::Vector3d::Zero();
      double                bucket_size   = 1.;
      std::array<int, 3>    n_buckets     = {0, 0, 0};
      std::vector<unsigned> bucket_start, bucket_items;

      void
      build_buckets();
    };

  } // namespace geometry
} // namespace particulate

#endif
