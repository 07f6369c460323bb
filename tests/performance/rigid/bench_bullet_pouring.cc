// The pouring scene of issue 3 run by this engine and by Bullet 3 (Debian's
// libbullet-dev, linked by this benchmark only): the scene of
// tests/rigid/test_pouring.cc (PouringDescription's jittered lattice,
// e = 0.2, mu = 0.3, sequential impulses, dt = 1 ms) with its lengths
// scaled by `--scale` (default 10: radii uniform in [4, 6] cm), in an open
// box of side 0.1 m * scale * sqrt(N / 1000), so that every N starts as a
// column of about 20 layers. The default scale is for Bullet: its broad
// phase fattens every box by a fixed 5 cm (DBVT_BP_MARGIN), which at the
// test's millimetre scale (--scale 1) makes almost every sphere pair a
// candidate pair; ours has no absolute length in it.
//
// Both engines get the same bodies, initial velocities, time step, pair
// restitution and friction and the same number of solver sweeps; the
// penetration is measured here from the positions, by one formula for both.
// Times are thread CPU time of the step calls only (the machine is shared).
// Prints one Markdown row per engine and N.
//
// Usage: bench_rigid_bullet_pouring [N:steps ...] [--iterations k]
//        [--scale s]
// (default 1000:400, 10 sweeps as Bullet's default, scale 10).
#include <particulate/rigid/scene.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <dirent.h>

using namespace particulate::rigid;

namespace {
  double
  thread_seconds()
  {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1.e-9 * t.tv_nsec;
  }

  double
  process_seconds()
  {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1.e-9 * t.tv_nsec;
  }

  /** Threads of this process (entries of /proc/self/task). */
  unsigned int
  n_threads()
  {
    unsigned int n = 0;
    if (DIR *d = opendir("/proc/self/task"))
      {
        while (const dirent *e = readdir(d))
          n += e->d_name[0] != '.';
        closedir(d);
      }
    return n;
  }

  /** The scene as both engines see it: spheres, then the walls n.x >= c. */
  struct Scene
  {
    std::vector<Eigen::Vector3d> x0, v0;
    std::vector<double>          radius;
    std::vector<Eigen::Vector3d> wall_normal;
    std::vector<double>          wall_offset;
    SceneDescription             description;
  };

  Scene
  make_scene(const unsigned int n,
             const unsigned int iterations,
             const double       scale)
  {
    Scene             s;
    SceneDescription &d       = s.description;
    d.world.contact_solver    = ContactSolverType::sequential_impulses;
    d.world.solver.iterations = iterations;
    Material &m               = d.materials[0];
    m.density                 = 1000.;
    m.restitution             = 0.2;
    m.static_friction = m.dynamic_friction = 0.3;
    auto &p                                = d.pouring;
    p.n_spheres                            = n;
    p.radius_min                           = 0.004 * scale;
    p.radius_max                           = 0.006 * scale;
    const double side                      = 0.1 * scale * std::sqrt(n / 1000.);
    p.box_min                              = Eigen::Vector3d::Zero();
    p.box_max                              = Eigen::Vector3d(side, side, side);
    p.seed                                 = 7;
    d.time_step                            = 1.e-3;
    for (const BodyDescription &b : p.generate())
      if (b.fixed)
        {
          // A half-space at the origin: solid where n.x < offset.
          s.wall_normal.push_back(b.shape.normal);
          s.wall_offset.push_back(b.shape.offset);
        }
      else
        {
          s.x0.push_back(b.position);
          s.v0.push_back(b.velocity);
          s.radius.push_back(b.shape.radius);
        }
    return s;
  }

  /**
   * Deepest overlap of the spheres at @p x with each other and with the
   * walls, relative to the smaller radius of the pair: a uniform grid of
   * cells one largest diameter wide, each pair tested once.
   */
  double
  max_relative_penetration(const Scene                        &s,
                           const std::vector<Eigen::Vector3d> &x)
  {
    double worst = 0.;
    for (unsigned int i = 0; i < x.size(); ++i)
      for (unsigned int w = 0; w < s.wall_normal.size(); ++w)
        worst = std::max(worst,
                         (s.radius[i]
                          - (s.wall_normal[w].dot(x[i]) - s.wall_offset[w]))
                           / s.radius[i]);
    const double cell
      = 2. * *std::max_element(s.radius.begin(), s.radius.end());
    auto key = [cell](const Eigen::Vector3d &p,
                      const int              dx,
                      const int              dy,
                      const int              dz) {
      const std::int64_t i = std::int64_t(std::floor(p[0] / cell)) + dx,
                         j = std::int64_t(std::floor(p[1] / cell)) + dy,
                         k = std::int64_t(std::floor(p[2] / cell)) + dz;
      return (i * 73856093) ^ (j * 19349663) ^ (k * 83492791);
    };
    std::unordered_multimap<std::int64_t, unsigned int> grid;
    grid.reserve(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      grid.emplace(key(x[i], 0, 0, 0), i);
    for (unsigned int i = 0; i < x.size(); ++i)
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz)
            {
              const auto range = grid.equal_range(key(x[i], dx, dy, dz));
              for (auto it = range.first; it != range.second; ++it)
                {
                  const unsigned int j = it->second;
                  if (j <= i) // each pair once; hash collisions are harmless
                    continue;
                  const double overlap
                    = s.radius[i] + s.radius[j] - (x[j] - x[i]).norm();
                  worst
                    = std::max(worst,
                               overlap / std::min(s.radius[i], s.radius[j]));
                }
            }
    return worst;
  }

