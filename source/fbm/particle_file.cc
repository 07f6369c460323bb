#include <particulate/fbm/particle_file.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "entry_values.h"

namespace particulate {
  namespace fbm {
    namespace {
      /** The values of one line: split at commas and blanks. */
      std::vector<std::string>
      fields_of(const std::string &line)
      {
        std::string text = line;
        std::replace(text.begin(), text.end(), ',', ' ');
        std::istringstream       in(text);
        std::vector<std::string> fields;
        std::string              f;
        while (in >> f)
          fields.push_back(f);
        return fields;
      }

      /** The columns a @p dim-dimensional run knows, required ones first. */
      std::vector<std::string>
      known_columns(const unsigned int dim)
      {
        if (dim == 2)
          return {"shape", "x", "y", "vx", "vy", "omega", "angle", "motion"};
        return {"shape",
                "x",
                "y",
                "z",
                "vx",
                "vy",
                "vz",
                "omega_x",
                "omega_y",
                "omega_z",
                "angle",
                "axis_x",
                "axis_y",
                "axis_z",
                "qw",
                "qx",
                "qy",
                "qz",
                "motion"};
      }

      /** Column name -> position, checked against the known ones. */
      std::map<std::string, unsigned int>
      read_header(const std::vector<std::string> &names,
                  const unsigned int              dim,
                  const std::string              &where)
      {
        const auto                          known = known_columns(dim);
        std::map<std::string, unsigned int> column;
        for (unsigned int i = 0; i < names.size(); ++i)
          {
            if (std::find(known.begin(), known.end(), names[i]) == known.end())
              {
                std::string list;
                for (const auto &k : known)
                  list += (list.empty() ? "" : ", ") + k;
                internal::fail_at(where,
                                  "the header names an unknown column '"
                                    + names[i] + "'; a " + std::to_string(dim)
                                    + "D run knows " + list + ".");
              }
            if (!column.emplace(names[i], i).second)
              internal::fail_at(where,
                                "the header names column '" + names[i]
                                  + "' twice.");
          }
        for (const std::string required : {"shape", "x", "y", "z"})
          if ((dim == 3 || required != std::string("z"))
              && column.count(required) == 0)
            internal::fail_at(where,
                              "the header has no column '" + required
                                + "'; it needs shape, x, y"
                                + (dim == 3 ? ", z." : "."));
        const unsigned int axis = column.count("axis_x")
                                  + column.count("axis_y")
                                  + column.count("axis_z");
        if (axis && (axis != 3 || column.count("angle") == 0))
          internal::fail_at(where,
                            "an orientation by axis and angle needs all of "
                            "axis_x, axis_y, axis_z and angle.");
        const unsigned int quaternion = column.count("qw") + column.count("qx")
                                        + column.count("qy")
                                        + column.count("qz");
        if (quaternion != 0 && (quaternion != 4 || column.count("angle")))
          internal::fail_at(where,
                            "an orientation by quaternion needs all of qw, "
                            "qx, qy, qz, and no 'angle'.");
        if (dim == 3 && column.count("angle") && !axis)
          internal::fail_at(where,
                            "in 3D an 'angle' needs its axis: add columns "
                            "axis_x, axis_y, axis_z.");
        return column;
      }

      /** The particle of one data line. */
      ParticleDescription
      read_line(const std::vector<std::string>            &fields,
                const std::map<std::string, unsigned int> &column,
                const ShapeLibrary                        &shapes,
                const unsigned int                         dim,
                const std::string                         &where)
      {
        const auto value
          = [&](const std::string &name, const double otherwise) {
              const auto it = column.find(name);
              if (it == column.end())
                return otherwise;
              return internal::read_number(fields[it->second],
                                           where + ", column '" + name + "'");
            };
        const auto &shape
          = shapes.find(fields[column.at("shape")], where + ", column 'shape'");
        ParticleDescription p;
        p.shape             = shape.shape;
        p.shape_name        = shape.description.name;
        p.density           = shape.description.density;
        p.origin            = where;
        const char *axes[3] = {"x", "y", "z"};
        for (unsigned int d = 0; d < dim; ++d)
          {
            p.position[d] = value(axes[d], 0.);
            p.velocity[d] = value(std::string("v") + axes[d], 0.);
          }
        if (dim == 2)
          p.angular_velocity[2] = value("omega", 0.);
        else
          for (unsigned int d = 0; d < 3; ++d)
            p.angular_velocity[d] = value(std::string("omega_") + axes[d], 0.);
        if (column.count("qw"))
          {
            p.orientation
              = internal::unit_quaternion(Eigen::Vector4d(value("qw", 1.),
                                                          value("qx", 0.),
                                                          value("qy", 0.),
                                                          value("qz", 0.)),
                                          where);
          }
        else if (column.count("angle"))
          p.orientation
            = internal::rotation_about(Eigen::Vector3d(value("axis_x", 0.),
                                                       value("axis_y", 0.),
                                                       value("axis_z", 1.)),
                                       value("angle", 0.),
                                       where);
        p.orientation = shape.body_orientation(p.orientation);
        if (column.count("motion"))
          {
            const std::string &m = fields[column.at("motion")];
            if (m == "fixed")
              p.motion = ParticleMotion::fixed;
            else if (m != "free")
              internal::fail_at(where + ", column 'motion'",
                                "'" + m
                                  + "' is no motion of a particle file; "
                                    "write 'free' or 'fixed'.");
          }
        return p;
      }
    } // namespace



    std::vector<ParticleDescription>
    read_particle_file(const std::string  &filename,
                       const ShapeLibrary &shapes,
                       const unsigned int  dim)
    {
      std::ifstream in(filename);
      if (!in)
        throw std::runtime_error("Cannot open the particle file '" + filename
                                 + "' (entry 'Particle file' of subsection "
                                   "'Particles'; a relative path starts at "
                                   "the case file's folder).");
      std::vector<ParticleDescription>                   particles;
      std::optional<std::map<std::string, unsigned int>> column;
      std::string                                        line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          const std::string where = filename + ":" + std::to_string(number);
          const auto        first = line.find_first_not_of(" \t\r");
          if (first == std::string::npos)
            continue;
          if (!column)
            {
              // the header, with or without a leading '#'
              column = read_header(fields_of(line[first] == '#' ?
                                               line.substr(first + 1) :
                                               line),
                                   dim,
                                   where);
              continue;
            }
          if (line[first] == '#')
            continue;
          const std::vector<std::string> fields = fields_of(line);
          if (fields.size() != column->size())
            internal::fail_at(where,
                              "has " + std::to_string(fields.size())
                                + " values; the header names "
                                + std::to_string(column->size()) + " columns.");
          particles.push_back(read_line(fields, *column, shapes, dim, where));
        }
      if (particles.empty())
        throw std::runtime_error(filename
                                 + ": the particle file holds no particles "
                                   "(a header line, then one line per "
                                   "particle).");
      return particles;
    }
  } // namespace fbm
} // namespace particulate
