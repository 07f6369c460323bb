#include <particulate/core/checkpoint.h>
#include <particulate/fbm/body_coupling_state.h>

#include <stdexcept>
#include <string>

namespace particulate {
  namespace fbm {
    void
    BodyCouplingState::record_speed(const double speed, const double t)
    {
      if (speed > max_speed)
        {
          max_speed         = speed;
          time_of_max_speed = t;
        }
    }



    void
    BodyCouplingState::save(std::ostream &out) const
    {
      core::write_binary(out, acceleration);
      core::write_binary(out, angular_acceleration);
      core::write_binary(out, fluid_load.force);
      core::write_binary(out, fluid_load.torque);
      core::write_binary(out, max_speed);
      core::write_binary(out, time_of_max_speed);
      core::write_binary(out, solved_velocity);
      core::write_binary(out, solved_angular);
    }



    void
    BodyCouplingState::load(std::istream &in)
    {
      acceleration         = core::read_binary<Eigen::Vector3d>(in);
      angular_acceleration = core::read_binary<Eigen::Vector3d>(in);
      fluid_load.force     = core::read_binary<Eigen::Vector3d>(in);
      fluid_load.torque    = core::read_binary<Eigen::Vector3d>(in);
      max_speed            = core::read_binary<double>(in);
      time_of_max_speed    = core::read_binary<double>(in);
      solved_velocity      = core::read_binary<Eigen::Vector3d>(in);
      solved_angular       = core::read_binary<Eigen::Vector3d>(in);
    }



    void
    save_coupling_states(std::ostream                         &out,
                         const std::vector<BodyCouplingState> &states)
    {
      core::write_binary<unsigned long>(out, states.size());
      for (const auto &s : states)
        s.save(out);
    }



    void
    load_coupling_states(std::istream                   &in,
                         std::vector<BodyCouplingState> &states)
    {
      const auto n = core::read_binary<unsigned long>(in);
      if (n != states.size())
        throw std::runtime_error("it holds " + std::to_string(n)
                                 + " particles, the case file "
                                 + std::to_string(states.size()));
      for (auto &s : states)
        s.load(in);
    }
  } // namespace fbm
} // namespace particulate
