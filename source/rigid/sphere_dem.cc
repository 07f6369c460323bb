#include <particulate/geometry/half_space.h>
#include <particulate/rigid/sphere_dem.h>
#include <particulate/rigid/sphere_neighbour_search.h>
#include <particulate/rigid/world.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

#ifdef __SSE2__
#  include <emmintrin.h>
#endif

#include "phase_clock.h"

namespace particulate {
  namespace rigid {
    using detail::Clock;
    using detail::seconds_since;

    namespace {
      /** History key of the pair of bodies a < b. */
      std::uint64_t
      pair_key(const BodyId a, const BodyId b)
      {
        return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      }

      /**
       * A 3-vector as three scalars, for the force loops: their arithmetic
       * then stays in registers, where Eigen's fixed 3-vectors go through
       * 2-wide packets and stack temporaries whose partial stores stall the
       * wide reloads (measured: a third of the loop).
       */
      struct V3
      {
        double x, y, z;
      };
      inline V3
      operator+(const V3 &a, const V3 &b)
      {
        return {a.x + b.x, a.y + b.y, a.z + b.z};
      }
      inline V3
      operator-(const V3 &a, const V3 &b)
      {
        return {a.x - b.x, a.y - b.y, a.z - b.z};
      }
      inline V3
      operator*(const double s, const V3 &a)
      {
        return {s * a.x, s * a.y, s * a.z};
      }
      inline double
      dot(const V3 &a, const V3 &b)
      {
        return a.x * b.x + a.y * b.y + a.z * b.z;
      }
      inline V3
      cross(const V3 &a, const V3 &b)
      {
        return {a.y * b.z - a.z * b.y,
                a.z * b.x - a.x * b.z,
                a.x * b.y - a.y * b.x};
      }
      inline V3
      load(const Eigen::Vector3d &v)
      {
        return {v[0], v[1], v[2]};
      }
      inline void
      store(Eigen::Vector3d &v, const V3 &a)
      {
        v[0] = a.x;
        v[1] = a.y;
        v[2] = a.z;
      }
      inline void
      add_to(Eigen::Vector3d &v, const V3 &a)
      {
        v[0] += a.x;
        v[1] += a.y;
        v[2] += a.z;
      }

      /**
       * DemSolver's contact law at one overlapping point: returns the normal
       * force f_n and sets the tangential force @p ft on the second body
       * (the force is f_n n + ft), advancing the tangential @p spring. The
       * same formulas in the same order, except that the Coulomb tests
       * compare squares, so that a sticking contact (most of a packed bed)
       * needs no square root; the outcome differs only when a force equals its
       * limit to the last bit.
       * @param gap Gap (negative: overlap) in m.
       * @param n Unit normal from the first body to the second.
       * @param vrel Velocity of the second body's contact point relative to
       * the first's.
       */
      template <typename Material>
      inline double
      contact_law(const Material &m,
                  const double    sqrt_mass,
                  const double    gap,
                  const V3       &n,
                  const V3       &vrel,
                  const double    h,
                  V3             &spring,
                  V3             &ft)
      {
        const double vn       = dot(vrel, n);
        const double eta_n    = m.cn * sqrt_mass;
        const double eta_t    = m.ct * sqrt_mass;
        const V3     vt       = vrel - vn * n;
        const double fn       = m.kn * (-gap) - eta_n * vn;
        V3           xi       = spring - dot(spring, n) * n;
        xi                    = xi + h * vt;
        const double fn_pos   = std::max(fn, 0.);
        const double lim      = m.mu_s * fn_pos;
        ft                    = (-m.kt) * xi;
        const double elastic2 = dot(ft, ft);
        if (elastic2 > lim * lim)
          {
            const double len = std::sqrt(elastic2);
            ft = len > 0. ? (m.mu_d * fn_pos / len) * ft : V3{0., 0., 0.};
            xi = m.kt > 0. ? V3{-ft.x / m.kt, -ft.y / m.kt, -ft.z / m.kt} :
                             V3{0., 0., 0.};
          }
        else
          {
            ft                  = ft - eta_t * vt;
            const double total2 = dot(ft, ft);
            if (total2 > lim * lim)
              ft = (lim / std::sqrt(total2)) * ft;
          }
        spring = xi;
        return fn;
      }

#ifdef __SSE2__
      /**
       * Two sphere pairs side by side, one per lane of an SSE2 register, for
       * the pair loop. Per pair the loop is one chain of dependent operations
       * (square root, division, contact law, then a square root for the
       * impulse's magnitude) longer than the processor can overlap with the
       * next pair's chain; two lanes run two chains in the time of one. SSE2
       * is part of baseline x86-64, and each lane rounds exactly as the scalar
       * instructions do, so the result is bit for bit that of the scalar
       * loop (V3) and does not depend on the processor.
       */
      struct P3
      {
        __m128d x, y, z;
      };
      inline __m128d
      lanes(const double &a, const double &b)
      {
        return _mm_loadh_pd(_mm_load_sd(&a), &b);
      }
      inline P3
      lanes(const Eigen::Vector3d &a, const Eigen::Vector3d &b)
      {
        return {lanes(a[0], b[0]), lanes(a[1], b[1]), lanes(a[2], b[2])};
      }
      inline P3
      operator+(const P3 &a, const P3 &b)
      {
        return {_mm_add_pd(a.x, b.x),
                _mm_add_pd(a.y, b.y),
                _mm_add_pd(a.z, b.z)};
      }
      inline P3
      operator-(const P3 &a, const P3 &b)
      {
        return {_mm_sub_pd(a.x, b.x),
                _mm_sub_pd(a.y, b.y),
                _mm_sub_pd(a.z, b.z)};
      }
      inline P3
      operator*(const __m128d s, const P3 &a)
      {
        return {_mm_mul_pd(s, a.x), _mm_mul_pd(s, a.y), _mm_mul_pd(s, a.z)};
      }
      inline __m128d
      dot(const P3 &a, const P3 &b)
      {
        return _mm_add_pd(_mm_add_pd(_mm_mul_pd(a.x, b.x),
                                     _mm_mul_pd(a.y, b.y)),
                          _mm_mul_pd(a.z, b.z));
      }
      inline P3
      cross(const P3 &a, const P3 &b)
      {
        return {_mm_sub_pd(_mm_mul_pd(a.y, b.z), _mm_mul_pd(a.z, b.y)),
                _mm_sub_pd(_mm_mul_pd(a.z, b.x), _mm_mul_pd(a.x, b.z)),
                _mm_sub_pd(_mm_mul_pd(a.x, b.y), _mm_mul_pd(a.y, b.x))};
      }
      /** Sign flipped: exact, as the scalar unary minus. */
      inline __m128d
      negated(const __m128d a)
      {
        return _mm_xor_pd(a, _mm_set1_pd(-0.));
      }
      /** Per lane: @p mask ? @p a : @p b. */
      inline __m128d
      select(const __m128d mask, const __m128d a, const __m128d b)
      {
        return _mm_or_pd(_mm_and_pd(mask, a), _mm_andnot_pd(mask, b));
      }
      inline P3
      select(const __m128d mask, const P3 &a, const P3 &b)
      {
        return {select(mask, a.x, b.x),
                select(mask, a.y, b.y),
                select(mask, a.z, b.z)};
      }
      template <int lane>
      inline double
      get(const __m128d a)
      {
        return _mm_cvtsd_f64(lane == 0 ? a : _mm_unpackhi_pd(a, a));
      }
      template <int lane>
      inline V3
      get(const P3 &a)
      {
        return {get<lane>(a.x), get<lane>(a.y), get<lane>(a.z)};
      }

