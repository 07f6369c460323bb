#ifndef particulate_fbm_solver_failure_diagnosis_h
#define particulate_fbm_solver_failure_diagnosis_h

#include <particulate/fluid/solver_failure.h>

#include <string>

namespace particulate {
  namespace fbm {
    /**
     * What a coupled step started from, measured before its flow solve:
     * the quantities that decide whether the flow solver can follow the
     * step.
     */
    struct StepConditions
    {
      /// the step's size k [s]
      double time_step = 0.;
      /// the flow's CFL number max |u| k / (h / 2) (Q2 node spacing) with
      /// the bodies' velocities imposed
      double cfl = 0.;
      /// the smallest cell size h_min [m]
      double smallest_cell = 0.;
      /// the fastest particle (-1: none moves) and its speed [m/s]
      int    fastest_particle = -1;
      double fastest_speed    = 0.;
      /// pairs of bodies (walls included) in contact, and the deepest
      /// overlap among them [m]
      unsigned int n_contacts      = 0;
      double       deepest_overlap = 0.;
      /// the rigid engine's contact distance [m]
      double contact_distance = 0.;
    };

    /**
     * The message for a flow solve that failed in a coupled step: what the
     * solver measured, the step's conditions, and the likely cause they
     * point at with what to do, checked in this order:
     * - a particle that moves more than one smallest cell per step: the
     *   fictitious boundary jumps across cells, and the flow solver
     *   cannot follow; the step that keeps it within a cell;
     * - a CFL number above 1: convection outruns the step; the step for
     *   CFL 1;
     * - bodies overlapping by more than the contact distance: the fluid
     *   in the closed gap is squeezed between two imposed velocities;
     * - bodies in contact at a contact distance below half the smallest
     *   cell: the nearly covered cells between them carry weakly
     *   determined pressures; a contact distance of half a cell or more;
     * - none of these: the solver's settings (iterations, tolerance).
     */
    std::string
    diagnose_solver_failure(const fluid::SolverFailure &failure,
                            const StepConditions       &conditions);
  } // namespace fbm
} // namespace particulate

#endif
