#ifndef particulate_fbm_entry_values_h
#define particulate_fbm_entry_values_h

// Reading the values of particle entries: lists of numbers with a fixed
// count, whose errors name where the value was written.

#include <deal.II/base/utilities.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace particulate {
  namespace fbm {
    namespace internal {
      [[noreturn]] inline void
      fail_at(const std::string &where, const std::string &what)
      {
        throw std::runtime_error(where + ": " + what);
      }

      /** One finite number. */
      inline double
      read_number(const std::string &text, const std::string &where)
      {
        const std::string value = dealii::Utilities::trim(text);
        try
          {
            std::size_t  used = 0;
            const double x    = std::stod(value, &used);
            if (used == value.size() && std::isfinite(x))
              return x;
          }
        catch (const std::exception &)
          {}
        fail_at(where, "'" + value + "' is not a number.");
      }

      /** Exactly @p n comma-separated numbers (an empty text: none). */
      inline std::vector<double>
      read_numbers(const std::string &text,
                   const unsigned int n,
                   const std::string &where)
      {
        const auto items = dealii::Utilities::split_string_list(text, ',');
        if (items.size() != n)
          fail_at(where,
                  "'" + text + "' has " + std::to_string(items.size())
                    + " value(s); write " + std::to_string(n)
                    + ", separated by ','.");
        std::vector<double> x;
        for (const std::string &item : items)
          x.push_back(read_number(item, where));
        return x;
      }

      /** @p n comma-separated numbers as the first n components of a
       *  vector (the others 0). */
      inline Eigen::Vector3d
      read_vector(const std::string &text,
                  const unsigned int n,
                  const std::string &where)
      {
        const std::vector<double> x = read_numbers(text, n, where);
        Eigen::Vector3d           v = Eigen::Vector3d::Zero();
        for (unsigned int d = 0; d < n; ++d)
          v[d] = x[d];
        return v;
      }

      /** An angular velocity: 3 components in 3D, the one about z in 2D. */
      inline Eigen::Vector3d
      read_angular_velocity(const std::string &text,
                            const unsigned int dim,
                            const std::string &where)
      {
        if (dim == 3)
          return read_vector(text, 3, where);
        return Eigen::Vector3d(0., 0., read_numbers(text, 1, where)[0]);
      }

      /** The rotation by @p angle [rad] about @p axis (normalised). */
      inline Eigen::Quaterniond
      rotation_about(const Eigen::Vector3d &axis,
                     const double           angle,
                     const std::string     &where)
      {
        // scaled by its largest component first: the norm of an axis such
        // as (1e200, 0, 0) overflows
        const double largest = axis.cwiseAbs().maxCoeff();
        if (!(largest > 0.))
          fail_at(where, "the rotation axis must not be zero.");
        if (angle == 0.)
          return Eigen::Quaterniond::Identity();
        return Eigen::Quaterniond(
          Eigen::AngleAxisd(angle, (axis / largest).normalized()));
      }

      /** The rotation of quaternion (w, x, y, z), normalised without
       *  overflow; a zero quaternion is refused. */
      inline Eigen::Quaterniond
      unit_quaternion(const Eigen::Vector4d &wxyz, const std::string &where)
      {
        const double largest = wxyz.cwiseAbs().maxCoeff();
        if (!(largest > 0.))
          fail_at(where, "a rotation quaternion must not be zero.");
        const Eigen::Vector4d q = (wxyz / largest).normalized();
        return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
      }

      /** A quaternion w, x, y, z, normalised (it must not be zero). */
      inline Eigen::Quaterniond
      read_quaternion(const std::string &text, const std::string &where)
      {
        const std::vector<double> q = read_numbers(text, 4, where);
        return unit_quaternion(Eigen::Vector4d(q[0], q[1], q[2], q[3]), where);
      }
    } // namespace internal
  }   // namespace fbm
} // namespace particulate

#endif
