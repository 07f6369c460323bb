// Checkpoint of a World's dynamic state (World::save_state/load_state).
// The byte helpers mirror core::write_binary/read_binary on purpose: the
// rigid module depends on Eigen only, not on the deal.II-based core.
#include <particulate/rigid/world.h>

#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>

namespace particulate {
  namespace rigid {
    namespace {
      const std::uint64_t format_tag = 0x5249474944303031ull; // "RIGID001"

      template <typename T>
      void
      put(std::ostream &out, const T &value)
      {
        out.write(reinterpret_cast<const char *>(&value), sizeof(T));
      }

      template <typename T>
      T
      get(std::istream &in)
      {
        T value;
        in.read(reinterpret_cast<char *>(&value), sizeof(T));
        if (!in)
          throw std::runtime_error("the rigid-body state ends early");
        return value;
      }

      void
      put_vector(std::ostream &out, const Eigen::Vector3d &v)
      {
        for (int d = 0; d < 3; ++d)
          put(out, v[d]);
      }

      Eigen::Vector3d
      get_vector(std::istream &in)
      {
        Eigen::Vector3d v;
        for (int d = 0; d < 3; ++d)
          v[d] = get<double>(in);
        return v;
      }
    } // namespace



    void
    World::save_state(std::ostream &out) const
    {
      sync_bodies();
      put(out, format_tag);
      put(out, time_);
      put(out, step_number_);
      put(out, last_dt_);
      put<std::uint64_t>(out, bodies_.size());
      for (const RigidBody &b : bodies_)
        {
          put<int>(out, static_cast<int>(b.shape().kind()));
          put_vector(out, b.position);
          for (const double q : {b.orientation.w(),
                                 b.orientation.x(),
                                 b.orientation.y(),
                                 b.orientation.z()})
            put(out, q);
          put_vector(out, b.linear_velocity);
          put_vector(out, b.angular_velocity);
        }
      const auto write_edges = [&](const std::vector<ContactEdge> &edges) {
        put<std::uint64_t>(out, edges.size());
        for (const ContactEdge &e : edges)
          {
            put(out, e.manifold.a);
            put(out, e.manifold.b);
            put<int>(out, static_cast<int>(e.state));
            put_vector(out, e.gjk_direction);
            put_vector(out, e.step_impulse);
            put_vector(out, e.step_moment);
            put(out, e.step_weight);
            put<std::uint64_t>(out, e.manifold.points.size());
            for (const ContactPoint &c : e.manifold.points)
              {
                put_vector(out, c.position);
                put_vector(out, c.normal);
                put(out, c.distance);
                put_vector(out, c.local_a);
                put(out, c.normal_impulse);
                put_vector(out, c.tangent_impulse);
                put_vector(out, c.dem_spring);
                put_vector(out, c.impulse);
              }
          }
      };
      // The sphere-only DEM path writes its state as the general path's:
      // either path can continue from the file.
      std::vector<ContactEdge>     fast_edges, fast_dropped;
      std::vector<Eigen::Vector3d> fast_positions;
      if (sphere_dem_)
        sphere_dem_->export_state(bodies_,
                                  fast_edges,
                                  fast_dropped,
                                  fast_positions);
      write_edges(sphere_dem_ ? fast_edges : graph_.edges());
      // edges the last broad phase dropped still carry that step's forces
      write_edges(sphere_dem_ ? fast_dropped : dropped_);
      // where the DEM's Verlet list was built (empty: rebuild next step)
      const auto &list = sphere_dem_ ? fast_positions : broad_positions_;
      put<std::uint64_t>(out, list.size());
      for (const Eigen::Vector3d &x : list)
        put_vector(out, x);
    }



    void
    World::load_state(std::istream &in)
    {
      if (get<std::uint64_t>(in) != format_tag)
        throw std::runtime_error("not a rigid-body state");
      time_        = get<double>(in);
      step_number_ = get<unsigned long>(in);
      last_dt_     = get<double>(in);
      const auto n = get<std::uint64_t>(in);
      if (n != bodies_.size())
        throw std::runtime_error("the saved world has " + std::to_string(n)
                                 + " bodies and this one "
                                 + std::to_string(bodies_.size()));
      // the file replaces the sphere path's state, read from bodies_ next
      bodies_behind_  = false;
      bodies_written_ = true;
      for (RigidBody &b : bodies_)
        {
          if (get<int>(in) != static_cast<int>(b.shape().kind()))
            throw std::runtime_error(
              "the saved bodies have other shapes than these");
          b.position     = get_vector(in);
          const double w = get<double>(in), x = get<double>(in),
                       y = get<double>(in), z = get<double>(in);
          b.orientation      = Eigen::Quaterniond(w, x, y, z);
          b.linear_velocity  = get_vector(in);
          b.angular_velocity = get_vector(in);
          b.clear_accumulators();
        }
      const auto read_edges = [&](std::vector<ContactEdge> &edges) {
        edges.assign(get<std::uint64_t>(in), ContactEdge());
        for (ContactEdge &e : edges)
          {
            e.manifold.a = get<BodyId>(in);
            e.manifold.b = get<BodyId>(in);
            if (e.manifold.a >= bodies_.size()
                || e.manifold.b >= bodies_.size())
              throw std::runtime_error("a saved contact names a missing body");
            e.state         = static_cast<EdgeState>(get<int>(in));
            e.gjk_direction = get_vector(in);
            e.step_impulse  = get_vector(in);
            e.step_moment   = get_vector(in);
            e.step_weight   = get<double>(in);
            e.manifold.points.assign(get<std::uint64_t>(in), ContactPoint());
            for (ContactPoint &c : e.manifold.points)
              {
                c.position        = get_vector(in);
                c.normal          = get_vector(in);
                c.distance        = get<double>(in);
                c.local_a         = get_vector(in);
                c.normal_impulse  = get<double>(in);
                c.tangent_impulse = get_vector(in);
                c.dem_spring      = get_vector(in);
                c.impulse         = get_vector(in);
              }
          }
      };
      // the next step hands the state to the sphere-only path again if it
      // applies, rebuilding its list where it was built
      sphere_dem_.reset();
      read_edges(graph_.edges());
      read_edges(dropped_);
      broad_positions_.resize(get<std::uint64_t>(in));
      for (Eigen::Vector3d &x : broad_positions_)
        x = get_vector(in);
      forces_valid_ = false;
    }
  } // namespace rigid
} // namespace particulate
