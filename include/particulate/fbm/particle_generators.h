#ifndef particulate_fbm_particle_generators_h
#define particulate_fbm_particle_generators_h

#include <particulate/geometry/pose.h>
#include <particulate/geometry/shape.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * The radius of the ball (3D) or of the disk about the body's z axis
     * (2D, where bodies are prisms along z) that holds @p shape however it
     * turns in a run of dimension @p dim [m].
     */
    double
    placement_radius(const geometry::Shape &shape, const unsigned int dim);

    /** A ball (3D) or disk (2D) that a placed particle occupies. */
    struct OccupiedBall
    {
      Eigen::Vector3d centre;
      double          radius;
    };

    /**
     * The most particles a generator makes: the rigid engine holds every
     * particle on every rank (a few kB each with its contacts), so ten
     * million is beyond any machine's ranks; larger counts are refused
     * before anything is allocated.
     */
    constexpr double maximum_generated_particles = 1e7;

    /**
     * Particles on a regular lattice: centres first + (i, j, k) * spacing
     * for i < counts[0], j < counts[1], k < counts[2] (x fastest), all with
     * one orientation. A 2D run uses the first two counts.
     */
    struct ParticleLattice
    {
      Eigen::Vector3d             first   = Eigen::Vector3d::Zero(); ///< [m]
      Eigen::Vector3d             spacing = Eigen::Vector3d::Zero(); ///< [m]
      std::array<unsigned int, 3> counts  = {{1, 1, 1}};

      /** The centres [m] of a @p dim-dimensional run.
       * @throw std::runtime_error for more than
       *   maximum_generated_particles */
      std::vector<Eigen::Vector3d>
      centres(const unsigned int dim) const;
    };

    /**
     * A random non-overlapping fill of the box [lower, upper] with copies of
     * one shape at a given solid fraction (random sequential addition): the
     * number of particles is the solid fraction times the box's volume (2D:
     * area) over the shape's, rounded; each is placed at a uniformly random
     * centre, with a uniformly random orientation if asked, and kept if the
     * ball of its placement_radius() lies in the box and meets no ball
     * placed before it, of this fill or given as occupied. Balls that do
     * not overlap are a sufficient condition for bodies that do not.
     *
     * Random sequential addition of equal balls jams near a solid fraction
     * of 0.38 (3D) and 0.55 (2D) of the balls; elongated shapes reach less.
     * The same seed gives the same particles on every machine.
     */
    struct RandomFill
    {
      /** What the particles fill: the box, or the cylinder along z
       *  inscribed in it (axis through the centre of its x-y rectangle,
       *  radius half the rectangle's shorter side; 3D only). */
      enum class Region
      {
        box,
        cylinder
      };
      Eigen::Vector3d lower              = Eigen::Vector3d::Zero(); ///< [m]
      Eigen::Vector3d upper              = Eigen::Vector3d::Zero(); ///< [m]
      Region          region             = Region::box;
      double          solid_fraction     = 0.; ///< [-]
      unsigned int    seed               = 1;
      bool            random_orientation = false;
      /** Smallest gap [m] between the balls that hold the particles, and
       *  between them and the box's faces and the @p occupied balls. */
      double clearance = 0.;

      /**
       * The poses of the particles of shape @p shape, placed around
       * @p occupied, with @p orientation where they are not turned at
       * random; every ball that holds a particle keeps the clearance to the
       * others and to the box.
       * @throw std::runtime_error when no particle fits or 1000 tries per
       *   particle do not place them all (saying how many were placed)
       */
      std::vector<geometry::Pose>
      place(const geometry::Shape           &shape,
            const unsigned int               dim,
            const Eigen::Quaterniond        &orientation,
            const std::vector<OccupiedBall> &occupied) const;

      /** The number of particles the fill places. */
      unsigned int
      n_particles(const geometry::Shape &shape, const unsigned int dim) const;

    private:
      /** The volume (2D: area) of the region [m^3]. */
      double
      region_size(const unsigned int dim) const;

      /** Whether a ball at @p centre, kept @p margin from the region's
       *  boundary, lies in the cylinder (always for a box: the centre is
       *  drawn inside its margin). */
      bool
      inside_region(const Eigen::Vector3d &centre, const double margin) const;
    };
  } // namespace fbm
} // namespace particulate

#endif
