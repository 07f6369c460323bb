// The likely cause that a failed flow solve of a coupled step is given,
// from the step's measured conditions (fbm::diagnose_solver_failure), in
// the order the function documents: a particle crossing cells, the CFL
// number, an overlap beyond the contact distance, bodies in contact closer
// than half a cell, and otherwise the solver's settings.

#include <particulate/fbm/solver_failure_diagnosis.h>

#include <iostream>
#include <string>

#include "../fluid/test_utilities.h"

using namespace particulate;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  const fluid::SolverFailure linear(fluid::SolverFailure::Kind::linear,
                                    "FGMRES did not converge.",
                                    "advice");
  fbm::StepConditions        quiet;
  quiet.time_step        = 0.002;
  quiet.cfl              = 0.1;
  quiet.smallest_cell    = 0.002;
  quiet.fastest_particle = 3;
  quiet.fastest_speed    = 0.02;
  quiet.contact_distance = 0.002;

  const auto cause = [&](const fbm::StepConditions &c) {
    const std::string message = fbm::diagnose_solver_failure(linear, c);
    std::cout << message << "\n\n";
    return message.substr(message.find("Likely cause:"));
  };
  const auto says = [](const std::string &text, const std::string &what) {
    return text.find(what) != std::string::npos;
  };

  fbm::StepConditions fast = quiet;
  fast.fastest_speed       = 5.;
  checker.check(says(cause(fast), "crosses 5 cells"),
                "a particle crossing 5 cells per step is named");

  fbm::StepConditions convective = quiet;
  convective.cfl                 = 3.;
  checker.check(says(cause(convective), "CFL number 3"), "CFL 3 is named");

  fbm::StepConditions overlap = quiet;
  overlap.n_contacts          = 2;
  overlap.deepest_overlap     = 0.003;
  checker.check(says(cause(overlap), "overlap by 0.003 m"),
                "an overlap beyond the contact distance is named");

  fbm::StepConditions close     = quiet;
  close.n_contacts              = 50;
  close.contact_distance        = 0.0003;
  const std::string close_cause = cause(close);
  checker.check(says(close_cause, "50 contacts")
                  && says(close_cause, "below half the smallest cell (0.001 m)")
                  && says(close_cause, "Raise 'Contact distance'"),
                "contacts at 0.15 cells: raise the contact distance");

  fbm::StepConditions apart = close;
  apart.contact_distance    = 0.001;
  checker.check(says(cause(apart), "Raise 'Maximum iterations'"),
                "contacts at half a cell: the solver's settings");
  checker.check(says(cause(quiet), "Raise 'Maximum iterations'"),
                "nothing measured: the solver's settings");
  return checker.exit_code();
}
