#include <particulate/geometry/half_space.h>
#include <particulate/rigid/dem_solver.h>
#include <particulate/rigid/narrow_phase.h>
#include <particulate/rigid/newton_euler_integrator.h>
#include <particulate/rigid/world.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "phase_clock.h"

namespace particulate {
  namespace rigid {
    using detail::Clock;
    using detail::seconds_since;



    void
    WorldParameters::check() const
    {
      auto fail = [](const std::string &what) {
        throw std::invalid_argument("rigid::WorldParameters: " + what);
      };
      if (!gravity.allFinite())
        fail("gravity must be finite (m/s^2).");
      if (substeps < 1)
        fail("'substeps' must be at least 1.");
      if (!(contact_margin >= 0.))
        fail("the contact margin must be >= 0 m (0 selects it automatically).");
      if (!(contact_offset >= 0.) || !std::isfinite(contact_offset))
        fail("the contact offset must be a finite length >= 0 m.");
      if (!(fluid_density >= 0.))
        fail("the fluid density must be >= 0 kg/m^3.");
      if (!(dem_steps_per_contact >= 1.))
        fail("'DEM steps per contact' must be >= 1 (20 or more is advisable).");
      if (!(grid_level_ratio > 1.))
        fail("the hash-grid level ratio must exceed 1.");
      if (!(broad_phase_skin >= 0.))
        fail(
          "the broad-phase skin must be >= 0 m (0 selects it automatically).");
      if (solver.iterations < 1)
        fail("the contact solver needs at least one iteration.");
      if (!(solver.baumgarte >= 0. && solver.baumgarte <= 1.))
        fail("the Baumgarte factor must lie in [0, 1].");
      if (!(solver.penetration_slop >= 0.)
          || !(solver.restitution_threshold >= 0.)
          || !(solver.sticking_speed >= 0.) || !(solver.tolerance >= 0.))
        fail(
          "slop, restitution threshold, sticking speed and tolerance must be >= 0.");
    }



    World::World(const WorldParameters &parameters)
      : parameters_(parameters)
      , grid_(parameters.grid_level_ratio)
    {
      parameters_.check();
      solver_
        = ContactSolver::create(parameters_.contact_solver, parameters_.solver);
    }



    unsigned int
    World::add_material(const Material &m)
    {
      m.check();
      if (sphere_dem_) // it holds the pair materials
        hand_back_sphere_dem();
      materials_.push_back(m);
      const unsigned int n = materials_.size();
      pair_materials_.assign(n * n, ContactMaterial());
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            const Material c = Material::combine(materials_[i], materials_[j]);
            ContactMaterial &p     = pair_materials_[i * n + j];
            p.restitution          = c.restitution;
            p.static_friction      = c.static_friction;
            p.dynamic_friction     = c.dynamic_friction;
            p.stiffness            = c.dem_stiffness;
            p.tangential_stiffness = c.dem_tangential_stiffness;
            p.damping_ratio        = DemSolver::damping_ratio(c.restitution);
          }
      return n - 1;
    }



    BodyId
    World::add_body(std::shared_ptr<const geometry::Shape> shape,
                    const unsigned int                     material,
                    const Eigen::Vector3d                 &position,
                    const Eigen::Quaterniond              &orientation,
                    const bool                             fixed)
    {
      if (material >= materials_.size())
        throw std::invalid_argument(
          "rigid::World::add_body(): material index " + std::to_string(material)
          + " does not exist; call add_material() first (there are "
          + std::to_string(materials_.size()) + " materials).");
      if (!position.allFinite() || !orientation.coeffs().allFinite()
          || !(orientation.norm() > 0.))
        throw std::invalid_argument(
          "rigid::World::add_body(): position and orientation must be finite "
          "(and the quaternion non-zero).");
      if (sphere_dem_) // it holds the bodies and the lengths set below
        hand_back_sphere_dem();
      bodies_.emplace_back(std::move(shape),
                           material,
                           materials_[material].density,
                           fixed);
      collision_group_.push_back(0);
      RigidBody &b  = bodies_.back();
      b.position    = position;
      b.orientation = orientation.normalized();
      if (!SphereDem::can_handle(b))
        ++n_general_only_;
      if (!b.is_fixed())
        {
          // Smallest effective mass at a contact (for the DEM substeps): half
          // the mass (two equal bodies), or the rotational I_min / R^2 for
          // off-centre contacts.
          const double R = b.bounding_radius();
          smallest_contact_mass_
            = std::min({smallest_contact_mass_,
                        0.5 * b.mass(),
                        b.principal_inertia().minCoeff() / (R * R)});
        }
      const double r = b.bounding_radius();
      if (std::isfinite(r))
        min_radius_ = min_radius_ > 0. ? std::min(min_radius_, r) : r;
      margin_ = parameters_.contact_margin > 0. ? parameters_.contact_margin :
                                                  0.02 * min_radius_;
      // Automatic slop: 0.2 % of the smallest body. Resting contacts whose
      // tiny overlap stays below it get no Baumgarte push, which would
      // otherwise feed energy into stacks when the iterations stop early.
      skin_ = parameters_.broad_phase_skin > 0. ? parameters_.broad_phase_skin :
                                                  0.2 * min_radius_;
      broad_positions_.clear(); // forces a new broad phase
      if (parameters_.solver.penetration_slop == 0.)
        solver_->parameters.penetration_slop = 0.002 * min_radius_;
      return bodies_.size() - 1;
    }



