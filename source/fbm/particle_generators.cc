#include <particulate/fbm/particle_generators.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace particulate {
  namespace fbm {
    double
    placement_radius(const geometry::Shape &shape, const unsigned int dim)
    {
      if (dim == 3)
        return shape.bounding_radius();
      if (!shape.is_convex())
        {
          const geometry::BoundingBox b = shape.bounding_box();
          return std::hypot(std::max(-b.lower[0], b.upper[0]),
                            std::max(-b.lower[1], b.upper[1]));
        }
      // the farthest point of the section from the axis is the support
      // point in its own direction: a dense fan of directions finds it
      const unsigned int n = 2048;
      double             r = 0.;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double          phi = 2. * M_PI * i / n;
          const Eigen::Vector3d s
            = shape.support(Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.));
          r = std::max(r, s.head<2>().norm());
        }
      return r;
    }



    std::vector<Eigen::Vector3d>
    ParticleLattice::centres(const unsigned int dim) const
    {
      std::vector<Eigen::Vector3d> c;
      const unsigned int           nz = dim == 3 ? counts[2] : 1;
      if (double(counts[0]) * counts[1] * nz > maximum_generated_particles)
        throw std::runtime_error(
          "the lattice has " + std::to_string(counts[0]) + " x "
          + std::to_string(counts[1]) + " x " + std::to_string(nz)
          + " particles, more than the 10 million a run can hold (every "
            "rank keeps every particle).");
      for (unsigned int k = 0; k < nz; ++k)
        for (unsigned int j = 0; j < counts[1]; ++j)
          for (unsigned int i = 0; i < counts[0]; ++i)
            c.push_back(first + Eigen::Vector3d(i, j, k).cwiseProduct(spacing));
      return c;
    }



    namespace {
      /** Uniform numbers in [0, 1) from the 53 high bits of a 64-bit
       *  Mersenne twister: the same on every standard library. */
      class UniformNumbers
      {
      public:
        explicit UniformNumbers(const unsigned int seed)
          : engine(seed)
        {}

        double
        operator()()
        {
          return static_cast<double>(engine() >> 11) * 0x1.0p-53;
        }

      private:
        std::mt19937_64 engine;
      };

      /** A rotation uniformly distributed over SO(3) (Shoemake), or about z
       *  in 2D. */
      Eigen::Quaterniond
      random_rotation(UniformNumbers &uniform, const unsigned int dim)
      {
        if (dim == 2)
          return Eigen::Quaterniond(
            Eigen::AngleAxisd(2. * M_PI * uniform(), Eigen::Vector3d::UnitZ()));
        const double u1 = uniform(), u2 = 2. * M_PI * uniform(),
                     u3 = 2. * M_PI * uniform();
        const double a = std::sqrt(1. - u1), b = std::sqrt(u1);
        return Eigen::Quaterniond(b * std::cos(u3),
                                  a * std::sin(u2),
                                  a * std::cos(u2),
                                  b * std::sin(u3));
      }

      /** Balls in a uniform grid of cells as wide as the largest ball. */
      class BallGrid
      {
      public:
        BallGrid(const std::vector<OccupiedBall> &balls, const double r_new)
          : cell(2. * r_new)
        {
          for (const auto &b : balls)
            cell = std::max(cell, 2. * b.radius);
          for (const auto &b : balls)
            insert(b);
        }

        void
        insert(const OccupiedBall &b)
        {
          all.push_back(b);
          cells[key(index(b.centre))].push_back(all.size() - 1);
        }

        bool
        overlaps(const OccupiedBall &b, const unsigned int dim) const
        {
          const Eigen::Vector3i c  = index(b.centre);
          const int             kz = dim == 3 ? 1 : 0;
          for (int i = -1; i <= 1; ++i)
            for (int j = -1; j <= 1; ++j)
              for (int k = -kz; k <= kz; ++k)
                {
                  const auto it = cells.find(key(c + Eigen::Vector3i(i, j, k)));
                  if (it == cells.end())
                    continue;
                  for (const std::size_t n : it->second)
                    {
                      Eigen::Vector3d d = all[n].centre - b.centre;
                      if (dim == 2)
                        d[2] = 0.;
                      if (d.norm() < all[n].radius + b.radius)
                        return true;
                    }
                }
          return false;
        }

      private:
        Eigen::Vector3i
        index(const Eigen::Vector3d &x) const
        {
          return (x / cell).array().floor().cast<int>();
        }

        static std::int64_t
        key(const Eigen::Vector3i &c)
        {
          return (std::int64_t(c[0]) * 73856093)
                 ^ (std::int64_t(c[1]) * 19349663)
                 ^ (std::int64_t(c[2]) * 83492791);
        }

        double                                                     cell;
        std::vector<OccupiedBall>                                  all;
        std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
      };
    } // namespace



    double
    RandomFill::region_size(const unsigned int dim) const
    {
      const Eigen::Vector3d size = upper - lower;
      if (region == Region::cylinder)
        {
          if (dim != 3)
            throw std::runtime_error("a 'cylinder' region is a 3D one; a 2D "
                                     "fill takes a 'box'.");
          const double radius = 0.5 * std::min(size[0], size[1]);
          return M_PI * radius * radius * size[2];
        }
      return dim == 3 ? size.prod() : size[0] * size[1];
    }



    bool
    RandomFill::inside_region(const Eigen::Vector3d &centre,
                              const double           margin) const
    {
      if (region == Region::box)
        return true;
      const double radius
        = 0.5 * std::min(upper[0] - lower[0], upper[1] - lower[1]);
      return std::hypot(centre[0] - 0.5 * (lower[0] + upper[0]),
                        centre[1] - 0.5 * (lower[1] + upper[1]))
             <= radius - margin;
    }



    unsigned int
    RandomFill::n_particles(const geometry::Shape &shape,
                            const unsigned int     dim) const
    {
      const double n = solid_fraction * region_size(dim) / shape.volume();
      if (!(n <= maximum_generated_particles))
        throw std::runtime_error(
          "the solid fraction gives " + std::to_string(n)
          + " particles of this shape in the region, more than the 10 "
            "million a run can hold (every rank keeps every particle).");
      return static_cast<unsigned int>(std::lround(n));
    }



    std::vector<geometry::Pose>
    RandomFill::place(const geometry::Shape           &shape,
                      const unsigned int               dim,
                      const Eigen::Quaterniond        &orientation,
                      const std::vector<OccupiedBall> &occupied) const
    {
      const unsigned int n = n_particles(shape, dim);
      // a ball grown by half the clearance keeps that gap to every other
      // grown ball; it keeps a whole clearance to the box
      const double r      = placement_radius(shape, dim) + 0.5 * clearance;
      const double margin = r + 0.5 * clearance;
      if (n == 0)
        throw std::runtime_error(
          "the solid fraction gives no particle of this shape in the "
          "region; raise 'Solid fraction' or enlarge the region.");
      for (unsigned int d = 0; d < dim; ++d)
        if (!(upper[d] - lower[d] > 2. * margin))
          throw std::runtime_error(
            std::string("the region is narrower along ") + "xyz"[d]
            + " than a particle with its clearance ("
            + std::to_string(2. * margin) + " m across however it turns).");
      std::vector<OccupiedBall> grown = occupied;
      for (auto &b : grown)
        b.radius += 0.5 * clearance;
      UniformNumbers              uniform(seed);
      BallGrid                    grid(grown, r);
      std::vector<geometry::Pose> poses;
      const unsigned long         max_tries = 1000ul * n;
      for (unsigned long tries = 0; poses.size() < n && tries < max_tries;
           ++tries)
        {
          OccupiedBall ball{Eigen::Vector3d::Zero(), r};
          for (unsigned int d = 0; d < dim; ++d)
            ball.centre[d] = lower[d] + margin
                             + (upper[d] - lower[d] - 2. * margin) * uniform();
          const Eigen::Quaterniond q
            = random_orientation ? random_rotation(uniform, dim) : orientation;
          if (!inside_region(ball.centre, margin) || grid.overlaps(ball, dim))
            continue;
          grid.insert(ball);
          poses.emplace_back(q, ball.centre);
        }
      if (poses.size() < n)
        throw std::runtime_error(
          "placed " + std::to_string(poses.size()) + " of " + std::to_string(n)
          + " particles in 1000 tries each: random sequential placement "
            "jams near a solid fraction of 0.38 (3D) or 0.55 (2D) of the "
            "balls that hold the particles. Lower 'Solid fraction' or "
            "'Clearance', enlarge the region or use a 'Lattice'.");
      return poses;
    }
  } // namespace fbm
} // namespace particulate
