#include <particulate/rigid/contact_graph.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace particulate {
  namespace rigid {
    void
    ContactGraph::update(std::vector<BodyPair>     pairs,
                         std::vector<ContactEdge> *dropped)
    {
      std::sort(pairs.begin(), pairs.end());
      std::vector<ContactEdge> next;
      next.reserve(pairs.size());
      // Both lists are sorted by pair: merge them in one pass.
      std::size_t o = 0;
      for (const BodyPair &p : pairs)
        {
          auto key = [](const ContactEdge &e) {
            return BodyPair{e.manifold.a, e.manifold.b};
          };
          while (o < edges_.size() && key(edges_[o]) < p)
            {
              if (dropped && edges_[o].step_weight > 0.)
                dropped->push_back(std::move(edges_[o]));
              ++o;
            }
          if (o < edges_.size() && key(edges_[o]) == p)
            next.push_back(std::move(edges_[o++]));
          else
            {
              ContactEdge e;
              e.manifold.a = p.first;
              e.manifold.b = p.second;
              next.push_back(std::move(e));
            }
        }
      if (dropped)
        for (; o < edges_.size(); ++o)
          if (edges_[o].step_weight > 0.)
            dropped->push_back(std::move(edges_[o]));
      edges_.swap(next);
    }



    void
    ContactGraph::warm_start(ContactEdge                     &edge,
                             const std::vector<ContactPoint> &old_points,
                             const double                     tolerance)
    {
      auto &pts = edge.manifold.points;
      if (pts.empty())
        {
          edge.state = EdgeState::proximity;
          return;
        }
      edge.state        = old_points.empty() ? EdgeState::new_contact :
                                               EdgeState::persistent_contact;
      const double tol2 = tolerance * tolerance;
      if (pts.size() == 1 && old_points.size() == 1)
        {
          // One point before and after (spheres): the same contact, however
          // far the body-frame anchor has rolled.
          ContactPoint       &p = pts[0];
          const ContactPoint &q = old_points[0];
          if (q.normal.dot(p.normal) > 0.9)
            {
              p.normal_impulse  = q.normal_impulse;
              p.tangent_impulse = q.tangent_impulse
                                  - p.normal.dot(q.tangent_impulse) * p.normal;
              p.dem_spring
                = q.dem_spring - p.normal.dot(q.dem_spring) * p.normal;
            }
          return;
        }
      for (ContactPoint &p : pts)
        {
          double best = tol2;
          int    k    = -1;
          for (unsigned int i = 0; i < old_points.size(); ++i)
            {
              const double d2
                = (old_points[i].local_a - p.local_a).squaredNorm();
              if (d2 <= best && old_points[i].normal.dot(p.normal) > 0.9)
                {
                  best = d2;
                  k    = i;
                }
            }
          if (k >= 0)
            {
              const ContactPoint &q = old_points[k];
              p.normal_impulse      = q.normal_impulse;
              // Keep only the tangential parts with respect to the new normal.
              p.tangent_impulse = q.tangent_impulse
                                  - p.normal.dot(q.tangent_impulse) * p.normal;
              p.dem_spring
                = q.dem_spring - p.normal.dot(q.dem_spring) * p.normal;
            }
        }
    }



    unsigned int
    ContactGraph::compute_contact_groups(const std::vector<RigidBody> &bodies)
    {
      const unsigned int n = bodies.size();
      group_of_body_.assign(n, -1);
      group_edges_.clear();

      // Incidence lists (CSR) of the edges that carry contact points.
      std::vector<unsigned int> start(n + 1, 0), incident;
      for (const ContactEdge &e : edges_)
        if (!e.manifold.points.empty())
          {
            ++start[e.manifold.a + 1];
            ++start[e.manifold.b + 1];
          }
      for (unsigned int i = 0; i < n; ++i)
        start[i + 1] += start[i];
      incident.resize(start[n]);
      std::vector<unsigned int> fill(start.begin(), start.end() - 1);
      std::vector<char>         touches_fixed(n, 0);
      for (unsigned int k = 0; k < edges_.size(); ++k)
        {
          const ContactManifold &m = edges_[k].manifold;
          if (m.points.empty())
            continue;
          incident[fill[m.a]++] = k;
          incident[fill[m.b]++] = k;
          if (bodies[m.a].is_fixed())
            touches_fixed[m.b] = 1;
          if (bodies[m.b].is_fixed())
            touches_fixed[m.a] = 1;
        }

      // Algorithm 3 as an iterative breadth-first search that never enters
      // fixed bodies. Seeds: first the bodies resting on fixed ones.
      std::vector<char>         edge_done(edges_.size(), 0);
      std::vector<unsigned int> queue;
      auto                      grow = [&](const unsigned int seed) {
        const int g = group_edges_.size();
        group_edges_.emplace_back();
        queue.assign(1, seed);
        group_of_body_[seed] = g;
        for (std::size_t q = 0; q < queue.size(); ++q)
          {
            const unsigned int v = queue[q];
            for (unsigned int s = start[v]; s < start[v + 1]; ++s)
              {
                const unsigned int k = incident[s];
                if (!edge_done[k])
                  {
                    edge_done[k] = 1;
                    group_edges_[g].push_back(k);
                  }
                const ContactManifold &m = edges_[k].manifold;
                const unsigned int     w = m.a == v ? m.b : m.a;
                if (!bodies[w].is_fixed() && group_of_body_[w] < 0)
                  {
                    group_of_body_[w] = g;
                    queue.push_back(w);
                  }
              }
          }
      };
      for (int pass = 0; pass < 2; ++pass)
        for (unsigned int v = 0; v < n; ++v)
          if (!bodies[v].is_fixed() && group_of_body_[v] < 0
              && start[v + 1] > start[v] && (pass == 1 || touches_fixed[v]))
            grow(v);
      return group_edges_.size();
    }


    void
    ContactGraph::validate(const unsigned int n_bodies) const
    {
      auto fail = [](const std::string &what) {
        throw std::logic_error("rigid::ContactGraph::validate(): " + what);
      };
      for (std::size_t k = 0; k < edges_.size(); ++k)
        {
          const ContactManifold &m = edges_[k].manifold;
          if (!(m.a < m.b) || m.b >= n_bodies)
            fail("edge " + std::to_string(k) + " has bad body ids");
          if (k > 0
              && !(BodyPair{edges_[k - 1].manifold.a, edges_[k - 1].manifold.b}
                   < BodyPair{m.a, m.b}))
            fail("edges not sorted or duplicated at " + std::to_string(k));
          for (const ContactPoint &c : m.points)
            if (std::abs(c.normal.norm() - 1.) > 1.e-9
                || !c.position.allFinite() || !std::isfinite(c.distance)
                || c.normal_impulse < 0.)
              fail("edge " + std::to_string(k)
                   + " has an invalid contact point");
        }
    }
  } // namespace rigid
} // namespace particulate