      /**
       * contact_law() for two contacts, one per lane, with the same
       * operations in the same order; the branches become selections, and
       * the square roots and divisions of the limited forces are taken only
       * when a lane needs them.
       */
      template <typename Material>
      inline __m128d
      contact_law(const Material &m0,
                  const Material &m1,
                  const __m128d   sqrt_mass,
                  const __m128d   gap,
                  const P3       &n,
                  const P3       &vrel,
                  const __m128d   h,
                  P3             &spring,
                  P3             &ft)
      {
        const __m128d zero = _mm_setzero_pd();
        const __m128d kn = lanes(m0.kn, m1.kn), kt = lanes(m0.kt, m1.kt);
        const __m128d mu_s  = lanes(m0.mu_s, m1.mu_s);
        const __m128d vn    = dot(vrel, n);
        const __m128d eta_n = _mm_mul_pd(lanes(m0.cn, m1.cn), sqrt_mass);
        const __m128d eta_t = _mm_mul_pd(lanes(m0.ct, m1.ct), sqrt_mass);
        const P3      vt    = vrel - vn * n;
        const __m128d fn
          = _mm_sub_pd(_mm_mul_pd(kn, negated(gap)), _mm_mul_pd(eta_n, vn));
        P3 xi = spring - dot(spring, n) * n;
        xi    = xi + h * vt;
        // std::max(fn, 0.): fn unless 0 > fn
        const __m128d fn_pos   = _mm_max_pd(zero, fn);
        const __m128d lim      = _mm_mul_pd(mu_s, fn_pos);
        const __m128d lim2     = _mm_mul_pd(lim, lim);
        ft                     = negated(kt) * xi;
        const __m128d elastic2 = dot(ft, ft);
        const __m128d slip     = _mm_cmpgt_pd(elastic2, lim2);
        P3            ft_slip = ft, xi_slip = xi;
        if (_mm_movemask_pd(slip) != 0)
          {
            const __m128d len = _mm_sqrt_pd(elastic2);
            const __m128d scale
              = _mm_div_pd(_mm_mul_pd(lanes(m0.mu_d, m1.mu_d), fn_pos), len);
            const P3 zero3{zero, zero, zero};
            ft_slip = select(_mm_cmpgt_pd(len, zero), scale * ft, zero3);
            xi_slip = select(_mm_cmpgt_pd(kt, zero),
                             P3{_mm_div_pd(negated(ft_slip.x), kt),
                                _mm_div_pd(negated(ft_slip.y), kt),
                                _mm_div_pd(negated(ft_slip.z), kt)},
                             zero3);
          }
        P3            ft_stick = ft - eta_t * vt;
        const __m128d total2   = dot(ft_stick, ft_stick);
        const __m128d capped = _mm_andnot_pd(slip, _mm_cmpgt_pd(total2, lim2));
        if (_mm_movemask_pd(capped) != 0)
          ft_stick = select(capped,
                            _mm_div_pd(lim, _mm_sqrt_pd(total2)) * ft_stick,
                            ft_stick);
        ft     = select(slip, ft_slip, ft_stick);
        spring = select(slip, xi_slip, xi);
        return fn;
      }
#endif