    RigidBody &
    World::body(const BodyId id)
    {
      if (id >= bodies_.size())
        throw std::out_of_range("rigid::World::body(): no body with id "
                                + std::to_string(id) + " (there are "
                                + std::to_string(bodies_.size()) + ").");
      sync_bodies();
      bodies_written_ = true;
      return bodies_[id];
    }



    const RigidBody &
    World::body(const BodyId id) const
    {
      if (id >= bodies_.size())
        throw std::out_of_range("rigid::World::body(): no body with id "
                                + std::to_string(id) + " (there are "
                                + std::to_string(bodies_.size()) + ").");
      sync_bodies();
      return bodies_[id];
    }



    void
    World::sync_bodies() const
    {
      if (bodies_behind_ && sphere_dem_)
        sphere_dem_->write_bodies(bodies_);
      bodies_behind_ = false;
    }



    void
    World::set_external_force_and_torque(const BodyId           id,
                                         const Eigen::Vector3d &force,
                                         const Eigen::Vector3d &torque)
    {
      RigidBody &b = body(id);
      b.force      = force;
      b.torque     = torque;
    }



    unsigned int
    World::substeps_for(const double dt) const
    {
      unsigned int n = parameters_.substeps;
      if (parameters_.contact_solver == ContactSolverType::dem)
        {
          // Shortest binary contact time over all material pairs, with the
          // lightest dynamic body as the reduced mass (conservative).
          const double m_min = smallest_contact_mass_;
          if (std::isfinite(m_min))
            {
              double kmax = 0.;
              for (const auto &p : pair_materials_)
                kmax = std::max(kmax,
                                std::max(p.stiffness, p.tangential_stiffness));
              const double tc = M_PI * std::sqrt(m_min / kmax);
              n               = std::max<unsigned int>(
                n,
                std::ceil(dt * parameters_.dem_steps_per_contact / tc - 1.e-9));
            }
        }
      return n;
    }



    void
    World::set_collision_group(const BodyId id, const unsigned int group)
    {
      if (id >= bodies_.size())
        throw std::invalid_argument(
          "rigid::World::set_collision_group(): no body " + std::to_string(id)
          + ".");
      if (sphere_dem_)
        hand_back_sphere_dem();
      collision_group_[id] = group;
      any_collision_group_ = any_collision_group_ || group != 0;
    }



    bool
    World::sphere_fast_path_applies() const
    {
      if (parameters_.contact_solver != ContactSolverType::dem
          || !parameters_.sphere_fast_path || n_general_only_ > 0
          || any_collision_group_)
        return false;
      // rotation locks may be set at any time, through body()
      if (sphere_dem_ && !bodies_written_)
        return true;
      return std::none_of(bodies_.begin(),
                          bodies_.end(),
                          [](const RigidBody &b) {
                            return b.rotation_locked();
                          });
    }



    void
    World::hand_back_sphere_dem()
    {
      sync_bodies();
      bodies_written_ = true;
      sphere_dem_->export_state(bodies_,
                                graph_.edges(),
                                dropped_,
                                broad_positions_);
      sphere_dem_.reset();
    }



    const ContactGraph &
    World::contact_graph() const
    {
      if (!sphere_dem_)
        return graph_;
      sync_bodies();
      std::vector<ContactEdge>     dropped;
      std::vector<Eigen::Vector3d> positions;
      graph_snapshot_ = ContactGraph();
      sphere_dem_->export_state(bodies_,
                                graph_snapshot_.edges(),
                                dropped,
                                positions);
      return graph_snapshot_;
    }



    bool
    World::skin_exceeded() const
    {
      if (broad_positions_.size() != bodies_.size())
        return true;
      const double limit = 0.25 * skin_ * skin_; // (skin / 2)^2
      for (unsigned int i = 0; i < bodies_.size(); ++i)
        if ((bodies_[i].position - broad_positions_[i]).squaredNorm() > limit)
          return true;
      return false;
    }



