// 'Coupling = iterated': the step solved again until the velocities the
// fluid was given are those the bodies reach.
// 1. CouplingIteration (IQN-ILS) on maps with a known fixed point x* of
//    G(x) = A x + b. On a linear map IQN-ILS is GMRES on (I - A) x = b: in
//    n unknowns the (n + 1)-th given x is x*, so the (n + 2)-th record
//    converges.
//    - one unknown, a contraction (a = 0.9, where the plain iteration gains
//      a tenth of the error per step) and an expansion (a = -3, where it
//      diverges): the secant, converged with the third record (1e-12);
//    - three unknowns, A symmetric with eigenvalues 0.2, 0.5, 0.8: converged
//      with the fifth record to 1e-10 (the plain iteration: 104);
//    - a set of 200 bodies (600 unknowns) whose modes are contractions
//      between 0.6 and 0.75 (the added mass C above the bodies' own) except
//      two squeezed pairs, four modes at -3 (where the plain iteration
//      diverges): converged to 1e-6 within the 20 iterations a case allows
//      by default;
//    - a step that runs out of iterations says so (exhausted()).
// 2. A light disk in a viscous liquid (prm/settling-disk at mu = 0.5 Pa s,
//    refinement 4, ten steps of 1 ms from rest): k dt is about twice the
//    disk's mass, where the explicit coupling's answer depends on the added
//    mass: with C = 0.5 its velocity flips sign from step to step, with
//    C = 20 it ends 14 % off. The check: explicit, the velocities after
//    ten steps differ between C = 0.5 and C = 20 by more than 5 %;
//    iterated (tolerance 1e-8), by less than 1e-6 relative: the motion no
//    longer depends on the added mass.
#include <particulate/fbm/coupling_iteration.h>
#include <particulate/fbm/particulate_flow_simulation.h>

#include <Eigen/Dense>