      /**
       * @p q turned by the angular velocity @p w (|w|^2 = @p w2) over @p h
       * seconds, renormalised: NewtonEulerIntegrator's exact rotation of an
       * isotropic body, dq = (cos(a/2), sin(a/2) w/|w|) with a = |w| h. For
       * a/2 <= 0.1 (every substep of a resolved contact) cos(a/2) and
       * sin(a/2)/|w| come from their Taylor series in (a/2)^2 up to the
       * 8th power, whose remainder (< 3e-17 relative) lies below the
       * rounding: no square root, division or sincos.
       */
      inline Eigen::Quaterniond
      rotated(const Eigen::Quaterniond &q,
              const V3                 &w,
              const double              w2,
              const double              h)
      {
        const double x2 = 0.25 * h * h * w2; // (a/2)^2
        double       c, s;                   // cos(a/2), sin(a/2) / |w|
        if (x2 <= 0.01)
          {
            c = 1.
                + x2
                    * (-1. / 2.
                       + x2
                           * (1. / 24.
                              + x2 * (-1. / 720. + x2 * (1. / 40320.))));
            s = 0.5 * h
                * (1.
                   + x2
                       * (-1. / 6.
                          + x2
                              * (1. / 120.
                                 + x2 * (-1. / 5040. + x2 * (1. / 362880.)))));
          }
        else
          {
            const double len = std::sqrt(w2);
            c                = std::cos(0.5 * h * len);
            s                = std::sin(0.5 * h * len) / len;
          }
        // dq * q, then normalised
        const double qw = q.w(), qx = q.x(), qy = q.y(), qz = q.z();
        const double dx = s * w.x, dy = s * w.y, dz = s * w.z;
        const double rw = c * qw - dx * qx - dy * qy - dz * qz;
        const double rx = c * qx + dx * qw + dy * qz - dz * qy;
        const double ry = c * qy - dx * qz + dy * qw + dz * qx;
        const double rz = c * qz + dx * qy - dy * qx + dz * qw;
        const double inv
          = 1. / std::sqrt(rw * rw + rx * rx + ry * ry + rz * rz);
        return Eigen::Quaterniond(inv * rw, inv * rx, inv * ry, inv * rz);
      }

      template <typename T>
      void
      permute(std::vector<T> &v, const std::vector<unsigned int> &order)
      {
        std::vector<T> out(v.size());
        for (std::size_t k = 0; k < order.size(); ++k)
          out[k] = v[order[k]];
        v.swap(out);
      }
    } // namespace



    bool
    SphereDem::can_handle(const RigidBody &body)
    {
      const geometry::ShapeKind type = body.shape().kind();
      if (body.is_fixed())
        return type == geometry::ShapeKind::sphere
               || type == geometry::ShapeKind::half_space;
      return type == geometry::ShapeKind::sphere && !body.rotation_locked();
    }



    SphereDem::SphereDem(const std::vector<RigidBody>       &bodies,
                         const std::vector<ContactMaterial> &pair_materials,
                         const unsigned int                  n_materials,
                         const Settings                     &settings,
                         const std::vector<ContactEdge>     &edges,
                         const std::vector<Eigen::Vector3d> &list_positions)
      : settings_(settings)
      , n_materials_(n_materials)
    {
      for (const ContactMaterial &m : pair_materials)
        materials_.push_back(
          {m.stiffness,
           m.tangential_stiffness,
           2. * m.damping_ratio * std::sqrt(m.stiffness),
           2. * m.damping_ratio * std::sqrt(m.tangential_stiffness),
           m.static_friction,
           m.dynamic_friction});
      const bool saved_list = list_positions.size() == bodies.size();
      std::vector<Eigen::Vector3d> list_x;
      for (BodyId id = 0; id < bodies.size(); ++id)
        {
          const RigidBody       &b = bodies[id];
          const Eigen::Vector3d &at
            = saved_list ? list_positions[id] : b.position;
          if (b.shape().kind() == geometry::ShapeKind::half_space)
            {
              wall_id_.push_back(id);
              wall_material_.push_back(b.material());
              wall_list_position_.push_back(at);
              continue;
            }
          id_.push_back(id);
          radius_.push_back(b.bounding_radius());
          inverse_mass_.push_back(b.inverse_mass());
          // isotropic: one principal moment stands for the tensor
          inverse_inertia_.push_back(b.inverse_principal_inertia()[0]);
          material_.push_back(b.material());
          list_x.push_back(at);
        }
      const std::size_t n = id_.size();
      x_.assign(n, Eigen::Vector3d::Zero());
      v_ = w_ = f_ = t_ = applied_f_ = applied_t_ = buoyancy_ = x_;
      for (std::size_t k = 0; k < n; ++k)
        {
          const RigidBody &b = bodies[id_[k]];
          if (settings_.fluid_density > 0. && !b.is_fixed())
            buoyancy_[k]
              = -settings_.fluid_density * b.volume() * settings_.gravity;
          applied_f_[k] = buoyancy_[k];
        }
      q_.assign(n, Eigen::Quaterniond::Identity());
      const std::size_t n_walls = wall_id_.size();
      wall_normal_.assign(n_walls, Eigen::Vector3d::Zero());
      wall_position_ = wall_v_ = wall_w_ = wall_normal_;
      wall_offset_.assign(n_walls, 0.);
      read_walls(bodies);

      // The springs of the general path's contact points (its loads belong
      // to a finished step: each step starts its own).
      std::vector<History> springs;
      for (const ContactEdge &e : edges)
        if (e.manifold.points.size() == 1)
          springs.push_back(
            {pair_key(e.manifold.a, e.manifold.b),
             e.manifold.points[0].dem_spring,
             Load{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.}});
      rebuild(list_x, std::move(springs), false);
    }



    void
    SphereDem::read_walls(const std::vector<RigidBody> &bodies)
    {
      for (std::size_t w = 0; w < wall_id_.size(); ++w)
        {
          const RigidBody &b = bodies[wall_id_[w]];
          const auto &hs  = static_cast<const geometry::HalfSpace &>(b.shape());
          wall_normal_[w] = b.orientation * hs.normal();
          wall_offset_[w] = hs.offset() + wall_normal_[w].dot(b.position);
          wall_position_[w] = b.position;
          wall_v_[w]        = b.linear_velocity;
          wall_w_[w]        = b.angular_velocity;
        }
    }



