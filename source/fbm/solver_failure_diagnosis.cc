#include <particulate/fbm/solver_failure_diagnosis.h>

#include <sstream>

namespace particulate {
  namespace fbm {
    namespace {
      /** The fastest particle's travel in one step, in smallest cells. */
      double
      cells_per_step(const StepConditions &c)
      {
        return c.smallest_cell > 0. ?
                 c.fastest_speed * c.time_step / c.smallest_cell :
                 0.;
      }

      void
      describe(const StepConditions &c, std::ostringstream &out)
      {
        out << "\nMeasured at the start of the step (time step " << c.time_step
            << " s): CFL number " << c.cfl << "; ";
        if (c.fastest_particle >= 0)
          out << "the fastest particle, " << c.fastest_particle << ", moves "
              << c.fastest_speed << " m/s, " << cells_per_step(c)
              << " smallest cells (h = " << c.smallest_cell << " m) per step";
        else
          out << "no particle moves";
        out << "; " << c.n_contacts << " contact(s)";
        if (c.n_contacts > 0)
          out << ", deepest overlap " << c.deepest_overlap << " m";
        out << ".";
      }

      void
      name_cause(const fluid::SolverFailure &failure,
                 const StepConditions       &c,
                 std::ostringstream         &out)
      {
        out << "\nLikely cause: ";
        if (cells_per_step(c) > 1.)
          out << "particle " << c.fastest_particle << " crosses "
              << cells_per_step(c)
              << " cells in one step, so its fictitious boundary jumps over "
                 "cells the flow solver never saw it cross. A step below h / "
                 "speed = "
              << c.smallest_cell / c.fastest_speed
              << " s keeps it within a cell: reduce 'Time step' in "
                 "subsection 'Time'.";
        else if (c.cfl > 1.)
          out << "the CFL number " << c.cfl
              << " is above 1: the flow is carried over more than a node "
                 "spacing in one step. A step of "
              << c.time_step / c.cfl
              << " s gives CFL 1: reduce 'Time step' in subsection 'Time', "
                 "or set 'Adaptive time step = true' there.";
        else if (c.n_contacts > 0 && c.deepest_overlap > c.contact_distance)
          out << "bodies overlap by " << c.deepest_overlap
              << " m, more than the contact distance " << c.contact_distance
              << " m: the fluid left in the closed gap is forced by two "
                 "different imposed velocities. Raise 'Contact distance' "
                 "in subsection 'Particles' to about a cell so that the "
                 "bodies keep the fluid between them, or 'Rigid substeps' "
                 "there.";
        else if (c.n_contacts > 0 && c.contact_distance < 0.5 * c.smallest_cell)
          // doc/validation/dense-bed.md: a bed in contact at 0.15 cells
          // stalled the linear solver, at half a cell it did not
          out << "bodies are in contact (" << c.n_contacts
              << " contacts) at the contact distance " << c.contact_distance
              << " m, below half the smallest cell (" << 0.5 * c.smallest_cell
              << " m): the velocity nodes between them are covered by "
                 "different bodies, and the pressure of the nearly covered "
                 "cells there is weakly determined. Raise 'Contact distance' "
                 "in subsection 'Particles' to at least half a cell, or set "
                 "it to 'auto' (a cell).";
        else if (failure.kind == fluid::SolverFailure::Kind::linear)
          out << "nothing measured points at the step (CFL at most 1, "
                 "particles within a cell per step, no deep contact): the "
                 "linear solver needs more room. Raise 'Maximum iterations' "
                 "in subsection 'Linear solver', or choose a stronger "
                 "'Velocity preconditioner' there.";
        else
          out << "nothing measured points at the step (CFL at most 1, "
                 "particles within a cell per step, no deep contact): raise "
                 "'Maximum iterations' in subsection 'Nonlinear solver', or "
                 "check the fluid's parameters (a viscosity or density far "
                 "from the case's scale).";
      }
    } // namespace



    std::string
    diagnose_solver_failure(const fluid::SolverFailure &failure,
                            const StepConditions       &conditions)
    {
      std::ostringstream out;
      out << failure.measured;
      describe(conditions, out);
      name_cause(failure, conditions, out);
      return out.str();
    }
  } // namespace fbm
} // namespace particulate
