#include <particulate/rigid/body_surface_writer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace rigid {
    namespace {
      BodySurfaceWriter::PlacedSurface
      place(const RigidBody              &body,
            const BodyId                  id,
            const geometry::TriangleMesh &mesh)
      {
        BodySurfaceWriter::PlacedSurface s{id, body.is_fixed(), {}, {}, &mesh};
        s.points.reserve(mesh.n_vertices());
        s.velocities.reserve(mesh.n_vertices());
        for (const Eigen::Vector3d &v : mesh.vertices)
          {
            const Eigen::Vector3d x = body.to_world(v);
            s.points.push_back(x);
            s.velocities.push_back(
              body.linear_velocity
              + body.angular_velocity.cross(x - body.position));
          }
        return s;
      }

      void
      write_points(
        std::ostream                                        &out,
        const char                                          *name,
        const std::vector<BodySurfaceWriter::PlacedSurface> &surfaces,
        const bool                                           velocities)
      {
        out << "        <DataArray type=\"Float64\""
            << (name ? std::string(" Name=\"") + name + "\"" : std::string())
            << " NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const auto &s : surfaces)
          for (const auto &p : velocities ? s.velocities : s.points)
            out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
        out << "        </DataArray>\n";
      }

      void
      write_polys(std::ostream                                        &out,
                  const std::vector<BodySurfaceWriter::PlacedSurface> &surfaces)
      {
        out << "      <Polys>\n"
            << "        <DataArray type=\"Int64\" Name=\"connectivity\" "
               "format=\"ascii\">\n";
        std::size_t first = 0;
        for (const auto &s : surfaces)
          {
            for (const auto &t : s.mesh->triangles)
              out << first + t[0] << ' ' << first + t[1] << ' ' << first + t[2]
                  << '\n';
            first += s.points.size();
          }
        out << "        </DataArray>\n"
            << "        <DataArray type=\"Int64\" Name=\"offsets\" "
               "format=\"ascii\">\n";
        std::size_t offset = 0;
        for (const auto &s : surfaces)
          for (std::size_t t = 0; t < s.mesh->n_triangles(); ++t)
            out << (offset += 3) << '\n';
        out << "        </DataArray>\n      </Polys>\n";
      }

      void
      write_cell_data(
        std::ostream                                        &out,
        const std::vector<BodySurfaceWriter::PlacedSurface> &surfaces)
      {
        out << "      <CellData Scalars=\"id\">\n";
        for (const bool fixed : {false, true})
          {
            out << "        <DataArray type=\"" << (fixed ? "Int32" : "Int64")
                << "\" Name=\"" << (fixed ? "fixed" : "id")
                << "\" format=\"ascii\">\n";
            for (const auto &s : surfaces)
              for (std::size_t t = 0; t < s.mesh->n_triangles(); ++t)
                out << (fixed ? std::size_t(s.fixed) : std::size_t(s.id))
                    << '\n';
            out << "        </DataArray>\n";
          }
        out << "      </CellData>\n";
      }
    } // namespace



    BodySurfaceWriter::BodySurfaceWriter(std::string  prefix,
                                         const Layout layout)
      : prefix(prefix)
      , series(std::move(prefix))
      , layout(layout)
    {}



    const geometry::TriangleMesh &
    BodySurfaceWriter::display_mesh(const RigidBody &body)
    {
      const geometry::Shape *key = &body.shape();
      auto                   it  = meshes.find(key);
      if (it == meshes.end())
        it = meshes
               .emplace(key,
                        std::make_pair(body.shape_ptr(),
                                       body.shape().surface_mesh()))
               .first;
      return it->second.second;
    }



    PvdSeries &
    BodySurfaceWriter::body_series(const BodyId id)
    {
      auto it = bodies.find(id);
      if (it != bodies.end())
        return it->second;
      const std::string folder = prefix;
      std::error_code   error;
      std::filesystem::create_directories(folder, error);
      if (error)
        throw std::runtime_error("rigid::BodySurfaceWriter: cannot create '"
                                 + folder + "': " + error.message());
      PvdSeries body(folder + "/body_" + std::to_string(id));
      // a resumed run: this body's pieces of the snapshots written so far
      std::vector<std::pair<double, std::string>> written;
      for (std::size_t k = 0; k < series.written().size(); ++k)
        written.emplace_back(series.written()[k].first, piece_name(id, k));
      body.resume(std::move(written));
      return bodies.emplace(id, std::move(body)).first->second;
    }



    std::string
    BodySurfaceWriter::piece_name(const BodyId id, const std::size_t snapshot)
    {
      char number[16];
      std::snprintf(number, sizeof number, "%05zu", snapshot);
      return "body_" + std::to_string(id) + "_" + number + ".vtp";
    }



    void
    BodySurfaceWriter::write_piece(const std::string                &name,
                                   const std::vector<PlacedSurface> &surfaces)
    {
      std::ofstream out(name);
      if (!out)
        throw std::runtime_error("rigid::BodySurfaceWriter: cannot open '"
                                 + name
                                 + "' for writing; does the folder exist?");
      std::size_t n_points = 0, n_triangles = 0;
      for (const auto &s : surfaces)
        {
          n_points += s.points.size();
          n_triangles += s.mesh->n_triangles();
        }
      out << std::setprecision(10)
          << "<?xml version=\"1.0\"?>\n"
             "<VTKFile type=\"PolyData\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n"
             "  <PolyData>\n"
          << "    <Piece NumberOfPoints=\"" << n_points
          << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
             "NumberOfPolys=\""
          << n_triangles << "\">\n      <Points>\n";
      write_points(out, nullptr, surfaces, false);
      out << "      </Points>\n";
      write_polys(out, surfaces);
      out << "      <PointData Vectors=\"velocity\">\n";
      write_points(out, "velocity", surfaces, true);
      out << "      </PointData>\n";
      write_cell_data(out, surfaces);
      out << "    </Piece>\n  </PolyData>\n</VTKFile>\n";
      out.close();
      if (!out)
        throw std::runtime_error("rigid::BodySurfaceWriter: writing '" + name
                                 + "' failed; is the disk full?");
    }



    std::string
    BodySurfaceWriter::write(const World &world)
    {
      return layout == Layout::each_body ? write_each_body(world) :
                                           write_one_file(world);
    }



    std::string
    BodySurfaceWriter::write_one_file(const World &world)
    {
      std::vector<PlacedSurface> surfaces;
      for (BodyId i = 0; i < std::min(world.n_bodies(), first_left_out); ++i)
        if (world.body(i).shape().is_bounded())
          surfaces.push_back(
            place(world.body(i), i, display_mesh(world.body(i))));
      const std::string name = series.next_file("vtp");
      write_piece(name, surfaces);
      series.add(world.time(), name);
      return name;
    }



    std::string
    BodySurfaceWriter::write_each_body(const World &world)
    {
      const std::size_t snapshot = series.written().size();
      // the pieces lie in the folder named like the series, next to it
      const std::string  folder = std::filesystem::path(prefix).filename();
      std::ostringstream blocks;
      unsigned int       block = 0;
      for (BodyId i = 0; i < std::min(world.n_bodies(), first_left_out); ++i)
        if (world.body(i).shape().is_bounded())
          {
            PvdSeries        &own   = body_series(i);
            const std::string piece = piece_name(i, snapshot);
            write_piece(prefix + "/" + piece,
                        {place(world.body(i), i, display_mesh(world.body(i)))});
            own.add(world.time(), prefix + "/" + piece);
            blocks << "    <DataSet index=\"" << block++ << "\" name=\"body "
                   << i << "\" file=\"" << folder << "/" << piece << "\"/>\n";
          }

      const std::string name = series.next_file("vtm");
      std::ofstream     out(name);
      out << "<?xml version=\"1.0\"?>\n"
             "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
             "byte_order=\"LittleEndian\">\n"
             "  <vtkMultiBlockDataSet>\n"
          << blocks.str() << "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
      out.close();
      if (!out)
        throw std::runtime_error("rigid::BodySurfaceWriter: writing '" + name
                                 + "' failed; does the folder exist, is the "
                                   "disk full?");
      series.add(world.time(), name);
      return name;
    }
  } // namespace rigid
} // namespace particulate