    void
    SphereDem::read_bodies(std::vector<RigidBody> &bodies)
    {
      // The coupling or the user may have changed the bodies; the list is
      // stale when anything moved more than half the skin since it was
      // built, as on the general path.
      const double limit = 0.25 * settings_.skin * settings_.skin;
      bool         stale = false;
      for (std::size_t k = 0; k < id_.size(); ++k)
        {
          RigidBody &b  = bodies[id_[k]];
          x_[k]         = b.position;
          q_[k]         = b.orientation;
          v_[k]         = b.linear_velocity;
          w_[k]         = b.angular_velocity;
          applied_f_[k] = b.force + buoyancy_[k];
          applied_t_[k] = b.torque;
          b.clear_accumulators();
          stale |= (x_[k] - x_list_[k]).squaredNorm() > limit;
        }
      read_walls(bodies);
      for (std::size_t w = 0; w < wall_id_.size(); ++w)
        {
          bodies[wall_id_[w]].clear_accumulators();
          stale |= (wall_position_[w] - wall_list_position_[w]).squaredNorm()
                   > limit;
        }
      rebuild_needed_ = rebuild_needed_ || stale;
      loads_applied_  = true;
    }



    void
    SphereDem::write_bodies(std::vector<RigidBody> &bodies) const
    {
      for (std::size_t k = 0; k < id_.size(); ++k)
        if (inverse_mass_[k] > 0.)
          {
            RigidBody &b       = bodies[id_[k]];
            b.position         = x_[k];
            b.orientation      = q_[k];
            b.linear_velocity  = v_[k];
            b.angular_velocity = w_[k];
          }
    }



    std::vector<SphereDem::History>
    SphereDem::history() const
    {
      std::vector<History> h;
      h.reserve(pairs_.size() + walls_.size());
      for (std::size_t k = 0; k < pairs_.size(); ++k)
        h.push_back({pair_key(id_[pairs_[k].i], id_[pairs_[k].j]),
                     pairs_[k].spring,
                     pair_loads_[k]});
      for (std::size_t k = 0; k < walls_.size(); ++k)
        {
          // general-path convention: spring and impulse of the larger id
          const BodyId s = id_[walls_[k].sphere], w = wall_id_[walls_[k].wall];
          const double sign = w < s ? 1. : -1.;
          Load         load = wall_loads_[k];
          load.impulse *= sign;
          h.push_back({pair_key(s, w), sign * walls_[k].spring, load});
        }
      return h;
    }



    void
    SphereDem::rebuild(std::vector<Eigen::Vector3d> list_x,
                       std::vector<History>         history,
                       const bool                   keep_dropped)
    {
      const double reach = settings_.margin + settings_.offset + settings_.skin;
      const SphereNeighbourSearch search(list_x, radius_, reach);
      const auto                 &order = search.order();
      permute(id_, order);
      permute(x_, order);
      permute(v_, order);
      permute(w_, order);
      permute(q_, order);
      permute(applied_f_, order);
      permute(applied_t_, order);
      permute(buoyancy_, order);
      permute(radius_, order);
      permute(inverse_mass_, order);
      permute(inverse_inertia_, order);
      permute(material_, order);
      x_list_.resize(order.size());
      for (std::size_t k = 0; k < order.size(); ++k)
        x_list_[k] = list_x[order[k]];
      for (std::size_t w = 0; w < wall_id_.size(); ++w)
        wall_list_position_[w] = wall_position_[w];

      std::sort(history.begin(),
                history.end(),
                [](const History &a, const History &b) {
                  return a.key < b.key;
                });
      std::vector<bool> used(history.size(), false);
      auto              find = [&](const std::uint64_t key) -> long {
        const auto it = std::lower_bound(history.begin(),
                                         history.end(),
                                         key,
                                         [](const History &a, std::uint64_t b) {
                                           return a.key < b;
                                         });
        if (it == history.end() || it->key != key)
          return -1;
        used[it - history.begin()] = true;
        return it - history.begin();
      };
      const Load zero{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.};

      pairs_.clear();
      pair_loads_.clear();
      for (const auto &[k, l] : search.pairs())
        {
          if (inverse_mass_[k] == 0. && inverse_mass_[l] == 0.)
            continue; // two fixed spheres
          // the smaller id first, as body a of the general path
          const std::uint32_t i = id_[k] < id_[l] ? k : l, j = i == k ? l : k;
          SpherePair          p{i,
                       j,
                       material_[i] * n_materials_ + material_[j],
                       std::sqrt(1. / (inverse_mass_[i] + inverse_mass_[j])),
                       Eigen::Vector3d::Zero()};
          Load                load = zero;
          const long          h    = find(pair_key(id_[i], id_[j]));
          if (h >= 0)
            {
              p.spring = history[h].spring;
              load     = history[h].load;
            }
          pairs_.push_back(p);
          pair_loads_.push_back(load);
        }

      walls_.clear();
      wall_loads_.clear();
      for (std::uint32_t k = 0; k < id_.size(); ++k)
        {
          if (inverse_mass_[k] == 0.)
            continue;
          for (std::uint32_t w = 0; w < wall_id_.size(); ++w)
            {
              const double gap = wall_normal_[w].dot(x_list_[k])
                                 - wall_offset_[w] - radius_[k];
              if (gap > reach)
                continue;
              const BodyId s = id_[k], b = wall_id_[w];
              WallPair     p{k,
                         w,
                         b < s ?
                               wall_material_[w] * n_materials_ + material_[k] :
                               material_[k] * n_materials_ + wall_material_[w],
                         std::sqrt(1. / inverse_mass_[k]),
                         Eigen::Vector3d::Zero()};
              Load         load = zero;
              const long   h    = find(pair_key(s, b));
              if (h >= 0)
                {
                  const double sign = b < s ? 1. : -1.;
                  p.spring          = sign * history[h].spring;
                  load              = history[h].load;
                  load.impulse *= sign;
                }
              walls_.push_back(p);
              wall_loads_.push_back(load);
            }
        }

      // Pairs that left the list keep the forces they had during this step.
      if (keep_dropped)
        for (std::size_t h = 0; h < history.size(); ++h)
          if (!used[h] && history[h].load.weight > 0.)
            dropped_.emplace_back(history[h].key, history[h].load);
      rebuild_needed_ = false;
    }



