#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/inner_spheres.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace particulate {
  namespace geometry {

    InnerSpheres::InnerSpheres(std::vector<Ball> balls)
      : spheres(std::move(balls))
    {
      for (const auto &b : spheres)
        if (!(b.radius >= 0.) || !b.centre.allFinite())
          throw GeometryError("InnerSpheres: sphere radii must be >= 0 and "
                              "centres finite.");
      build_buckets();
    }

    InnerSpheres
    InnerSpheres::from_cells(const DistanceMap &map)
    {
      const auto       &n             = map.n_points();
      const double      h             = map.spacing();
      const double      half_diagonal = 0.5 * std::sqrt(3.) * h;
      std::vector<Ball> balls;
      for (int k = 0; k + 1 < n[2]; ++k)
        for (int j = 0; j + 1 < n[1]; ++j)
          for (int i = 0; i + 1 < n[0]; ++i)
            {
              // Trilinear value at the cell centre: the mean of the corners.
              double centre = 0., lowest = 1e300;
              for (int c = 0; c < 8; ++c)
                {
                  const double v = map.value(i + (c & 1),
                                             j + ((c >> 1) & 1),
                                             k + ((c >> 2) & 1));
                  centre += v;
                  lowest = std::min(lowest, v);
                }
              if (!(centre < 0.))
                continue;
              // Upper bound of the true distance at the centre (Lipschitz).
              const double bound  = lowest + half_diagonal;
              const double radius = std::min(half_diagonal, h - bound);
              if (radius > 0.)
                balls.push_back(
                  {map.point(i, j, k) + Eigen::Vector3d::Constant(0.5 * h),
                   radius});
            }
      return InnerSpheres(std::move(balls));
    }

    InnerSpheres
    InnerSpheres::greedy(const DistanceMap &map, const PackingParameters &prm)
    {
      if (!(prm.target_coverage > 0.) || prm.target_coverage > 1.)
        throw GeometryError(
          "InnerSpheres::greedy: the target coverage must lie in (0, 1].");
      if (!(prm.inflation >= 0.) || !(prm.inflation < 1.))
        throw GeometryError(
          "InnerSpheres::greedy: the inflation must lie in [0, 1) (a fraction of "
          "the map spacing).");
      const auto  &n     = map.n_points();
      const double h     = map.spacing();
      const double r_min = prm.min_radius > 0. ? prm.min_radius : 0.25 * h;

      // Interior grid points, largest inscribed sphere first.
      std::vector<std::size_t> interior;
      const std::size_t        total = std::size_t(n[0]) * n[1] * n[2];
      std::vector<double>      value(total);
      for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i)
            {
              const std::size_t id = map.index(i, j, k);
              value[id]            = map.value(i, j, k);
              if (value[id] < 0.)
                interior.push_back(id);
            }
      std::stable_sort(interior.begin(),
                       interior.end(),
                       [&](std::size_t a, std::size_t b) {
                         return value[a] < value[b];
                       });

      std::vector<char> covered(total, 0);
      std::size_t       n_covered = 0;
      const auto        target    = static_cast<std::size_t>(
        std::ceil(prm.target_coverage * static_cast<double>(interior.size())));
      std::vector<Ball> balls;
      for (const std::size_t id : interior)
        {
          if (n_covered >= target || balls.size() >= prm.max_spheres)
            break;
          if (covered[id])
            continue;
          const double r = -value[id] + prm.inflation * h;
          if (r < r_min)
            break; // all remaining candidates are smaller still
          const int i = static_cast<int>(id % n[0]),
                    j = static_cast<int>((id / n[0]) % n[1]),
                    k = static_cast<int>(id / (std::size_t(n[0]) * n[1]));
          const Eigen::Vector3d c = map.point(i, j, k);
          balls.push_back({c, r});
          // Mark the interior grid points inside the new sphere.
          const int w = static_cast<int>(std::floor(r / h));
          for (int kk = std::max(0, k - w); kk <= std::min(n[2] - 1, k + w);
               ++kk)
            for (int jj = std::max(0, j - w); jj <= std::min(n[1] - 1, j + w);
                 ++jj)
              for (int ii = std::max(0, i - w); ii <= std::min(n[0] - 1, i + w);
                   ++ii)
                {
                  const std::size_t q = map.index(ii, jj, kk);
                  if (!covered[q] && value[q] < 0.
                      && (map.point(ii, jj, kk) - c).squaredNorm() <= r * r)
                    {
                      covered[q] = 1;
                      ++n_covered;
                    }
                }
          if (!covered[id])
            {
              covered[id] = 1;
              ++n_covered;
            }
        }
      return InnerSpheres(std::move(balls));
    }

    void
    InnerSpheres::build_buckets()
    {
      box = BoundingBox();
      if (spheres.empty())
        return;
      double mean_r = 0.;
      for (const auto &b : spheres)
        {
          box.extend(b.centre.array() - b.radius);
          box.extend(b.centre.array() + b.radius);
          mean_r += b.radius;
        }
      mean_r /= spheres.size();
      // Buckets about the size of a typical sphere, at most ~64^3 of them.
      const double extent = box.extent().maxCoeff();
      bucket_size         = std::max({2. * mean_r, extent / 64., 1e-300});
      bucket_origin       = box.lower;
      for (int d = 0; d < 3; ++d)
        n_buckets[d] = std::max(1,
                                static_cast<int>(
                                  std::ceil(box.extent()[d] / bucket_size)));
      const std::size_t nb
        = std::size_t(n_buckets[0]) * n_buckets[1] * n_buckets[2];

      auto range
        = [&](const Ball &b, std::array<int, 3> &lo, std::array<int, 3> &hi) {
            for (int d = 0; d < 3; ++d)
              {
                lo[d] = std::clamp(static_cast<int>(std::floor(
                                     (b.centre[d] - b.radius - bucket_origin[d])
                                     / bucket_size)),
                                   0,
                                   n_buckets[d] - 1);
                hi[d] = std::clamp(static_cast<int>(std::floor(
                                     (b.centre[d] + b.radius - bucket_origin[d])
                                     / bucket_size)),
                                   0,
                                   n_buckets[d] - 1);
              }
          };
      // Two passes: count, then fill (CSR).
      bucket_start.assign(nb + 1, 0);
      for (int pass = 0; pass < 2; ++pass)
        {
          std::vector<unsigned> fill;
          if (pass == 1)
            {
              std::partial_sum(bucket_start.begin(),
                               bucket_start.end(),
                               bucket_start.begin());
              bucket_items.resize(bucket_start.back());
              fill.assign(bucket_start.begin(), bucket_start.end() - 1);
            }
          for (std::size_t s = 0; s < spheres.size(); ++s)
            {
              std::array<int, 3> lo, hi;
              range(spheres[s], lo, hi);
              for (int k = lo[2]; k <= hi[2]; ++k)
                for (int j = lo[1]; j <= hi[1]; ++j)
                  for (int i = lo[0]; i <= hi[0]; ++i)
                    {
                      const std::size_t b
                        = i
                          + std::size_t(n_buckets[0])
                              * (j + std::size_t(n_buckets[1]) * k);
                      if (pass == 0)
                        ++bucket_start[b + 1];
                      else
                        bucket_items[fill[b]++] = static_cast<unsigned>(s);
                    }
            }
        }
    }

    bool
    InnerSpheres::contains(const Eigen::Vector3d &p) const
    {
      if (spheres.empty() || !box.contains(p))
        return false;
      std::size_t b = 0, stride = 1;
      for (int d = 0; d < 3; ++d)
        {
          const int i = std::clamp(static_cast<int>(std::floor(
                                     (p[d] - bucket_origin[d]) / bucket_size)),
                                   0,
                                   n_buckets[d] - 1);
          b += stride * i;
          stride *= n_buckets[d];
        }
      for (unsigned q = bucket_start[b]; q < bucket_start[b + 1]; ++q)
        {
          const Ball &s = spheres[bucket_items[q]];
          if ((p - s.centre).squaredNorm() <= s.radius * s.radius)
            return true;
        }
      return false;
    }

    InnerSphereData
    InnerSpheres::export_data() const
    {
      InnerSphereData d;
      for (const auto &s : spheres)
        {
          d.cx.push_back(static_cast<float>(s.centre[0]));
          d.cy.push_back(static_cast<float>(s.centre[1]));
          d.cz.push_back(static_cast<float>(s.centre[2]));
          d.r.push_back(static_cast<float>(s.radius));
        }
      return d;
    }

  } // namespace geometry
} // namespace particulate