    void
    World::broad_phase(const double horizon)
    {
      // DEM (horizon 0): Verlet skin instead of a velocity bound; remember
      // where the bodies were.
      if (horizon == 0.)
        {
          broad_positions_.resize(bodies_.size());
          for (unsigned int i = 0; i < bodies_.size(); ++i)
            broad_positions_[i] = bodies_[i].position;
        }
      const double skin_half = horizon == 0. ? 0.5 * skin_ : 0.;
      const double g         = parameters_.gravity.norm();
      proxies_.resize(bodies_.size());
      for (unsigned int i = 0; i < bodies_.size(); ++i)
        {
          const RigidBody &b = bodies_[i];
          BroadPhaseProxy &p = proxies_[i];
          p.center           = b.position;
          p.fixed            = b.is_fixed();
          const double r     = b.bounding_radius();
          if (!std::isfinite(r))
            {
              if (b.shape().kind() != geometry::ShapeKind::half_space)
                throw std::logic_error(
                  "rigid::World: unbounded shape other than a half-space");
              const auto &hs
                = static_cast<const geometry::HalfSpace &>(b.shape());
              p.radius       = r;
              p.plane_normal = b.orientation * hs.normal();
              p.plane_offset = hs.offset() + p.plane_normal.dot(b.position)
                               + 0.5 * (margin_ + parameters_.contact_offset)
                               + horizon * b.linear_velocity.norm() + skin_half;
              continue;
            }
          // Inflate by half the margin plus how far the body may travel
          // before the next broad phase (twice its speed, for collisions that
          // speed it up, plus gravity).
          const double travel
            = b.is_fixed() ?
                horizon * b.linear_velocity.norm() :
                horizon
                  * (2. * b.linear_velocity.norm()
                     + b.angular_velocity.norm() * r + g * horizon);
          p.radius = r + 0.5 * (margin_ + parameters_.contact_offset)
                     + skin_half + travel;
        }
      grid_.update(proxies_);
      grid_.find_pairs(pairs_);
      if (any_collision_group_)
        pairs_.erase(std::remove_if(pairs_.begin(),
                                    pairs_.end(),
                                    [this](const BodyPair &p) {
                                      const unsigned int g
                                        = collision_group_[p.first];
                                      return g != 0
                                             && g == collision_group_[p.second];
                                    }),
                     pairs_.end());
      graph_.update(pairs_, &dropped_);
    }



    void
    World::narrow_phase(const double h)
    {
      const bool dem = parameters_.contact_solver == ContactSolverType::dem;
      std::vector<ContactPoint> old;
      for (ContactEdge &e : graph_.edges())
        {
          const RigidBody &a = bodies_[e.manifold.a],
                          &b = bodies_[e.manifold.b];
          // Detection works on the true shapes; the offset is taken off the
          // gaps afterwards, so the solvers see the inflated shapes.
          const double offset = parameters_.contact_offset;
          double       margin = margin_ + offset;
          if (!dem)
            {
              // Speculative margin: how much the gap may close in this step.
              const double ra
                = std::isfinite(a.bounding_radius()) ? a.bounding_radius() : 0.;
              const double rb
                = std::isfinite(b.bounding_radius()) ? b.bounding_radius() : 0.;
              margin += h
                        * ((a.linear_velocity - b.linear_velocity).norm()
                           + a.angular_velocity.norm() * ra
                           + b.angular_velocity.norm() * rb
                           + h * parameters_.gravity.norm());
            }
          if (a.shape().kind() == geometry::ShapeKind::sphere
              && b.shape().kind() == geometry::ShapeKind::sphere)
            {
              // Fast path for the most common pair (granular flows): update
              // the single contact point in place, keeping its cache.
              const double ra = a.bounding_radius(), rb = b.bounding_radius();
              const Eigen::Vector3d d    = b.position - a.position;
              const double          dist = d.norm();
              const double          gap  = dist - ra - rb - offset;
              auto                 &pts  = e.manifold.points;
              if (gap > margin - offset)
                {
                  pts.clear();
                  e.state = EdgeState::proximity;
                  continue;
                }
              const Eigen::Vector3d n = dist > 0. ? Eigen::Vector3d(d / dist) :
                                                    Eigen::Vector3d::UnitZ();
              if (pts.size() != 1 || pts[0].normal.dot(n) <= 0.9)
                {
                  pts.assign(1, ContactPoint());
                  e.state = EdgeState::new_contact;
                }
              else
                e.state = EdgeState::persistent_contact;
              ContactPoint &c = pts[0];
              c.position      = a.position + (ra + 0.5 * (gap + offset)) * n;
              c.normal        = n;
              c.distance      = gap;
              c.local_a       = a.orientation.conjugate() * (ra * n);
              continue;
            }
          old.swap(e.manifold.points);
          NarrowPhase::collide(a, b, margin, e);
          for (ContactPoint &c : e.manifold.points)
            c.distance -= offset;
          const double rmin
            = std::min(a.bounding_radius(), b.bounding_radius());
          ContactGraph::warm_start(e, old, 0.05 * rmin);
        }
    }