    template <bool record>
    void
    SphereDem::contact_forces(const double h,
                              const bool   first_substep,
                              const bool   last_substep)
    {
      const double offset = settings_.offset, margin = settings_.margin;
      double       deepest  = 0.;
      unsigned int contacts = 0;
      auto         sum_load = [&](Load        &load,
                          const V3    &impulse,
                          const double weight,
                          const V3    &moment) {
        if (first_substep)
          {
            store(load.impulse, impulse);
            store(load.moment, moment);
            load.weight = weight;
          }
        else
          {
            add_to(load.impulse, impulse);
            add_to(load.moment, moment);
            load.weight += weight;
          }
      };
      auto add_load = [&](Load &load, const V3 &F, const V3 &point) {
        if constexpr (!record)
          return;
        const V3     impulse = h * F;
        const double weight  = std::sqrt(dot(impulse, impulse));
        sum_load(load, impulse, weight, weight * point);
      };
      auto separated = [&](Eigen::Vector3d &spring, Load &load) {
        spring.setZero();
        if (record && first_substep)
          load = Load{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.};
      };

      auto one_pair = [&](const std::size_t k) {
        SpherePair  &p  = pairs_[k];
        const V3     xa = load(x_[p.i]), xb = load(x_[p.j]);
        const double ra = radius_[p.i], rb = radius_[p.j];
        const V3     d    = xb - xa;
        const double dist = std::sqrt(dot(d, d));
        const double gap  = dist - ra - rb - offset;
        if (last_substep && gap <= margin)
          {
            ++contacts;
            deepest = std::max(deepest, -gap);
          }
        if (gap >= 0.)
          {
            separated(p.spring, pair_loads_[k]);
            return;
          }
        // The contact point lies on the line of centres, at s_a n from a's
        // centre and -s_b n from b's: the relative velocity needs one cross
        // product, and only the tangential force has a torque.
        const V3     n  = dist > 0. ? (1. / dist) * d : V3{0., 0., 1.};
        const double sa = ra + 0.5 * (gap + offset), sb = dist - sa;
        const V3     vrel = (load(v_[p.j]) - load(v_[p.i]))
                        - cross(sa * load(w_[p.i]) + sb * load(w_[p.j]), n);
        V3           spring = load(p.spring), ft;
        const double fn     = contact_law(materials_[p.material],
                                      p.sqrt_mass,
                                      gap,
                                      n,
                                      vrel,
                                      h,
                                      spring,
                                      ft);
        store(p.spring, spring);
        const V3 F = fn * n + ft, turn = cross(n, ft);
        add_to(f_[p.j], F);
        add_to(t_[p.j], (-sb) * turn);
        add_to(f_[p.i], (-1.) * F);
        add_to(t_[p.i], (-sa) * turn);
        add_load(pair_loads_[k], F, xa + sa * n);
      };

      std::size_t k = 0;
#ifdef __SSE2__
      const __m128d h2 = _mm_set1_pd(h), zero = _mm_setzero_pd();
      // One lane's part of the loop body after the two contact laws: the same
      // stores and sums as one_pair(), in pair order.
      auto finish = [&](auto          lane,
                        SpherePair   &p,
                        Load         &load,
                        const __m128d gap,
                        const P3     &spring,
                        const P3     &F,
                        const P3     &Tj,
                        const P3     &Ti,
                        const P3     &impulse,
                        const __m128d weight,
                        const P3     &moment) {
        constexpr int l = decltype(lane)::value;
        const double  g = get<l>(gap);
        if (last_substep && g <= margin)
          {
            ++contacts;
            deepest = std::max(deepest, -g);
          }
        if (g >= 0.)
          {
            separated(p.spring, load);
            return;
          }
        store(p.spring, get<l>(spring));
        add_to(f_[p.j], get<l>(F));
        add_to(t_[p.j], get<l>(Tj));
        add_to(f_[p.i], get<l>(P3{negated(F.x), negated(F.y), negated(F.z)}));
        add_to(t_[p.i], get<l>(Ti));
        if constexpr (record)
          sum_load(load, get<l>(impulse), get<l>(weight), get<l>(moment));
      };
      for (; k + 1 < pairs_.size(); k += 2)
        {
          SpherePair   &p0 = pairs_[k], &p1 = pairs_[k + 1];
          const P3      xa   = lanes(x_[p0.i], x_[p1.i]);
          const P3      xb   = lanes(x_[p0.j], x_[p1.j]);
          const __m128d ra   = lanes(radius_[p0.i], radius_[p1.i]);
          const __m128d rb   = lanes(radius_[p0.j], radius_[p1.j]);
          const P3      d    = xb - xa;
          const __m128d dist = _mm_sqrt_pd(dot(d, d));
          const __m128d gap  = _mm_sub_pd(_mm_sub_pd(_mm_sub_pd(dist, ra), rb),
                                         _mm_set1_pd(offset));
          const __m128d touching = _mm_cmplt_pd(gap, zero);
          if (_mm_movemask_pd(touching) == 0)
            {
              // neither touches: the scalar body only counts and clears
              one_pair(k);
              one_pair(k + 1);
              continue;
            }
          const P3      n = select(_mm_cmpgt_pd(dist, zero),
                              _mm_div_pd(_mm_set1_pd(1.), dist) * d,
                              P3{zero, zero, _mm_set1_pd(1.)});
          const __m128d sa
            = _mm_add_pd(ra,
                         _mm_mul_pd(_mm_set1_pd(0.5),
                                    _mm_add_pd(gap, _mm_set1_pd(offset))));
          const __m128d sb = _mm_sub_pd(dist, sa);
          const P3      vrel
            = (lanes(v_[p0.j], v_[p1.j]) - lanes(v_[p0.i], v_[p1.i]))
              - cross(sa * lanes(w_[p0.i], w_[p1.i])
                        + sb * lanes(w_[p0.j], w_[p1.j]),
                      n);
          P3            spring = lanes(p0.spring, p1.spring), ft;
          const __m128d fn     = contact_law(materials_[p0.material],
                                         materials_[p1.material],
                                         lanes(p0.sqrt_mass, p1.sqrt_mass),
                                         gap,
                                         n,
                                         vrel,
                                         h2,
                                         spring,
                                         ft);
          const P3      F = fn * n + ft, turn = cross(n, ft);
          const P3      Tj = negated(sb) * turn, Ti       = negated(sa) * turn;
          P3            impulse{zero, zero, zero}, moment = impulse;
          __m128d       weight = zero;
          if constexpr (record)
            {
              impulse = h2 * F;
              weight  = _mm_sqrt_pd(dot(impulse, impulse));
              moment  = weight * (xa + sa * n);
            }
          finish(std::integral_constant<int, 0>(),
                 p0,
                 pair_loads_[k],
                 gap,
                 spring,
                 F,
                 Tj,
                 Ti,
                 impulse,
                 weight,
                 moment);
          finish(std::integral_constant<int, 1>(),
                 p1,
                 pair_loads_[k + 1],
                 gap,
                 spring,
                 F,
                 Tj,
                 Ti,
                 impulse,
                 weight,
                 moment);
        }
#endif
      for (; k < pairs_.size(); ++k)
        one_pair(k);

      for (std::size_t k = 0; k < walls_.size(); ++k)
        {
          WallPair              &p = walls_[k];
          const Eigen::Vector3d &x = x_[p.sphere], &n = wall_normal_[p.wall];
          const double           r = radius_[p.sphere];
          // sphere_plane() of the narrow phase, then the offset
          const double raw = n.dot(x) - wall_offset_[p.wall] - r;
          const double gap = raw - offset;
          if (last_substep && gap <= margin)
            {
              ++contacts;
              deepest = std::max(deepest, -gap);
            }
          if (gap >= 0.)
            {
              separated(p.spring, wall_loads_[k]);
              continue;
            }
          const Eigen::Vector3d point
            = 0.5 * ((x - r * n) + (x - (r + raw) * n));
          const Eigen::Vector3d lever_wall = point - wall_position_[p.wall];
          const Eigen::Vector3d lever      = point - x;
          const Eigen::Vector3d vrel = v_[p.sphere] + w_[p.sphere].cross(lever)
                                       - wall_v_[p.wall]
                                       - wall_w_[p.wall].cross(lever_wall);
          V3           spring = load(p.spring), ft;
          const double fn     = contact_law(materials_[p.material],
                                        p.sqrt_mass,
                                        gap,
                                        load(n),
                                        load(vrel),
                                        h,
                                        spring,
                                        ft);
          store(p.spring, spring);
          const V3 F = fn * load(n) + ft;
          add_to(f_[p.sphere], F);
          add_to(t_[p.sphere], cross(load(lever), F));
          add_load(wall_loads_[k], F, load(point));
        }
      if (last_substep)
        {
          max_penetration_ = deepest;
          contacts_        = contacts;
        }
    }



