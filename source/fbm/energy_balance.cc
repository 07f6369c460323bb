#include <particulate/fbm/energy_balance.h>

#include <cmath>
#include <sstream>

namespace particulate {
  namespace fbm {
    EnergyBalance::EnergyBalance(const std::vector<rigid::BodyId> &free_ids)
      : ids(free_ids)
      , start_position(free_ids.size())
      , start_orientation(free_ids.size())
      , force(free_ids.size())
      , torque(free_ids.size())
    {}



    double
    EnergyBalance::kinetic_energy(const rigid::RigidBody &body)
    {
      const Eigen::Vector3d &v     = body.linear_velocity;
      const Eigen::Vector3d &omega = body.angular_velocity;
      return 0.5 * body.mass() * v.squaredNorm()
             + 0.5 * omega.dot(body.inertia_world() * omega);
    }



    void
    EnergyBalance::start_step(const rigid::World &world)
    {
      start_energy = 0.;
      for (unsigned int i = 0; i < ids.size(); ++i)
        {
          const rigid::RigidBody &body = world.body(ids[i]);
          start_position[i]            = body.position;
          start_orientation[i]         = body.orientation;
          force[i]                     = body.force;
          torque[i]                    = body.torque;
          start_energy += kinetic_energy(body);
        }
      if (initial_energy < 0.)
        initial_energy = start_energy;
    }



    void
    EnergyBalance::end_step(const rigid::World &world)
    {
      double energy = 0., work = 0.;
      for (unsigned int i = 0; i < ids.size(); ++i)
        {
          const rigid::RigidBody &body = world.body(ids[i]);
          const Eigen::AngleAxisd turn(body.orientation
                                       * start_orientation[i].conjugate());
          const Eigen::Vector3d   dphi = turn.angle() * turn.axis();
          const double w = force[i].dot(body.position - start_position[i])
                           + torque[i].dot(dphi);
          work += w;
          work_handled += std::abs(w);
          energy += kinetic_energy(body);
        }
      gain += energy - start_energy - work;
    }



    double
    EnergyBalance::energy_handled() const
    {
      return std::max(initial_energy, 0.) + work_handled;
    }



    std::string
    EnergyBalance::warning(const double t)
    {
      if (warned || !(gain > gain_fraction * energy_handled()))
        return "";
      warned = true;
      std::ostringstream message;
      message << "Warning: at t = " << t << " s the particles have gained "
              << gain
              << " J of kinetic energy that no load paid for since the run "
                 "started, ";
      if (energy_handled() > 0.)
        message << 100. * gain / energy_handled()
                << " % of the energy they held and exchanged with the fluid "
                   "and gravity ("
                << energy_handled() << " J).";
      else
        message << "while they were at rest and no load did work on them.";
      message << " Contacts should only dissipate energy: a DEM spring too "
                 "stiff for the rigid substep, or bodies pushed apart from "
                 "deep overlaps, create it. Raise 'Rigid substeps' in "
                 "subsection 'Particles' or reduce 'Time step' in subsection "
                 "'Time'. The run goes on.";
      return message.str();
    }
  } // namespace fbm
} // namespace particulate
