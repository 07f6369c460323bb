// The fluid-inertia loads of 'Force integral = stress and inertia'
// (fbm::fluid_inertia_loads) against closed forms, for a disk in the DFG 2D
// channel whose velocity field is set by hand (no solve):
//  1. uniform fluid acceleration A = (u - u_start)/k, body at rest:
//     F = -rho A int(alpha), T = -rho int(x - X) alpha x A, with the
//     integrals of alpha, the Q2 interpolant of the body's node indicator,
//     computed here independently (nodal interpolation of the signed
//     distance test, then quadrature over every cell);
//  2. the same with the body accelerating with the fluid: F = T = 0;
//  3. fluid rotating rigidly with the body, steady: the convective
//     acceleration (u . grad) u = -omega^2 r is the centripetal one of the
//     body, F = T = 0 (a linear field is exact in Q2, so to round-off);
//  4. the loads are linear in A: halving the time step doubles them.
// On 2 ranks: the loads and the reference integrals are sums over ranks.

#include <particulate/fbm/fictitious_boundary.h>
#include <particulate/fbm/hydrodynamic_forces.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/rigid/world.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  /** (1, 0) at points that the body covers (signed distance <= 0, the
   *  rule of FictitiousBoundary::Marking::inside), else (0, 0). */
  class NodeIndicator : public dealii::Function<2>
  {
  public:
    explicit NodeIndicator(const rigid::RigidBody &body)
      : dealii::Function<2>(2)
      , body(body)
    {}
    double
    value(const dealii::Point<2> &p,
          const unsigned int      component) const override
    {
      return component == 0
             && body.signed_distance(Eigen::Vector3d(p[0], p[1], 0.)) <= 0.;
    }

  private:
    const rigid::RigidBody &body;
  };

  /** int alpha and int (x - X) alpha over the whole domain (all ranks). */
  struct AlphaMoments
  {
    double          integral = 0.;
    Eigen::Vector3d first    = Eigen::Vector3d::Zero();
  };

  AlphaMoments
  alpha_moments(const fluid::NavierStokes<2>              &flow,
                const fluid::NavierStokes<2>::BlockVector &alpha,
                const Eigen::Vector3d                     &centre)
  {
    const dealii::QGauss<2>             quadrature(3);
    dealii::FEValues<2>                 fe_values(flow.get_mapping(),
                                  flow.get_fe(),
                                  quadrature,
                                  dealii::update_values
                                    | dealii::update_quadrature_points
                                    | dealii::update_JxW_values);
    std::vector<dealii::Vector<double>> values(quadrature.size(),
                                               dealii::Vector<double>(3));
    AlphaMoments                        m;
    for (const auto &cell : flow.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values.get_function_values(alpha, values);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double w = values[q][0] * fe_values.JxW(q);
              const auto  &x = fe_values.quadrature_point(q);
              m.integral += w;
              m.first
                += w * Eigen::Vector3d(x[0] - centre[0], x[1] - centre[1], 0.);
            }
        }
    m.integral = dealii::Utilities::MPI::sum(m.integral, MPI_COMM_WORLD);
    for (unsigned int d = 0; d < 3; ++d)
      m.first[d] = dealii::Utilities::MPI::sum(m.first[d], MPI_COMM_WORLD);
    return m;
  }

  /** |a - b| <= tolerance * scale, componentwise over force and torque. */
  void
  check_load(testing::Checker            &checker,
             const fbm::HydrodynamicLoad &load,
             const Eigen::Vector3d       &force,
             const Eigen::Vector3d       &torque,
             const double                 force_scale,
             const double                 torque_scale,
             const std::string           &what)
  {
    const double force_error  = (load.force - force).norm() / force_scale,
                 torque_error = (load.torque - torque).norm() / torque_scale;
    char numbers[240];
    std::snprintf(numbers,
                  sizeof(numbers),
                  ": F = (%.6g, %.6g), expected (%.6g, %.6g); T_z = %.6g, "
                  "expected %.6g; relative errors %.1e, %.1e",
                  load.force[0],
                  load.force[1],
                  force[0],
                  force[1],
                  load.torque[2],
                  torque[2],
                  force_error,
                  torque_error);
    checker.check(force_error < 1e-10 && torque_error < 1e-10, what + numbers);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;

  // the initial condition carries the field under test: uniform
  // (U_x, U_y), then a rigid rotation about the disk's centre
  const double          U_x = 0.3, U_y = -0.2, omega = 2.5;
  const Eigen::Vector3d centre(1.1037, 0.2113, 0.);
  const std::string     uniform = "subsection Initial condition\n"
                                  "  set Velocity = 0.3; -0.2\n"
                                  "end\n";
  char                  rotating[240];
  std::snprintf(rotating,
                sizeof(rotating),
                "subsection Initial condition\n"
                "  set Velocity = -%g * (y - %g); %g * (x - %g)\n"
                "end\n",
                omega,
                centre[1],
                omega,
                centre[0]);

  for (const bool rotation : {false, true})
    {
      testing::CaseFlow<2> channel(
        testing::library_case("dfg-2d-2", rotation ? rotating : uniform));
      fluid::NavierStokes<2> &flow = channel.flow;
      flow.set_initial_condition(0.);
      const double rho = flow.get_parameters().properties.density;

      // a disk away from the walls and the channel's cylinder, off the grid
      rigid::World world;
      const double radius = 0.061;
      const auto   id
        = world.add_body(std::make_shared<geometry::Cylinder>(radius, 0.5),
                         world.add_material({}),
                         centre,
                         Eigen::Quaterniond::Identity(),
                         true);
      const std::vector<fbm::FictitiousBoundary<2>::Body> bodies
        = {{&world.body(id)}};
      fbm::FictitiousBoundary<2> interface(flow);
      interface.setup();
      interface.classify(bodies);
      const unsigned long covered = interface.n_nodes_inside(1)[0];

      auto alpha_owned = flow.make_owned_vector();
      flow.interpolate_velocity(NodeIndicator(world.body(id)), alpha_owned);
      auto alpha           = flow.make_ghosted_vector();
      alpha                = alpha_owned;
      const AlphaMoments m = alpha_moments(flow, alpha, centre);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << covered << " covered nodes; int alpha = " << m.integral
                  << " m^2 (disk area " << M_PI * radius * radius << ")"
                  << std::endl;
      checker.check(covered > 20, "the disk covers more than 20 nodes");

      const double                      k = 0.01;
      std::vector<fbm::RigidStepMotion> motion(1);
      motion[0].centre = centre;
      if (!rotation)
        {
          // the fluid went from rest to (U_x, U_y) in one step
          const auto            at_rest = flow.make_ghosted_vector();
          const Eigen::Vector3d A(U_x / k, U_y / k, 0.);
          const Eigen::Vector3d force  = -rho * m.integral * A,
                                torque = -rho * m.first.cross(A);
          const double force_scale     = rho * A.norm() * m.integral,
                       torque_scale    = force_scale * radius;

          check_load(
            checker,
            fbm::fluid_inertia_loads(flow, interface, at_rest, k, motion)[0],
            force,
            torque,
            force_scale,
            torque_scale,
            "uniform acceleration, body at rest");
          check_load(checker,
                     fbm::fluid_inertia_loads(flow,
                                              interface,
                                              at_rest,
                                              k / 2.,
                                              motion)[0],
                     2. * force,
                     2. * torque,
                     force_scale,
                     torque_scale,
                     "half the time step, twice the load");

          motion[0].acceleration = A;
          check_load(
            checker,
            fbm::fluid_inertia_loads(flow, interface, at_rest, k, motion)[0],
            Eigen::Vector3d::Zero(),
            Eigen::Vector3d::Zero(),
            force_scale,
            torque_scale,
            "body accelerating with the fluid");
        }
      else
        {
          // steady rigid rotation: the field at the start of the step is
          // the same; the body rotates with it
          const auto &steady         = flow.get_solution();
          motion[0].angular_velocity = Eigen::Vector3d(0., 0., omega);
          const double force_scale  = rho * omega * omega * radius * m.integral,
                       torque_scale = force_scale * radius;
          check_load(
            checker,
            fbm::fluid_inertia_loads(flow, interface, steady, k, motion)[0],
            Eigen::Vector3d::Zero(),
            Eigen::Vector3d::Zero(),
            force_scale,
            torque_scale,
            "fluid rotating rigidly with the body");
        }
    }
  return checker.exit_code();
}