    template <bool loads>
    bool
    SphereDem::integrate(const double h)
    {
      const double limit = 0.25 * settings_.skin * settings_.skin;
      const V3     g     = load(settings_.gravity);
      // Without loads from outside the applied force is the buoyancy (zero
      // without a fluid) and the applied torque zero.
      const bool buoyant = settings_.fluid_density > 0.;
      // Raw pointers: the compiler then keeps them in registers instead of
      // reloading them from the vectors after every store.
      Eigen::Vector3d *const __restrict x
        = x_.data(),
        *const __restrict v = v_.data(), *const __restrict w = w_.data(),
                          *const __restrict f = f_.data(),
                          *const __restrict t = t_.data();
      const Eigen::Vector3d *const __restrict applied_f
        = applied_f_.data(),
        *const __restrict applied_t                  = applied_t_.data(),
                          *const __restrict buoyancy = buoyancy_.data(),
                          *const __restrict x_list   = x_list_.data();
      Eigen::Quaterniond *const __restrict q         = q_.data();
      const double *const __restrict inverse_mass    = inverse_mass_.data();
      const double *const __restrict inverse_inertia = inverse_inertia_.data();
      const V3          zero{0., 0., 0.};
      bool              stale      = false;
      const std::size_t n          = id_.size();
      auto              one_sphere = [&](const std::size_t k) {
        const double im = inverse_mass[k];
        const V3     F = load(f[k]), T_contact = load(t[k]);
        store(f[k], zero);
        store(t[k], zero);
        if (im == 0.) // fixed sphere: it neither accelerates nor moves
          return;
        // DemSolver's velocity kick ...
        const V3 F_applied = loads   ? load(applied_f[k]) :
                                          buoyant ? load(buoyancy[k]) :
                                                    zero;
        const V3 vk = load(v[k]) + h * (im * (F_applied + F) + g);
        store(v[k], vk);
        const V3 T = loads ? load(applied_t[k]) + T_contact : T_contact;
        V3       wk = load(w[k]);
        if (dot(T, T) > 0.)
          {
            wk = wk + h * (inverse_inertia[k] * T);
            store(w[k], wk);
          }
        // ... and NewtonEulerIntegrator's drift and exact rotation of an
        // isotropic body.
        const V3 xk = load(x[k]) + h * vk;
        store(x[k], xk);
        const double w2 = dot(wk, wk);
        if (w2 > 0.)
          q[k] = rotated(q[k], wk, w2, h);
        const V3 moved = xk - load(x_list[k]);
        stale |= dot(moved, moved) > limit;
      };

      std::size_t k = 0;
#ifdef __SSE2__
      // Two spheres at a time, one per lane, as in the pair loop (bit for bit
      // the scalar result): the renormalisation's square root and division
      // end a chain of dependent operations per sphere. A fixed sphere, one
      // that does not spin, and one that turns too far for the Taylor series
      // take the scalar body.
      const __m128d h2 = _mm_set1_pd(h), z = _mm_setzero_pd();
      const P3      g2{_mm_set1_pd(g.x), _mm_set1_pd(g.y), _mm_set1_pd(g.z)};
      auto          put = [](double *const a, double *const b, const P3 &v) {
        _mm_storel_pd(a, v.x);
        _mm_storel_pd(a + 1, v.y);
        _mm_storel_pd(a + 2, v.z);
        _mm_storeh_pd(b, v.x);
        _mm_storeh_pd(b + 1, v.y);
        _mm_storeh_pd(b + 2, v.z);
      };
      __m128d stale2 = z;
      for (; k + 1 < n; k += 2)
        {
          const __m128d im = lanes(inverse_mass[k], inverse_mass[k + 1]);
          if (_mm_movemask_pd(_mm_cmpeq_pd(im, z)) != 0)
            {
              one_sphere(k);
              one_sphere(k + 1);
              continue;
            }
          const P3 F = lanes(f[k], f[k + 1]), T_contact = lanes(t[k], t[k + 1]);
          const P3 F_applied = loads   ? lanes(applied_f[k], applied_f[k + 1]) :
                               buoyant ? lanes(buoyancy[k], buoyancy[k + 1]) :
                                         P3{z, z, z};
          const P3 vk
            = lanes(v[k], v[k + 1]) + h2 * (im * (F_applied + F) + g2);
          const P3 wk0 = lanes(w[k], w[k + 1]);
          const P3 T   = loads ?
                           lanes(applied_t[k], applied_t[k + 1]) + T_contact :
                           T_contact;
          const P3 wk  = select(
            _mm_cmpgt_pd(dot(T, T), z),
            wk0 + h2 * (lanes(inverse_inertia[k], inverse_inertia[k + 1]) * T),
            wk0);
          const __m128d w2 = dot(wk, wk);
          const __m128d x2
            = _mm_mul_pd(_mm_mul_pd(_mm_set1_pd(0.25 * h), h2), w2); // (a/2)^2
          if (_mm_movemask_pd(_mm_and_pd(_mm_cmpgt_pd(w2, z),
                                         _mm_cmple_pd(x2, _mm_set1_pd(0.01))))
              != 3)
            {
              one_sphere(k);
              one_sphere(k + 1);
              continue;
            }
          put(f[k].data(), f[k + 1].data(), P3{z, z, z});
          put(t[k].data(), t[k + 1].data(), P3{z, z, z});
          put(v[k].data(), v[k + 1].data(), vk);
          put(w[k].data(), w[k + 1].data(), wk);
          const P3 xk = lanes(x[k], x[k + 1]) + h2 * vk;
          put(x[k].data(), x[k + 1].data(), xk);
          // rotated(), Taylor branch
          const __m128d c = _mm_add_pd(
            _mm_set1_pd(1.),
            _mm_mul_pd(
              x2,
              _mm_add_pd(
                _mm_set1_pd(-1. / 2.),
                _mm_mul_pd(
                  x2,
                  _mm_add_pd(
                    _mm_set1_pd(1. / 24.),
                    _mm_mul_pd(x2,
                               _mm_add_pd(_mm_set1_pd(-1. / 720.),
                                          _mm_mul_pd(x2,
                                                     _mm_set1_pd(
                                                       1. / 40320.)))))))));
          const __m128d sn = _mm_mul_pd(
            _mm_set1_pd(0.5 * h),
            _mm_add_pd(
              _mm_set1_pd(1.),
              _mm_mul_pd(
                x2,
                _mm_add_pd(
                  _mm_set1_pd(-1. / 6.),
                  _mm_mul_pd(
                    x2,
                    _mm_add_pd(
                      _mm_set1_pd(1. / 120.),
                      _mm_mul_pd(x2,
                                 _mm_add_pd(_mm_set1_pd(-1. / 5040.),
                                            _mm_mul_pd(x2,
                                                       _mm_set1_pd(
                                                         1. / 362880.))))))))));
          Eigen::Quaterniond &q0 = q[k], &q1 = q[k + 1];
          const __m128d       qx = lanes(q0.coeffs()[0], q1.coeffs()[0]),
                        qy       = lanes(q0.coeffs()[1], q1.coeffs()[1]),
                        qz       = lanes(q0.coeffs()[2], q1.coeffs()[2]),
                        qw       = lanes(q0.coeffs()[3], q1.coeffs()[3]);
          const __m128d dx = _mm_mul_pd(sn, wk.x), dy = _mm_mul_pd(sn, wk.y),
                        dz = _mm_mul_pd(sn, wk.z);
          auto mul
            = [](const __m128d a, const __m128d b) { return _mm_mul_pd(a, b); };
          const __m128d rw
            = _mm_sub_pd(_mm_sub_pd(_mm_sub_pd(mul(c, qw), mul(dx, qx)),
                                    mul(dy, qy)),
                         mul(dz, qz));
          const __m128d rx
            = _mm_sub_pd(_mm_add_pd(_mm_add_pd(mul(c, qx), mul(dx, qw)),
                                    mul(dy, qz)),
                         mul(dz, qy));
          const __m128d ry
            = _mm_add_pd(_mm_add_pd(_mm_sub_pd(mul(c, qy), mul(dx, qz)),
                                    mul(dy, qw)),
                         mul(dz, qx));
          const __m128d rz
            = _mm_add_pd(_mm_sub_pd(_mm_add_pd(mul(c, qz), mul(dx, qy)),
                                    mul(dy, qx)),
                         mul(dz, qw));
          const __m128d inv = _mm_div_pd(
            _mm_set1_pd(1.),
            _mm_sqrt_pd(_mm_add_pd(
              _mm_add_pd(_mm_add_pd(mul(rw, rw), mul(rx, rx)), mul(ry, ry)),
              mul(rz, rz))));
          put(q0.coeffs().data(),
              q1.coeffs().data(),
              P3{mul(inv, rx), mul(inv, ry), mul(inv, rz)});
          _mm_storel_pd(&q0.coeffs()[3], mul(inv, rw));
          _mm_storeh_pd(&q1.coeffs()[3], mul(inv, rw));
          const P3 moved = xk - lanes(x_list[k], x_list[k + 1]);
          stale2
            = _mm_or_pd(stale2,
                        _mm_cmpgt_pd(dot(moved, moved), _mm_set1_pd(limit)));
        }
      stale |= _mm_movemask_pd(stale2) != 0;
#endif
      for (; k < n; ++k)
        one_sphere(k);
      return stale;
    }



