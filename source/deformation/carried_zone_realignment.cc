#include <particulate/deformation/carried_zone_realignment.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    namespace {
      /// more distinct displacements than this among the vertices inside
      /// the bodies: the zones turn with their bodies
      constexpr unsigned int max_zones = 64;

      /** The undeformed vertices, found by position to a tolerance. */
      template <int dim>
      class VertexLookup
      {
      public:
        VertexLookup(const std::vector<Point<dim>> &points,
                     const double                   tolerance)
          : points(points)
          , tolerance(tolerance)
        {
          for (unsigned int i = 0; i < points.size(); ++i)
            buckets.emplace(key(points[i]), i);
        }

        /** Whether a vertex lies within the tolerance of @p x. */
        bool
        contains(const Point<dim> &x) const
        {
          const Key centre = key(x);
          // the neighbouring buckets too: x may round across a border
          unsigned int n_neighbours = 1;
          for (unsigned int d = 0; d < dim; ++d)
            n_neighbours *= 3;
          for (unsigned int n = 0; n < n_neighbours; ++n)
            {
              Key          k = centre;
              unsigned int m = n;
              for (unsigned int d = 0; d < dim; ++d, m /= 3)
                k[d] += static_cast<long long>(m % 3) - 1;
              const auto found = buckets.find(k);
              if (found != buckets.end()
                  && points[found->second].distance(x) <= tolerance)
                return true;
            }
          return false;
        }

      private:
        using Key = std::array<long long, dim>;

        Key
        key(const Point<dim> &x) const
        {
          Key k;
          for (unsigned int d = 0; d < dim; ++d)
            k[d] = static_cast<long long>(std::floor(x[d] / tolerance));
          return k;
        }

        const std::vector<Point<dim>>   &points;
        const double                     tolerance;
        std::multimap<Key, unsigned int> buckets;
      };

      /** Vertices inside the bodies, grouped by their displacement. */
      template <int dim>
      struct DisplacementGroup
      {
        Tensor<1, dim>            displacement;
        std::vector<unsigned int> vertices;

        Point<dim>
        centre(const std::vector<Point<dim>> &carried) const
        {
          Point<dim> sum;
          for (const unsigned int v : vertices)
            sum += carried[v];
          return sum / static_cast<double>(vertices.size());
        }

        double
        extent(const std::vector<Point<dim>> &carried) const
        {
          const Point<dim> c       = centre(carried);
          double           largest = 0.;
          for (const unsigned int v : vertices)
            largest = std::max(largest, carried[v].distance(c));
          return largest;
        }
      };

      template <int dim>
      double
      bounding_diagonal(const std::vector<Point<dim>> &points)
      {
        Point<dim> low, high;
        for (unsigned int d = 0; d < dim; ++d)
          {
            low[d]  = std::numeric_limits<double>::max();
            high[d] = std::numeric_limits<double>::lowest();
          }
        for (const auto &p : points)
          for (unsigned int d = 0; d < dim; ++d)
            {
              low[d]  = std::min(low[d], p[d]);
              high[d] = std::max(high[d], p[d]);
            }
        return low.distance(high);
      }

      /** The groups; empty when there are more than max_zones. */
      template <int dim>
      std::vector<DisplacementGroup<dim>>
      group_inside_vertices(const std::vector<Point<dim>> &carried,
                            const std::vector<Point<dim>> &undeformed,
                            const DistanceField<dim>      &distance,
                            const double                   tolerance)
      {
        std::vector<DisplacementGroup<dim>> groups;
        for (unsigned int v = 0; v < carried.size(); ++v)
          {
            if (distance.signed_distance(carried[v]) >= 0.)
              continue;
            const Tensor<1, dim> R = carried[v] - undeformed[v];
            auto                 g = groups.begin();
            while (g != groups.end()
                   && (g->displacement - R).norm() > tolerance)
              ++g;
            if (g == groups.end())
              {
                if (groups.size() == max_zones)
                  return {};
                groups.push_back({R, {}});
                g = groups.end() - 1;
              }
            g->vertices.push_back(v);
          }
        return groups;
      }

      /** Whether two groups lie so close that they are parts of one zone
       *  (a body that turned moves each vertex by its own displacement):
       *  closer than their extents, @p zone_width and two spacings @p h. */
      template <int dim>
      bool
      groups_touch(const std::vector<DisplacementGroup<dim>> &groups,
                   const std::vector<Point<dim>>             &carried,
                   const double                               zone_width,
                   const double                               h)
      {
        for (unsigned int a = 0; a < groups.size(); ++a)
          for (unsigned int b = a + 1; b < groups.size(); ++b)
            if (groups[a].centre(carried).distance(groups[b].centre(carried))
                < groups[a].extent(carried) + groups[b].extent(carried)
                    + zone_width + 2. * h)
              return true;
        return false;
      }

      /** The undeformed vertex nearest to @p x. */
      template <int dim>
      unsigned int
      nearest_vertex(const std::vector<Point<dim>> &points, const Point<dim> &x)
      {
        unsigned int nearest  = 0;
        double       smallest = std::numeric_limits<double>::max();
        for (unsigned int i = 0; i < points.size(); ++i)
          if (points[i].distance_square(x) < smallest)
            {
              smallest = points[i].distance_square(x);
              nearest  = i;
            }
        return nearest;
      }

      /** Whether the undeformed mesh within @p zone_width of the surface
       *  (its vertices counted as carried by @p displacement) has a twin
       *  shifted by @p shift. */
      template <int dim>
      bool
      repeats_under(const Tensor<1, dim>          &shift,
                    const Tensor<1, dim>          &displacement,
                    const std::vector<Point<dim>> &undeformed,
                    const VertexLookup<dim>       &lookup,
                    const DistanceField<dim>      &distance,
                    const double                   zone_width)
      {
        for (const auto &u : undeformed)
          if (distance.signed_distance(u + displacement) <= zone_width
              && !lookup.contains(u + shift))
            return false;
        return true;
      }
    } // namespace



    template <int dim>
    std::vector<RealignedZone<dim>>
    realigned_zones(
      const std::vector<Point<dim>>                           &carried,
      const std::vector<Point<dim>>                           &undeformed,
      const DistanceField<dim>                                &distance,
      const double                                             zone_width,
      const std::function<Tensor<1, dim>(const Point<dim> &)> &step)
    {
      const double tolerance = 1e-9 * bounding_diagonal(undeformed);
      const auto   groups
        = group_inside_vertices(carried, undeformed, distance, tolerance);
      if (groups.empty())
        return {};
      // the spacing of the vertices: that of a group's first vertex to its
      // nearest neighbour, the largest of these
      double h = 0.;
      for (const auto &g : groups)
        {
          double nearest = std::numeric_limits<double>::max();
          for (unsigned int v = 0; v < undeformed.size(); ++v)
            if (v != g.vertices[0])
              nearest
                = std::min(nearest,
                           undeformed[v].distance(undeformed[g.vertices[0]]));
          h = std::max(h, nearest);
        }
      if (groups_touch(groups, carried, zone_width, h))
        return {};
      const VertexLookup<dim>         lookup(undeformed, tolerance);
      std::vector<RealignedZone<dim>> zones;
      for (const auto &g : groups)
        {
          const Point<dim>  &u = undeformed[g.vertices[0]];
          RealignedZone<dim> zone;
          zone.centre = g.centre(carried);
          // the lattice translation nearest to the displacement at the end
          // of the step: the one that takes the vertex, so carried, to its
          // nearest undeformed neighbour
          const Tensor<1, dim> ahead
            = g.displacement + (step ? step(zone.centre) : Tensor<1, dim>());
          const Tensor<1, dim> shift
            = undeformed[nearest_vertex(undeformed, u + ahead)] - u;
          if (repeats_under(shift,
                            g.displacement,
                            undeformed,
                            lookup,
                            distance,
                            zone_width))
            zone.residual = g.displacement - shift;
          zones.push_back(zone);
        }
      return zones;
    }



    template <int dim>
    Tensor<1, dim>
    residual_near(const std::vector<RealignedZone<dim>> &zones,
                  const Point<dim>                      &x)
    {
      const RealignedZone<dim> *nearest  = nullptr;
      double                    smallest = std::numeric_limits<double>::max();
      for (const auto &zone : zones)
        if (zone.centre.distance_square(x) < smallest)
          {
            smallest = zone.centre.distance_square(x);
            nearest  = &zone;
          }
      return nearest ? nearest->residual : Tensor<1, dim>();
    }



    template std::vector<RealignedZone<2>>
    realigned_zones(const std::vector<Point<2>> &,
                    const std::vector<Point<2>> &,
                    const DistanceField<2> &,
                    double,
                    const std::function<Tensor<1, 2>(const Point<2> &)> &);
    template std::vector<RealignedZone<3>>
    realigned_zones(const std::vector<Point<3>> &,
                    const std::vector<Point<3>> &,
                    const DistanceField<3> &,
                    double,
                    const std::function<Tensor<1, 3>(const Point<3> &)> &);
    template Tensor<1, 2>
    residual_near(const std::vector<RealignedZone<2>> &, const Point<2> &);
    template Tensor<1, 3>
    residual_near(const std::vector<RealignedZone<3>> &, const Point<3> &);
  } // namespace deformation
} // namespace particulate
