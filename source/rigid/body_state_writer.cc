#include <particulate/rigid/body_state_writer.h>

#include <iomanip>
#include <limits>
#include <stdexcept>

namespace particulate {
  namespace rigid {
    BodyStateWriter::BodyStateWriter(const std::string &prefix)
      : bodies_(prefix + "_bodies.dat")
      , energy_(prefix + "_energy.dat")
    {
      if (!bodies_ || !energy_)
        throw std::runtime_error(
          "rigid::BodyStateWriter: cannot open '" + prefix
          + "_bodies.dat' or '_energy.dat' for writing; does "
            "the folder exist and is it writable?");
      bodies_
        << "# time id x y z qw qx qy qz u v w omega_x omega_y omega_z fx fy fz\n"
        << "# SI units: s, m, m/s, rad/s, N (contact force averaged over the last step)\n";
      energy_
        << "# time kinetic_energy potential_energy n_contacts max_penetration\n"
        << "# SI units: s, J, J, -, m\n";
      bodies_ << std::setprecision(12);
      energy_ << std::setprecision(12);
    }



    void
    BodyStateWriter::write(const World &world)
    {
      const double t  = world.time();
      double       pe = 0.;
      for (BodyId id = 0; id < world.n_bodies(); ++id)
        {
          const RigidBody &b = world.body(id);
          if (b.is_fixed())
            continue;
          pe -= b.mass() * world.parameters().gravity.dot(b.position);
          // NaN: the world records no contact forces
          Eigen::Vector3d f = Eigen::Vector3d::Zero();
          if (world.parameters().record_contact_forces)
            for (const auto &c : world.contact_forces(id))
              f += c.force;
          else
            f.setConstant(std::numeric_limits<double>::quiet_NaN());
          const auto &q = b.orientation;
          bodies_ << t << ' ' << id << ' ' << b.position[0] << ' '
                  << b.position[1] << ' ' << b.position[2] << ' ' << q.w()
                  << ' ' << q.x() << ' ' << q.y() << ' ' << q.z() << ' '
                  << b.linear_velocity[0] << ' ' << b.linear_velocity[1] << ' '
                  << b.linear_velocity[2] << ' ' << b.angular_velocity[0] << ' '
                  << b.angular_velocity[1] << ' ' << b.angular_velocity[2]
                  << ' ' << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
        }
      energy_ << t << ' ' << world.kinetic_energy() << ' ' << pe << ' '
              << world.statistics().contacts << ' ' << world.max_penetration()
              << '\n';
      bodies_.flush();
      energy_.flush();
    }
  } // namespace rigid
} // namespace particulate