    void
    SphereDem::step(const unsigned int n_substeps,
                    const double       h,
                    StepStatistics    &stats)
    {
      dropped_.clear();
      for (unsigned int s = 0; s < n_substeps; ++s)
        {
          auto t0 = Clock::now();
          if (rebuild_needed_)
            rebuild(x_, history(), s > 0);
          stats.time_broad += seconds_since(t0);

          t0 = Clock::now();
          if (settings_.record_contact_forces)
            contact_forces<true>(h, s == 0, s + 1 == n_substeps);
          else
            contact_forces<false>(h, s == 0, s + 1 == n_substeps);
          stats.time_solve += seconds_since(t0);

          t0 = Clock::now();
          rebuild_needed_
            = loads_applied_ ? integrate<true>(h) : integrate<false>(h);
          stats.time_integrate += seconds_since(t0);
        }
      if (loads_applied_) // each step's loads act over that step only
        {
          applied_f_ = buoyancy_;
          std::fill(applied_t_.begin(),
                    applied_t_.end(),
                    Eigen::Vector3d::Zero());
          loads_applied_ = false;
        }
      stats.pairs             = pairs_.size() + walls_.size();
      stats.contacts          = contacts_;
      stats.solver_iterations = 1;
    }



    void
    SphereDem::append_contact_forces(const double               dt,
                                     std::vector<ContactForce> &out) const
    {
      auto add = [&](const BodyId a, const BodyId b, const Load &load) {
        if (!(load.weight > 0.))
          return;
        const Eigen::Vector3d F = load.impulse / dt; // on b
        const Eigen::Vector3d p = load.moment / load.weight;
        out.push_back({b, a, p, F});
        out.push_back({a, b, p, -F});
      };
      for (const History &h : history())
        add(h.key >> 32, h.key & 0xffffffffu, h.load);
      for (const auto &[key, load] : dropped_)
        add(key >> 32, key & 0xffffffffu, load);
    }