  /** What one engine did with one scene. */
  struct Result
  {
    double       cpu_per_step = 0., process_per_step = 0.;
    double       pen_max = 0., pen_final = 0., kinetic_energy = 0.;
    double       rest_time = -1., energy_ratio = 0.;
    unsigned int threads = 0;
  };

  /**
   * The stepping loop shared by both engines: times step() in thread CPU
   * time, measures the penetration after every step (untimed) and checks
   * every 10 steps whether the bed is at rest (translational energy below
   * 1e-6 of the initial potential energy, as in test_pouring).
   */
  template <typename Engine>
  Result
  run(const Scene &s, Engine &engine, const unsigned int steps)
  {
    std::vector<double> mass(s.radius.size());
    double              pe0 = 0.;
    for (unsigned int i = 0; i < mass.size(); ++i)
      {
        mass[i] = s.description.materials[0].density * 4. / 3. * M_PI
                  * std::pow(s.radius[i], 3);
        pe0 += mass[i] * 9.81 * s.x0[i][2];
      }
    std::vector<Eigen::Vector3d> x, v;
    Result                       r;
    double                       cpu = 0., process = 0.;
    for (unsigned int k = 1; k <= steps; ++k)
      {
        const double t0 = thread_seconds(), p0 = process_seconds();
        engine.step(s.description.time_step);
        cpu += thread_seconds() - t0;
        process += process_seconds() - p0;
        engine.read(x, v);
        r.pen_final = max_relative_penetration(s, x);
        r.pen_max   = std::max(r.pen_max, r.pen_final);
        double ke   = 0.;
        for (unsigned int i = 0; i < v.size(); ++i)
          ke += 0.5 * mass[i] * v[i].squaredNorm();
        r.kinetic_energy = ke;
        r.energy_ratio   = ke / pe0;
        if (r.rest_time < 0. && k % 10 == 0 && ke < 1.e-6 * pe0)
          r.rest_time = k * s.description.time_step;
      }
    r.cpu_per_step     = cpu / steps;
    r.process_per_step = process / steps;
    r.threads          = n_threads();
    return r;
  }

  /** This engine: the World built from the scene description. */
  class Ours
  {
  public:
    explicit Ours(const Scene &s)
      : world_(s.description.build_world())
    {
      for (BodyId id = 0; id < world_.n_bodies(); ++id)
        if (!world_.body(id).is_fixed())
          spheres_.push_back(id);
    }
    void
    step(const double dt)
    {
      world_.step(dt);
    }
    void
    read(std::vector<Eigen::Vector3d> &x, std::vector<Eigen::Vector3d> &v) const
    {
      x.resize(spheres_.size());
      v.resize(spheres_.size());
      for (unsigned int i = 0; i < spheres_.size(); ++i)
        {
          x[i] = world_.body(spheres_[i]).position;
          v[i] = world_.body(spheres_[i]).linear_velocity;
        }
    }

  private:
    World               world_;
    std::vector<BodyId> spheres_;
  };

