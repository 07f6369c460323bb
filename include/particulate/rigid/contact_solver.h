#ifndef particulate_rigid_contact_solver_h
#define particulate_rigid_contact_solver_h

#include <particulate/rigid/contact_graph.h>
#include <particulate/rigid/rigid_body.h>

#include <memory>
#include <string>
#include <vector>

namespace particulate {
  namespace rigid {
    /** The contact models of thesis §4.4, chosen in the input file. */
    enum class ContactSolverType
    {
      /** Velocity-level LCP with Coulomb friction (box-friction pyramid),
       * assembled per contact group and solved by projected Gauss–Seidel
       * (thesis §4.4.2–4.4.3, eqs. 4.69–4.72 and 4.84–4.86). */
      projected_gauss_seidel,
      /** Sequential impulses with accumulated-impulse clamping and a
       * circular friction cone (thesis §4.4.5, Algorithm 8, eq. 4.103). */
      sequential_impulses,
      /** Soft contact: linear spring–dashpot normal force and a
       * Coulomb-limited tangential spring (thesis §4.4.4, Algorithm 7). */
      dem
    };

    /** Name of a solver type as used in input files: "projected Gauss-Seidel",
     * "sequential impulses" or "DEM". */
    std::string
    to_string(ContactSolverType type);

    /** Inverse of to_string(); throws std::invalid_argument listing the valid
     * names for anything else. */
    ContactSolverType
    contact_solver_type_from_string(const std::string &name);

    /** Pair properties of a contact, precomputed per material pair. */
    struct ContactMaterial
    {
      /** Coefficient of restitution. */
      double restitution = 0.;
      /** Static friction coefficient. */
      double static_friction = 0.;
      /** Dynamic friction coefficient. */
      double dynamic_friction = 0.;
      /** DEM normal stiffness in N/m. */
      double stiffness = 1.e5;
      /** DEM tangential stiffness in N/m. */
      double tangential_stiffness = 2.e4;
      /** DEM damping ratio zeta that yields `restitution` (see DemSolver). */
      double damping_ratio = 1.;
    };

    /** Tuning of the contact solvers (all have safe defaults). */
    struct ContactSolverParameters
    {
      /** Sweeps of the PGS/SI contact solve per (sub)step. */
      unsigned int iterations = 100;
      /** Relative change of the impulses below which the sweeps stop. */
      double tolerance = 1.e-10;
      /** Maximum sweeps of the restitution (collision) pass. */
      unsigned int collision_iterations = 200;
      /** Approach speed in m/s below which a contact does not bounce (added
       * to 2 |g| h, so that resting contacts never bounce). */
      double restitution_threshold = 0.;
      /** Fraction of the penetration beyond the slop removed per step by the
       * velocity solvers (Baumgarte stabilisation). */
      double baumgarte = 0.2;
      /** Penetration in m tolerated without correction; 0 lets the World
       * choose 0.2 % of the smallest bounding radius. */
      double penetration_slop = 0.;
      /** Tangential speed in m/s below which a contact counts as sticking
       * (static friction applies) at the start of the step. */
      double sticking_speed = 1.e-4;
      /** Whether cached impulses from the previous step seed the solve. */
      bool warm_start = true;
    };

    /** Everything a contact solver works on during one (sub)step. */
    struct SolverContext
    {
      /** The bodies; velocities are updated in place. */
      std::vector<RigidBody> *bodies = nullptr;
      /** The contact graph with this substep's contact points and groups. */
      ContactGraph *graph = nullptr;
      /** Pair materials: index ma * n_materials + mb. */
      const std::vector<ContactMaterial> *pair_materials = nullptr;
      /** Number of materials. */
      unsigned int n_materials = 0;
      /** Applied force per body in N (coupling, buoyancy), without gravity. */
      const std::vector<Eigen::Vector3d> *forces = nullptr;
      /** Applied torque per body in N m. */
      const std::vector<Eigen::Vector3d> *torques = nullptr;
      /** Gravitational acceleration in m/s^2. */
      Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
      /** Substep length in s. */
      double h = 0.;

      /** Material of a contact edge. */
      const ContactMaterial &
      material(const ContactEdge &e) const
      {
        return (
          *pair_materials)[(*bodies)[e.manifold.a].material() * n_materials
                           + (*bodies)[e.manifold.b].material()];
      }
    };

    /**
     * Interface of the contact solvers. solve() advances the velocities of
     * all bodies over one substep: applied forces and gravity plus contact
     * impulses or forces. The World then moves the bodies
     * (NewtonEulerIntegrator::integrate_position). Each contact point's
     * `impulse` must hold the total impulse on body b over the substep.
     */
    class ContactSolver
    {
    public:
      /** @param parameters Solver tuning. */
      explicit ContactSolver(const ContactSolverParameters &parameters)
        : parameters(parameters)
      {}
      virtual ~ContactSolver() = default;

      /** Advances all velocities over ctx.h. */
      virtual void
      solve(SolverContext &ctx)
        = 0;

      /** Which model this is. */
      virtual ContactSolverType
      type() const = 0;

      /** Sweeps used by the last solve (largest over the groups). */
      unsigned int
      last_iterations() const
      {
        return last_iterations_;
      }

      /** Creates the solver of the given type. */
      static std::unique_ptr<ContactSolver>
      create(ContactSolverType type, const ContactSolverParameters &parameters);

      /** The tuning. */
      ContactSolverParameters parameters;

    protected:
      /** Applies forces and gravity to all dynamic bodies over ctx.h. */
      static void
      kick(SolverContext &ctx);

      /** Sweeps used by the last solve. */
      unsigned int last_iterations_ = 0;
    };
  } // namespace rigid
} // namespace particulate

#endif