    void
    SphereDem::export_state(const std::vector<RigidBody> &bodies,
                            std::vector<ContactEdge>     &edges,
                            std::vector<ContactEdge>     &dropped,
                            std::vector<Eigen::Vector3d> &list_positions) const
    {
      auto edge = [](const std::uint64_t key, const Load &load) {
        ContactEdge e;
        e.manifold.a   = key >> 32;
        e.manifold.b   = key & 0xffffffffu;
        e.step_impulse = load.impulse;
        e.step_moment  = load.moment;
        e.step_weight  = load.weight;
        return e;
      };
      // Contact points as the general narrow phase makes them, from the
      // current positions; a point also for a spring that must survive.
      auto add_point = [&](ContactEdge           &e,
                           const Eigen::Vector3d &position,
                           const Eigen::Vector3d &normal,
                           const double           gap,
                           const Eigen::Vector3d &spring) {
        if (gap > settings_.margin && spring.squaredNorm() == 0.)
          return;
        ContactPoint c;
        c.position   = position;
        c.normal     = normal;
        c.distance   = gap;
        c.local_a    = bodies[e.manifold.a].to_body(position);
        c.dem_spring = spring;
        e.manifold.points.push_back(c);
        e.state = EdgeState::persistent_contact;
      };
      const std::vector<History> h = history();
      edges.clear();
      for (std::size_t k = 0; k < pairs_.size(); ++k)
        {
          const SpherePair      &p  = pairs_[k];
          ContactEdge            e  = edge(h[k].key, h[k].load);
          const Eigen::Vector3d &xa = x_[p.i], d = x_[p.j] - xa;
          const double           dist = d.norm();
          const double           gap
            = dist - radius_[p.i] - radius_[p.j] - settings_.offset;
          const Eigen::Vector3d n
            = dist > 0. ? Eigen::Vector3d(d / dist) : Eigen::Vector3d::UnitZ();
          add_point(e,
                    xa + (radius_[p.i] + 0.5 * (gap + settings_.offset)) * n,
                    n,
                    gap,
                    h[k].spring);
          edges.push_back(std::move(e));
        }
      for (std::size_t k = 0; k < walls_.size(); ++k)
        {
          const WallPair        &p = walls_[k];
          const History         &r = h[pairs_.size() + k];
          ContactEdge            e = edge(r.key, r.load);
          const Eigen::Vector3d &x = x_[p.sphere], &n = wall_normal_[p.wall];
          const double           radius = radius_[p.sphere];
          const double           raw = n.dot(x) - wall_offset_[p.wall] - radius;
          const bool             wall_first = wall_id_[p.wall] < id_[p.sphere];
          add_point(e,
                    0.5 * ((x - radius * n) + (x - (radius + raw) * n)),
                    wall_first ? n : Eigen::Vector3d(-n),
                    raw - settings_.offset,
                    r.spring);
          edges.push_back(std::move(e));
        }
      std::sort(edges.begin(),
                edges.end(),
                [](const ContactEdge &a, const ContactEdge &b) {
                  return a.manifold.a != b.manifold.a ?
                           a.manifold.a < b.manifold.a :
                           a.manifold.b < b.manifold.b;
                });
      dropped.clear();
      for (const auto &[key, load] : dropped_)
        dropped.push_back(edge(key, load));
      list_positions.resize(bodies.size());
      for (std::size_t k = 0; k < id_.size(); ++k)
        list_positions[id_[k]] = x_list_[k];
      for (std::size_t w = 0; w < wall_id_.size(); ++w)
        list_positions[wall_id_[w]] = wall_list_position_[w];
    }
  } // namespace rigid
} // namespace particulate