  /**
   * Bullet's standard rigid-body pipeline (DBVT broad phase, sequential
   * impulses, btDiscreteDynamicsWorld, single-threaded) with its default
   * tuning except: the sweep count, no sleeping (ours never puts bodies to
   * sleep either) and per-body restitution and friction of sqrt(e) and
   * sqrt(mu), because Bullet multiplies the two bodies' values where ours
   * takes the minimum and the geometric mean: both then use e and mu per
   * pair.
   */
  class Bullet
  {
  public:
    Bullet(const Scene &s, const unsigned int iterations)
      : dispatcher_(&configuration_)
      , world_(&dispatcher_, &broad_phase_, &solver_, &configuration_)
    {
      world_.setGravity(btVector3(0., 0., -9.81));
      world_.getSolverInfo().m_numIterations = iterations;
      const Material &m                      = s.description.materials[0];
      const double    restitution            = std::sqrt(m.restitution);
      const double    friction               = std::sqrt(m.dynamic_friction);
      auto            add                    = [&](btCollisionShape      *shape,
                     const double           mass,
                     const Eigen::Vector3d &x) {
        btVector3 inertia(0., 0., 0.);
        if (mass > 0.)
          shape->calculateLocalInertia(mass, inertia);
        btRigidBody::btRigidBodyConstructionInfo info(mass,
                                                      nullptr,
                                                      shape,
                                                      inertia);
        info.m_startWorldTransform.setIdentity();
        info.m_startWorldTransform.setOrigin(btVector3(x[0], x[1], x[2]));
        info.m_restitution = restitution;
        info.m_friction    = friction;
        bodies_.push_back(std::make_unique<btRigidBody>(info));
        bodies_.back()->setActivationState(DISABLE_DEACTIVATION);
        world_.addRigidBody(bodies_.back().get());
        return bodies_.back().get();
      };
      for (unsigned int w = 0; w < s.wall_normal.size(); ++w)
        {
          const Eigen::Vector3d &n = s.wall_normal[w];
          shapes_.push_back(
            std::make_unique<btStaticPlaneShape>(btVector3(n[0], n[1], n[2]),
                                                 s.wall_offset[w]));
          add(shapes_.back().get(), 0., Eigen::Vector3d::Zero());
        }
      const double density = m.density;
      for (unsigned int i = 0; i < s.x0.size(); ++i)
        {
          shapes_.push_back(std::make_unique<btSphereShape>(s.radius[i]));
          btRigidBody *b
            = add(shapes_.back().get(),
                  density * 4. / 3. * M_PI * std::pow(s.radius[i], 3),
                  s.x0[i]);
          b->setLinearVelocity(btVector3(s.v0[i][0], s.v0[i][1], s.v0[i][2]));
          spheres_.push_back(b);
        }
    }
    ~Bullet()
    {
      for (auto &b : bodies_)
        world_.removeRigidBody(b.get());
    }
    void
    step(const double dt)
    {
      // maxSubSteps = 0: exactly one internal step of dt, no interpolation.
      world_.stepSimulation(dt, 0);
    }
    void
    read(std::vector<Eigen::Vector3d> &x, std::vector<Eigen::Vector3d> &v) const
    {
      x.resize(spheres_.size());
      v.resize(spheres_.size());
      for (unsigned int i = 0; i < spheres_.size(); ++i)
        {
          const btVector3 &p = spheres_[i]->getWorldTransform().getOrigin();
          const btVector3 &u = spheres_[i]->getLinearVelocity();
          x[i]               = Eigen::Vector3d(p.x(), p.y(), p.z());
          v[i]               = Eigen::Vector3d(u.x(), u.y(), u.z());
        }
    }

  private:
    btDefaultCollisionConfiguration                configuration_;
    btCollisionDispatcher                          dispatcher_;
    btDbvtBroadphase                               broad_phase_;
    btSequentialImpulseConstraintSolver            solver_;
    btDiscreteDynamicsWorld                        world_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<std::unique_ptr<btRigidBody>>      bodies_;
    std::vector<btRigidBody *>                     spheres_;
  };

  void
  print_row(const char        *engine,
            const unsigned int n,
            const unsigned int steps,
            const double       dt,
            const Result      &r)
  {
    char rest[64];
    if (r.rest_time > 0.)
      std::snprintf(rest, sizeof rest, "yes, t = %.2f s", r.rest_time);
    else
      std::snprintf(rest,
                    sizeof rest,
                    "no: KE/PE0 = %.1e at t = %.2f s",
                    r.energy_ratio,
                    steps * dt);
    std::printf("| %u | %s | %u | %.2f | %.2f | %.2f | %.3f | %.3f | %.3g | %s "
                "| %u |\n",
                n,
                engine,
                steps,
                1.e3 * r.cpu_per_step,
                1.e6 * r.cpu_per_step / n,
                r.process_per_step / r.cpu_per_step,
                100. * r.pen_max,
                100. * r.pen_final,
                r.kinetic_energy,
                rest,
                r.threads);
    std::fflush(stdout);
  }
} // namespace

int
main(int argc, char **argv)
{
  std::vector<std::pair<unsigned int, unsigned int>> runs;
  unsigned int                                       iterations = 10;
  double                                             scale      = 10.;
  for (int a = 1; a < argc; ++a)
    {
      const std::string arg = argv[a];
      if (arg == "--iterations" && a + 1 < argc)
        iterations = std::atoi(argv[++a]);
      else if (arg == "--scale" && a + 1 < argc)
        scale = std::atof(argv[++a]);
      else
        {
          const auto colon = arg.find(':');
          runs.emplace_back(std::stoul(arg.substr(0, colon)),
                            colon == std::string::npos ?
                              400 :
                              std::stoul(arg.substr(colon + 1)));
        }
    }
  if (runs.empty())
    runs.emplace_back(1000, 400);

  std::printf("Bullet %d, btScalar of %zu bytes, %d task-scheduler threads; "
              "%u solver sweeps for both engines\n\n",
              btGetVersion(),
              sizeof(btScalar),
              btGetTaskScheduler() ? btGetTaskScheduler()->getNumThreads() : 1,
              iterations);
  std::printf(
    "| N | engine | steps | ms/step | µs/sphere-step | process/thread CPU | "
    "max pen. over run (%% r) | final pen. (%% r) | final KE (J) | at rest | "
    "threads |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto &[n, steps] : runs)
    {
      const Scene s = make_scene(n, iterations, scale);
      {
        Ours ours(s);
        print_row("this engine (SI)",
                  n,
                  steps,
                  s.description.time_step,
                  run(s, ours, steps));
      }
      {
        Bullet bullet(s, iterations);
        print_row("Bullet",
                  n,
                  steps,
                  s.description.time_step,
                  run(s, bullet, steps));
      }
    }
  return 0;
}