    void
    World::step(const double dt)
    {
      if (!(dt > 0.) || !std::isfinite(dt))
        throw std::invalid_argument(
          "rigid::World::step(): the time step must be a "
          "positive finite number of seconds, got "
          + std::to_string(dt) + ".");
      const unsigned int n_sub = substeps_for(dt);
      const double       h     = dt / n_sub;
      stats_                   = StepStatistics();
      stats_.substeps          = n_sub;
      const bool fast          = sphere_fast_path_applies();
      if (sphere_dem_ && !fast)
        hand_back_sphere_dem();

      if (fast) // reads and clears the accumulators in its own passes
        step_sphere_dem(n_sub, h);
      else
        {
          // Applied loads: accumulators plus buoyancy, constant over the step.
          applied_force_.resize(bodies_.size());
          applied_torque_.resize(bodies_.size());
          for (unsigned int i = 0; i < bodies_.size(); ++i)
            {
              const RigidBody &b = bodies_[i];
              applied_force_[i]  = b.force;
              applied_torque_[i] = b.torque;
              if (parameters_.fluid_density > 0. && !b.is_fixed())
                applied_force_[i] -= parameters_.fluid_density * b.volume()
                                     * parameters_.gravity;
            }
          step_general(n_sub, h);
          for (RigidBody &b : bodies_)
            b.clear_accumulators();
        }

      // Contact forces are assembled on demand (contact_forces()).
      forces_valid_ = false;
      last_dt_      = dt;
      time_ += dt;
      ++step_number_;
    }



    void
    World::step_sphere_dem(const unsigned int n_sub, const double h)
    {
      if (!sphere_dem_)
        {
          SphereDem::Settings settings;
          settings.margin                = margin_;
          settings.offset                = parameters_.contact_offset;
          settings.skin                  = skin_;
          settings.gravity               = parameters_.gravity;
          settings.fluid_density         = parameters_.fluid_density;
          settings.record_contact_forces = parameters_.record_contact_forces;
          sphere_dem_                    = std::make_unique<SphereDem>(bodies_,
                                                    pair_materials_,
                                                    materials_.size(),
                                                    settings,
                                                    graph_.edges(),
                                                    broad_positions_);
          // the sphere path holds the contact state from here on
          graph_ = ContactGraph();
          dropped_.clear();
          broad_positions_.clear();
        }
      // The arrays of the sphere path are the state between steps; the bodies
      // are read only when they may have changed, and written when read.
      const auto t0 = Clock::now();
      if (bodies_written_)
        sphere_dem_->read_bodies(bodies_);
      stats_.time_broad += seconds_since(t0);
      sphere_dem_->step(n_sub, h, stats_);
      bodies_written_ = false;
      bodies_behind_  = true;
    }



    void
    World::step_general(const unsigned int n_sub, const double h)
    {
      const bool dem = parameters_.contact_solver == ContactSolverType::dem;
      for (ContactEdge &e : graph_.edges())
        {
          e.step_impulse.setZero();
          e.step_moment.setZero();
          e.step_weight = 0.;
        }
      dropped_.clear();

      SolverContext ctx;
      ctx.bodies         = &bodies_;
      ctx.graph          = &graph_;
      ctx.pair_materials = &pair_materials_;
      ctx.n_materials    = materials_.size();
      ctx.forces         = &applied_force_;
      ctx.torques        = &applied_torque_;
      ctx.gravity        = parameters_.gravity;
      ctx.h              = h;

      for (unsigned int s = 0; s < n_sub; ++s)
        {
          auto t0 = Clock::now();
          if (!dem)
            broad_phase(h);
          else if (skin_exceeded())
            broad_phase(0.);
          stats_.time_broad += seconds_since(t0);

          t0 = Clock::now();
          narrow_phase(h);
#ifndef NDEBUG
          graph_.validate(bodies_.size());
#endif
          if (!dem) // the DEM works pairwise and needs no groups
            stats_.groups = graph_.compute_contact_groups(bodies_);
          stats_.time_narrow += seconds_since(t0);

          t0 = Clock::now();
          solver_->solve(ctx);
          stats_.solver_iterations
            = std::max(stats_.solver_iterations, solver_->last_iterations());
          for (ContactEdge &e : graph_.edges())
            for (const ContactPoint &c : e.manifold.points)
              {
                const double w = c.impulse.norm();
                e.step_impulse += c.impulse;
                e.step_moment += w * c.position;
                e.step_weight += w;
              }
          stats_.time_solve += seconds_since(t0);

          t0 = Clock::now();
          for (RigidBody &b : bodies_)
            NewtonEulerIntegrator::integrate_position(b, h);
          stats_.time_integrate += seconds_since(t0);
        }
      stats_.pairs = graph_.edges().size();
      for (const ContactEdge &e : graph_.edges())
        stats_.contacts += e.manifold.points.size();
    }