#include <cmath>
#include <filesystem>
#include <string>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  testing::Checker checker;

  /** Iterate x -> G(x) = A x + b from x = 0 until converged or exhausted;
   *  returns the iterations used and the last given x in @p x. */
  unsigned int
  iterate(const Eigen::MatrixXd &A,
          const Eigen::VectorXd &b,
          const double           tolerance,
          const unsigned int     max_iterations,
          Eigen::VectorXd       &x,
          bool                  &converged)
  {
    fbm::CouplingIteration iteration(tolerance, max_iterations);
    iteration.start_step();
    x = Eigen::VectorXd::Zero(b.size());
    for (;;)
      {
        converged = iteration.record(x, A * x + b);
        if (converged || iteration.exhausted())
          return iteration.n_iterations();
        x = iteration.next_given();
      }
  }

  void
  check_scalar(const double a)
  {
    Eigen::MatrixXd A(1, 1);
    A << a;
    const Eigen::VectorXd b      = Eigen::VectorXd::Constant(1, 0.3);
    const double          x_star = 0.3 / (1. - a);
    Eigen::VectorXd       x;
    bool                  converged = false;
    const unsigned int    n         = iterate(A, b, 1e-12, 10, x, converged);
    checker.check(converged && n == 3,
                  "one unknown, a = " + std::to_string(a)
                    + ": converged with the third iterate (used "
                    + std::to_string(n) + ")");
    checker.check_relative(x[0],
                           x_star,
                           1e-12,
                           "one unknown, a = " + std::to_string(a)
                             + ": at the fixed point");
  }

  void
  check_vector()
  {
    const Eigen::Matrix3d Q
      = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1., 2., 3.).normalized())
          .toRotationMatrix();
    const Eigen::MatrixXd A
      = Q * Eigen::Vector3d(0.2, 0.5, 0.8).asDiagonal() * Q.transpose();
    const Eigen::VectorXd b(Eigen::Vector3d(1., -2., 0.5));
    const Eigen::VectorXd x_star
      = (Eigen::Matrix3d::Identity() - A).lu().solve(b);
    Eigen::VectorXd    x;
    bool               converged = false;
    const unsigned int n         = iterate(A, b, 1e-10, 100, x, converged);
    checker.check(converged && n <= 5,
                  "three unknowns: converged with record " + std::to_string(n)
                    + " (GMRES: the fifth; the plain iteration: 104)");
    checker.check((x - x_star).norm() <= 1e-8 * x_star.norm(),
                  "three unknowns: at the fixed point (error "
                    + std::to_string((x - x_star).norm() / x_star.norm())
                    + ")");
    const unsigned int used = iterate(A, b, 1e-10, 2, x, converged);
    checker.check(!converged && used == 2,
                  "three unknowns: two iterations are not enough, and the "
                  "iteration stops there");
  }

  /** 600 unknowns: contractions between 0.6 and 0.75, four modes at -3. */
  void
  check_many_bodies()
  {
    const int       n = 600;
    Eigen::VectorXd eigenvalues(n);
    for (int i = 0; i < n; ++i)
      eigenvalues[i] = 0.6 + 0.15 * i / (n - 1.);
    eigenvalues.head(4).setConstant(-3.);
    // an orthogonal basis that mixes all unknowns
    const Eigen::MatrixXd Q
      = Eigen::MatrixXd::Random(n, n).householderQr().householderQ();
    const Eigen::MatrixXd A = Q * eigenvalues.asDiagonal() * Q.transpose();
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1., 1.);
    const Eigen::VectorXd x_star
      = (Eigen::MatrixXd::Identity(n, n) - A).lu().solve(b);
    Eigen::VectorXd    x;
    bool               converged = false;
    const unsigned int used      = iterate(A, b, 1e-6, 20, x, converged);
    checker.check(converged,
                  "600 unknowns, four expanding modes: converged with record "
                    + std::to_string(used) + " of 20");
    checker.check((x - x_star).norm() <= 1e-5 * x_star.norm(),
                  "600 unknowns: at the fixed point (error "
                    + std::to_string((x - x_star).norm() / x_star.norm())
                    + ")");
  }

  /** The disk's velocity at the end of the run. */
  double
  disk_velocity(const std::string &coupling, const double C)
  {
    const std::string name
      = "iterated_coupling_" + coupling + "_" + std::to_string(C);
    auto parameters = fbm::read_particulate_flow_case(
      testing::source_path("prm/settling-disk/settling-disk.prm"),
      "subsection Mesh\n set Refinements = 4\nend\n"
      "subsection Time\n set End time = 0.01\nend\n"
      "subsection Fluid\n set Dynamic viscosity = 0.5\nend\n"
      "subsection Particles\n set Added mass coefficient = "
        + std::to_string(C) + "\n set Coupling = " + coupling
        + "\n set Coupling tolerance = 1e-8\nend\n");
    parameters.flow.output.directory = name;
    parameters.flow.output.write_vtu = false;
    std::filesystem::create_directories(name);
    fbm::ParticulateFlowSimulation<2> simulation(parameters,
                                                 name,
                                                 MPI_COMM_WORLD);
    const auto                        summary = simulation.run();
    return summary.velocity[0][1];
  }

  void
  check_runs()
  {
    const double explicit_light = disk_velocity("explicit", 0.5);
    const double explicit_heavy = disk_velocity("explicit", 20.);
    const double iterated_light = disk_velocity("iterated", 0.5);
    const double iterated_heavy = disk_velocity("iterated", 20.);
    const double explicit_spread
      = std::abs(explicit_light - explicit_heavy) / std::abs(iterated_light);
    checker.check(explicit_spread > 0.05,
                  "explicit: C = 0.5 and C = 20 differ by "
                    + std::to_string(explicit_spread) + " of the velocity");
    checker.check_relative(iterated_heavy,
                           iterated_light,
                           1e-6,
                           "iterated: C = 20 against C = 0.5");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_scalar(0.9);
  check_scalar(-3.);
  check_vector();
  check_many_bodies();
  check_runs();
  return checker.exit_code();
}
