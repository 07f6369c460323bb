#include <particulate/rigid/vtp_writer.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace particulate {
  namespace rigid {
    VtpWriter::VtpWriter(std::string prefix)
      : series(std::move(prefix))
    {}



    std::string
    VtpWriter::write(const World &world)
    {
      const std::string name = series.next_file("vtp");
      std::ofstream     out(name);
      if (!out)
        throw std::runtime_error("rigid::VtpWriter: cannot open '" + name
                                 + "' for writing; does the folder exist?");
      std::vector<BodyId> ids;
      for (BodyId i = 0; i < std::min(world.n_bodies(), first_left_out); ++i)
        if (std::isfinite(world.body(i).bounding_radius()))
          ids.push_back(i);
      const std::size_t n = ids.size();
      out << std::setprecision(10);
      out
        << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <PolyData>\n"
        << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
        << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
        << "      <Points>\n"
        << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const BodyId i : ids)
        {
          const auto &x = world.body(i).position;
          out << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
        }
      out
        << "        </DataArray>\n      </Points>\n      <Verts>\n"
        << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
      for (std::size_t k = 0; k < n; ++k)
        out << k << '\n';
      out
        << "        </DataArray>\n"
        << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
      for (std::size_t k = 0; k < n; ++k)
        out << k + 1 << '\n';
      out << "        </DataArray>\n      </Verts>\n"
          << "      <PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
      auto scalar = [&](const char *nm, const char *type, auto f) {
        out << "        <DataArray type=\"" << type << "\" Name=\"" << nm
            << "\" format=\"ascii\">\n";
        for (const BodyId i : ids)
          out << f(world.body(i), i) << '\n';
        out << "        </DataArray>\n";
      };
      auto vector = [&](const char *nm, int nc, auto f) {
        out << "        <DataArray type=\"Float64\" Name=\"" << nm
            << "\" NumberOfComponents=\"" << nc << "\" format=\"ascii\">\n";
        for (const BodyId i : ids)
          {
            const Eigen::VectorXd v = f(world.body(i));
            for (int c = 0; c < nc; ++c)
              out << v[c] << (c + 1 < nc ? ' ' : '\n');
          }
        out << "        </DataArray>\n";
      };
      scalar("id", "Int64", [](const RigidBody &, BodyId i) { return i; });
      scalar("radius", "Float64", [](const RigidBody &b, BodyId) {
        return b.bounding_radius();
      });
      scalar("fixed", "Int32", [](const RigidBody &b, BodyId) {
        return int(b.is_fixed());
      });
      vector("velocity", 3, [](const RigidBody &b) {
        return Eigen::VectorXd(b.linear_velocity);
      });
      vector("angular_velocity", 3, [](const RigidBody &b) {
        return Eigen::VectorXd(b.angular_velocity);
      });
      vector("orientation", 4, [](const RigidBody &b) {
        return Eigen::VectorXd(Eigen::Vector4d(b.orientation.w(),
                                               b.orientation.x(),
                                               b.orientation.y(),
                                               b.orientation.z()));
      });
      out << "      </PointData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
      out.close();

      series.add(world.time(), name);
      return name;
    }
  } // namespace rigid
} // namespace particulate