    void
    World::assemble_contact_forces() const
    {
      if (forces_valid_)
        return;
      forces_valid_ = true;
      contact_forces_.clear();
      force_offsets_.assign(bodies_.size() + 1, 0);
      if (!(last_dt_ > 0.))
        return;
      // Per pair: the step's impulse / dt at the impulse-weighted centre.
      auto add = [&](const ContactEdge &e) {
        if (!(e.step_weight > 0.))
          return;
        const Eigen::Vector3d F = e.step_impulse / last_dt_;
        const Eigen::Vector3d p = e.step_moment / e.step_weight;
        contact_forces_.push_back({e.manifold.b, e.manifold.a, p, F});
        contact_forces_.push_back({e.manifold.a, e.manifold.b, p, -F});
      };
      if (sphere_dem_)
        sphere_dem_->append_contact_forces(last_dt_, contact_forces_);
      else
        {
          for (const ContactEdge &e : graph_.edges())
            add(e);
          for (const ContactEdge &e : dropped_)
            add(e);
        }
      std::stable_sort(contact_forces_.begin(),
                       contact_forces_.end(),
                       [](const ContactForce &x, const ContactForce &y) {
                         return x.body != y.body ? x.body < y.body :
                                                   x.other < y.other;
                       });
      for (const ContactForce &f : contact_forces_)
        ++force_offsets_[f.body + 1];
      for (unsigned int i = 0; i < bodies_.size(); ++i)
        force_offsets_[i + 1] += force_offsets_[i];
    }



    const std::vector<ContactForce> &
    World::all_contact_forces() const
    {
      if (!parameters_.record_contact_forces)
        throw std::logic_error(
          "rigid::World::all_contact_forces(): this world does not record "
          "contact forces (WorldParameters::record_contact_forces is false).");
      assemble_contact_forces();
      return contact_forces_;
    }



    std::vector<ContactForce>
    World::contact_forces(const BodyId id) const
    {
      if (!parameters_.record_contact_forces)
        throw std::logic_error(
          "rigid::World::contact_forces(): this world does not record contact "
          "forces (WorldParameters::record_contact_forces is false).");
      assemble_contact_forces();
      if (id >= bodies_.size())
        throw std::out_of_range("rigid::World::contact_forces(): no body "
                                + std::to_string(id));
      if (force_offsets_.size() != bodies_.size() + 1)
        return {};
      return std::vector<ContactForce>(contact_forces_.begin()
                                         + force_offsets_[id],
                                       contact_forces_.begin()
                                         + force_offsets_[id + 1]);
    }



    double
    World::kinetic_energy() const
    {
      sync_bodies();
      double e = 0.;
      for (const RigidBody &b : bodies_)
        e += b.kinetic_energy();
      return e;
    }



    double
    World::max_penetration() const
    {
      if (sphere_dem_)
        return sphere_dem_->max_penetration();
      double p = 0.;
      for (const ContactEdge &e : graph_.edges())
        for (const ContactPoint &c : e.manifold.points)
          p = std::max(p, -c.distance);
      return p;
    }



    std::uint64_t
    World::state_hash() const
    {
      sync_bodies();
      std::uint64_t h   = 1469598103934665603ull;
      auto          mix = [&h](const double x) {
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        for (int k = 0; k < 8; ++k)
          {
            h ^= (bits >> (8 * k)) & 0xffu;
            h *= 1099511628211ull;
          }
      };
      for (const RigidBody &b : bodies_)
        {
          for (int k = 0; k < 3; ++k)
            {
              mix(b.position[k]);
              mix(b.linear_velocity[k]);
              mix(b.angular_velocity[k]);
            }
          for (int k = 0; k < 4; ++k)
            mix(b.orientation.coeffs()[k]);
        }
      return h;
    }
  } // namespace rigid
} // namespace particulate
