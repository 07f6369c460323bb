#include <particulate/core/input_file.h>
#include <particulate/core/mesh.h>
#include <particulate/core/parameter_text.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <stdexcept>

namespace particulate {
  namespace core {
    using namespace dealii;

    void
    MeshParameters::declare(ParameterHandler &prm)
    {
      const MeshParameters defaults;
      prm.enter_subsection("Mesh");
      prm.declare_entry(
        "Type",
        "hyper rectangle",
        Patterns::Selection(
          "hyper rectangle|graded rectangle|ball|column|channel with cylinder|file"),
        "Where the coarse mesh comes from. 'hyper rectangle': a box with "
        "boundary ids 0..2*dim-1 (x-min, x-max, y-min, y-max, z-min, z-max). "
        "'ball': the ball inscribed in the box of 'Lower corner' and 'Upper "
        "corner' (centred in it, radius half its shortest side; deal.II's "
        "hyper_ball, 5 cells in 2D, 7 in 3D) with a curved boundary of id 0 "
        "(e.g. a container around a particle). 'column' (3D): the circular "
        "cylinder along z inscribed in that box (axis through the centre of "
        "its x-y rectangle, radius half the rectangle's shorter side, from "
        "the box's lower to its upper z; a fluidized-bed column), its cross "
        "section deal.II's five-cell disk and 'Subdivisions' z-value cells "
        "along the axis, with boundary ids 0 mantle, 1 bottom (lower z), "
        "2 top. "
        "'channel with cylinder': the DFG benchmark channel (height 0.41 m, "
        "in 3D 'Channel depth' deep; cylinder diameter 0.1 m, axis along z at "
        "y = 0.2 m) with "
        "boundary ids 0 inflow, 1 outflow, 2 cylinder, 3 walls. 'file': read "
        "'File name'.");
      prm.declare_entry("File name",
                        "",
                        Patterns::Anything(),
                        "Coarse mesh file: Gmsh (.msh), UCD (.ucd) or Abaqus "
                        "(.inp). A relative path is taken from the folder of "
                        "the .prm file.");
      prm.declare_entry("Refinements",
                        std::to_string(defaults.refinements),
                        Patterns::Integer(0, 12),
                        "Number of global refinements of the coarse mesh.");
      prm.declare_entry("Lower corner",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Hyper rectangle: lower corner [m] (the first dim "
                        "values are used).");
      prm.declare_entry("Upper corner",
                        "1, 1, 1",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Hyper rectangle: upper corner [m].");
      prm.declare_entry("Subdivisions",
                        "1, 1, 1",
                        Patterns::List(Patterns::Integer(1), 2, 3),
                        "Hyper rectangle: coarse cells per direction.");
      prm.declare_entry("Fine region lower corner",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Graded rectangle: lower corner of the region of fine "
                        "cells [m] (e.g. around the path of a particle).");
      prm.declare_entry("Fine region upper corner",
                        "1, 1, 1",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Graded rectangle: upper corner of the fine region "
                        "[m].");
      prm.declare_entry("Fine cell size",
                        number_text(defaults.fine_cell_size),
                        Patterns::Double(0.),
                        "Graded rectangle: edge length of the coarse cells "
                        "inside the fine region [m] (before 'Refinements').");
      prm.declare_entry("Grading ratio",
                        number_text(defaults.grading_ratio),
                        Patterns::Double(1.),
                        "Graded rectangle: size ratio of neighbouring cells "
                        "outside the fine region (1: uniform cells of the "
                        "fine size everywhere).");
      prm.declare_entry("Cylinder shell width",
                        number_text(defaults.cylinder_shell_width),
                        Patterns::Double(0.),
                        "Channel with cylinder: width of the layer of "
                        "concentric shells around the cylinder [m].");
      prm.declare_entry("Cylinder shells",
                        std::to_string(defaults.cylinder_shells),
                        Patterns::Integer(1),
                        "Channel with cylinder: number of shells.");
      prm.declare_entry("Cylinder center x",
                        number_text(defaults.cylinder_center_x),
                        Patterns::Double(0.12),
                        "Channel with cylinder: x of the cylinder axis [m] "
                        "(0.2 for DFG 2D, 0.5 for DFG 3D-1Z). The mesh is "
                        "stretched upstream of the cylinder to place it.");
      prm.declare_entry("Channel length",
                        number_text(defaults.channel_length),
                        Patterns::Double(0.5),
                        "Channel with cylinder: length of the channel [m] "
                        "(2.2 for DFG 2D, 2.5 for DFG 3D-1Z).");
      prm.declare_entry("Channel depth",
                        number_text(defaults.channel_depth),
                        Patterns::Double(0.),
                        "Channel with cylinder, 3D: extent of the channel "
                        "along the cylinder's axis z [m] (0.41 for DFG 3D; "
                        "0.1025 for the oscillating-cylinder slab). The "
                        "mesh is scaled along z, keeping its cell layers.");
      prm.leave_subsection();
    }



    void
    MeshParameters::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      const std::string t = prm.get("Type");
      type                = t == "file"                  ? Type::file :
                            t == "channel with cylinder" ? Type::channel_with_cylinder :
                            t == "graded rectangle" ? Type::graded_rectangle :
                            t == "ball"             ? Type::ball :
                            t == "column"           ? Type::column :
                                                      Type::hyper_rectangle;
      file_name           = prm.get("File name");
      refinements         = prm.get_integer("Refinements");
      const auto doubles  = [&](const std::string &name) {
        std::vector<double> v;
        for (const auto &s : Utilities::split_string_list(prm.get(name)))
          v.push_back(Utilities::string_to_double(s));
        return v;
      };
      lower_corner   = doubles("Lower corner");
      upper_corner   = doubles("Upper corner");
      fine_lower     = doubles("Fine region lower corner");
      fine_upper     = doubles("Fine region upper corner");
      fine_cell_size = core::get_positive_double(prm, "Fine cell size", "Mesh");
      grading_ratio  = prm.get_double("Grading ratio");
      subdivisions.clear();
      for (const auto &s :
           Utilities::split_string_list(prm.get("Subdivisions")))
        subdivisions.push_back(Utilities::string_to_int(s));
      cylinder_shell_width
        = core::get_positive_double(prm, "Cylinder shell width", "Mesh");
      cylinder_shells   = prm.get_integer("Cylinder shells");
      cylinder_center_x = prm.get_double("Cylinder center x");
      channel_length    = prm.get_double("Channel length");
      channel_depth = core::get_positive_double(prm, "Channel depth", "Mesh");
      prm.leave_subsection();
    }



    namespace {
      template <int dim>
      Point<dim>
      corner(const std::vector<double> &values, const std::string &entry)
      {
        if (values.size() < dim)
          throw std::runtime_error("Mesh: the entry '" + entry + "' needs "
                                   + std::to_string(dim) + " values in "
                                   + std::to_string(dim) + "D.");
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = values[d];
        return p;
      }

      /**
       * The column of @p p: deal.II's subdivided cylinder, which lies
       * along x about the origin, turned (x to z, y to x, z to y) and moved
       * into the box of 'Lower corner' and 'Upper corner'; the mantle keeps
       * its cylindrical manifold (about the new axis), the cells get a
       * transfinite interpolation so that refined interior vertices follow
       * the curved mantle.
       */
      void
      make_column(const MeshParameters &p, Triangulation<3> &tria)
      {
        const Point<3> lower = corner<3>(p.lower_corner, "Lower corner");
        const Point<3> upper = corner<3>(p.upper_corner, "Upper corner");
        const double   radius
          = 0.5 * std::min(upper[0] - lower[0], upper[1] - lower[1]);
        const double half_length = 0.5 * (upper[2] - lower[2]);
        if (!(radius > 0.) || !(half_length > 0.))
          throw std::runtime_error(
            "subsection 'Mesh': a 'column' lies inside the box of 'Lower "
            "corner' and 'Upper corner'; every coordinate of 'Upper corner' "
            "must exceed that of 'Lower corner'.");
        const unsigned int axial
          = p.subdivisions.size() > 2 ? p.subdivisions[2] : 1;
        GridGenerator::subdivided_cylinder(tria, axial, radius, half_length);
        const Point<3> centre = 0.5 * (lower + upper);
        GridTools::transform(
          [&](const Point<3> &q) {
            return Point<3>(centre[0] + q[1],
                            centre[1] + q[2],
                            centre[2] + q[0]);
          },
          tria);
        tria.reset_all_manifolds();
        tria.set_all_manifold_ids(1);
        tria.set_all_manifold_ids_on_boundary(0, 0);
        tria.set_manifold(0,
                          CylindricalManifold<3>(Tensor<1, 3>({0., 0., 1.}),
                                                 centre));
        TransfiniteInterpolationManifold<3> cells;
        cells.initialize(tria);
        tria.set_manifold(1, cells);
      }



      /**
       * The curved manifolds of a channel with cylinder after its vertices
       * moved: the cylinder's axis at x = @p center_x, y = 0.2, and the
       * transfinite blend around it rebuilt from the moved coarse cells.
       */
      template <int dim>
      void
      attach_channel_manifolds(Triangulation<dim> &tria, const double center_x)
      {
        tria.set_manifold(0, *cylinder_axis_manifold<dim>(center_x, 0.2));
        TransfiniteInterpolationManifold<dim> transfinite;
        transfinite.initialize(tria);
        tria.set_manifold(1, transfinite);
      }



      /**
       * deal.II's channel_with_cylinder has its axis at x = 0.2 and length
       * 2.2. Move the axis to @p center_x and set the length by a piecewise
       * linear map of x that is a pure shift around the cylinder (so the
       * shells stay circular) and a stretch upstream and downstream of it.
       */
      template <int dim>
      void
      place_cylinder(Triangulation<dim> &tria,
                     const double        center_x,
                     const double        length)
      {
        const double shift = center_x - 0.2;
        const double a = 0.1, b = 0.3, old_length = 2.2;
        if (length - (b + shift) < 0.1)
          throw std::runtime_error(
            "Mesh: 'Channel length' must exceed 'Cylinder center x' + 0.2 m.");
        GridTools::transform(
          [&](const Point<dim> &p) {
            Point<dim> q = p;
            if (p[0] <= a)
              q[0] = p[0] * (a + shift) / a;
            else if (p[0] <= b)
              q[0] = p[0] + shift;
            else
              q[0] = b + shift
                     + (p[0] - b) * (length - b - shift) / (old_length - b);
            return q;
          },
          tria);

        attach_channel_manifolds(tria, center_x);
      }



      /// depth of deal.II's 3D channel with cylinder [m]
      constexpr double generated_channel_depth = 0.41;

      /**
       * Scale a 3D channel with cylinder along the cylinder's axis z to the
       * depth @p depth, keeping its layers.
       */
      template <int dim>
      void
      set_channel_depth(Triangulation<dim> &tria,
                        const double        center_x,
                        const double        depth)
      {
        GridTools::transform(
          [&](const Point<dim> &p) {
            Point<dim> q = p;
            q[dim - 1] *= depth / generated_channel_depth;
            return q;
          },
          tria);
        attach_channel_manifolds(tria, center_x);
      }

      template <int dim>
      void
      read_mesh_file(const MeshParameters &p, Triangulation<dim> &tria)
      {
        if (p.file_name.empty())
          throw std::runtime_error(
            "Mesh: 'Type = file' needs 'File name' in subsection 'Mesh'.");
        std::filesystem::path path(p.file_name);
        if (path.is_relative())
          path = std::filesystem::path(p.base_directory) / path;
        if (!std::filesystem::exists(path))
          throw std::runtime_error(
            "Mesh: cannot find the mesh file '" + path.string()
            + "' (entry 'File name' in subsection 'Mesh'; relative paths are "
              "taken from the folder of the .prm file).");
        GridIn<dim>       grid_in(tria);
        const std::string extension = path.extension().string();
        try
          {
            std::ifstream in(path);
            if (extension == ".msh")
              grid_in.read_msh(in);
            else if (extension == ".ucd")
              grid_in.read_ucd(in);
            else if (extension == ".inp")
              grid_in.read_abaqus(in);
            else
              throw std::runtime_error(
                "Mesh: unknown mesh format '" + extension + "' of '"
                + path.string()
                + "'. Use Gmsh (.msh), UCD (.ucd) or Abaqus (.inp).");
          }
        catch (const ExceptionBase &e)
          {
            std::ostringstream info;
            e.print_info(info);
            throw std::runtime_error("Mesh: cannot read '" + path.string()
                                     + "': " + info.str());
          }
      }
    } // namespace



    std::vector<double>
    graded_cell_sizes(const double lower,
                      const double upper,
                      const double fine_lower,
                      const double fine_upper,
                      const double h,
                      const double ratio)
    {
      const double a = std::clamp(fine_lower, lower, upper);
      const double b = std::clamp(fine_upper, a, upper);
      // cells growing from size h away from the fine region over a length
      // L; the sequence is scaled to fill L exactly
      const auto growing = [&](const double length) {
        std::vector<double> cells;
        if (length <= 1e-12 * (upper - lower))
          return cells;
        double size = h, sum = 0.;
        while (true)
          {
            size *= ratio;
            if (sum + size > length)
              break;
            cells.push_back(size);
            sum += size;
          }
        if (cells.empty())
          return std::vector<double>{length};
        for (double &c : cells) // stretch (by less than one cell) to fit
          c *= length / sum;
        return cells;
      };
      std::vector<double> sizes;
      const auto          before = growing(a - lower);
      sizes.insert(sizes.end(), before.rbegin(), before.rend());
      if (b - a > 0.)
        {
          const unsigned int n
            = std::max(1, static_cast<int>(std::round((b - a) / h)));
          sizes.insert(sizes.end(), n, (b - a) / n);
        }
      const auto after = growing(upper - b);
      sizes.insert(sizes.end(), after.begin(), after.end());
      return sizes;
    }



    template <int dim>
    void
    create_serial_mesh(const MeshParameters &p, Triangulation<dim> &serial)
    {
      switch (p.type)
        {
          case MeshParameters::Type::hyper_rectangle:
            {
              std::vector<unsigned int> repetitions(dim);
              for (unsigned int d = 0; d < dim; ++d)
                repetitions[d]
                  = d < p.subdivisions.size() ? p.subdivisions[d] : 1;
              GridGenerator::subdivided_hyper_rectangle(
                serial,
                repetitions,
                corner<dim>(p.lower_corner, "Lower corner"),
                corner<dim>(p.upper_corner, "Upper corner"),
                /*colorize=*/true);
              break;
            }
          case MeshParameters::Type::ball:
            {
              const Point<dim> lower
                = corner<dim>(p.lower_corner, "Lower corner");
              const Point<dim> upper
                = corner<dim>(p.upper_corner, "Upper corner");
              double radius = std::numeric_limits<double>::max();
              for (unsigned int d = 0; d < dim; ++d)
                radius = std::min(radius, 0.5 * (upper[d] - lower[d]));
              if (!(radius > 0.))
                throw std::runtime_error(
                  "subsection 'Mesh': a 'ball' lies inside the box of "
                  "'Lower corner' and 'Upper corner'; every coordinate of "
                  "'Upper corner' must exceed that of 'Lower corner'.");
              GridGenerator::hyper_ball(
                serial,
                0.5 * (lower + upper),
                radius,
                /*attach_spherical_manifold_on_boundary_cells=*/
                true);
              break;
            }
          case MeshParameters::Type::column:
            if constexpr (dim == 3)
              make_column(p, serial);
            else
              throw std::runtime_error(
                "subsection 'Mesh': a 'column' is a 3D mesh; a 2D run "
                "takes a 'hyper rectangle' for a channel.");
            break;
          case MeshParameters::Type::graded_rectangle:
            {
              const Point<dim> lower
                = corner<dim>(p.lower_corner, "Lower corner");
              const Point<dim> upper
                = corner<dim>(p.upper_corner, "Upper corner");
              const Point<dim> fine_lower
                = corner<dim>(p.fine_lower, "Fine region lower corner");
              const Point<dim> fine_upper
                = corner<dim>(p.fine_upper, "Fine region upper corner");
              std::vector<std::vector<double>> steps(dim);
              for (unsigned int d = 0; d < dim; ++d)
                steps[d] = graded_cell_sizes(lower[d],
                                             upper[d],
                                             fine_lower[d],
                                             fine_upper[d],
                                             p.fine_cell_size,
                                             p.grading_ratio);
              GridGenerator::subdivided_hyper_rectangle(serial,
                                                        steps,
                                                        lower,
                                                        upper,
                                                        /*colorize=*/true);
              break;
            }
          case MeshParameters::Type::channel_with_cylinder:
            GridGenerator::channel_with_cylinder(serial,
                                                 p.cylinder_shell_width,
                                                 p.cylinder_shells,
                                                 2.0,
                                                 /*colorize=*/true);
            if (p.cylinder_center_x != 0.2 || p.channel_length != 2.2)
              place_cylinder(serial, p.cylinder_center_x, p.channel_length);
            if constexpr (dim == 3)
              if (p.channel_depth != generated_channel_depth)
                set_channel_depth(serial, p.cylinder_center_x, p.channel_depth);
            break;
          case MeshParameters::Type::file:
            read_mesh_file(p, serial);
            break;
        }
      serial.refine_global(p.refinements);
    }



    template <int dim>
    void
    create_mesh(const MeshParameters                           &p,
                parallel::fullydistributed::Triangulation<dim> &tria)
    {
      // The levels of the uniform refinement go along (owned by the ranks
      // that own their first children), so that geometric multigrid can
      // use them; that needs the level-difference smoothing flag.
      Triangulation<dim> serial(
        Triangulation<dim>::limit_level_difference_at_vertices);
      create_serial_mesh(p, serial);

      const MPI_Comm comm = tria.get_communicator();
      GridTools::partition_triangulation_zorder(Utilities::MPI::n_mpi_processes(
                                                  comm),
                                                serial);
      GridTools::partition_multigrid_levels(serial);

      // Stateless manifolds (polar, cylindrical) carry over; a transfinite
      // interpolation refers to the serial coarse mesh and cannot, but the
      // vertices it placed are already in the refined mesh, and a flat
      // description of those interior cells is all the mapping needs.
      for (const auto id : serial.get_manifold_ids())
        if (id != numbers::flat_manifold_id)
          {
            const Manifold<dim> &m = serial.get_manifold(id);
            if (dynamic_cast<const TransfiniteInterpolationManifold<dim> *>(&m))
              tria.set_manifold(id, FlatManifold<dim>());
            else
              tria.set_manifold(id, m);
          }
      tria.create_triangulation(
        TriangulationDescription::Utilities::
          create_description_from_triangulation(
            serial,
            comm,
            TriangulationDescription::Settings::construct_multigrid_hierarchy));
    }



    template <int dim>
    std::vector<unsigned int>
    global_boundary_ids(
      const parallel::fullydistributed::Triangulation<dim> &tria)
    {
      std::set<unsigned int> local;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              local.insert(face->boundary_id());
      const std::vector<unsigned int> mine(local.begin(), local.end());
      return Utilities::MPI::compute_set_union(mine, tria.get_communicator());
    }

    template <int dim>
    std::pair<Point<dim>, Point<dim>>
    global_bounding_box(const Triangulation<dim> &tria, MPI_Comm comm)
    {
      std::vector<double> lower(dim, std::numeric_limits<double>::max()),
        upper(dim, std::numeric_limits<double>::lowest());
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::min(lower[d], cell->vertex(v)[d]);
                upper[d] = std::max(upper[d], cell->vertex(v)[d]);
              }
      Utilities::MPI::min(lower, comm, lower);
      Utilities::MPI::max(upper, comm, upper);
      std::pair<Point<dim>, Point<dim>> box;
      for (unsigned int d = 0; d < dim; ++d)
        {
          box.first[d]  = lower[d];
          box.second[d] = upper[d];
        }
      return box;
    }

    template <int dim>
    std::unique_ptr<Manifold<dim>>
    cylinder_axis_manifold(const double x, const double y)
    {
      Point<dim> axis_point;
      axis_point[0] = x;
      axis_point[1] = y;
      if constexpr (dim == 2)
        return std::make_unique<PolarManifold<2>>(axis_point);
      else
        return std::make_unique<CylindricalManifold<3>>(Tensor<1, 3>(
                                                          {0., 0., 1.}),
                                                        axis_point);
    }

    template void
    create_serial_mesh<2>(const MeshParameters &, Triangulation<2> &);
    template void
    create_serial_mesh<3>(const MeshParameters &, Triangulation<3> &);
    template void
    create_mesh<2>(const MeshParameters &,
                   parallel::fullydistributed::Triangulation<2> &);
    template void
    create_mesh<3>(const MeshParameters &,
                   parallel::fullydistributed::Triangulation<3> &);
    template std::unique_ptr<Manifold<2>>
    cylinder_axis_manifold<2>(const double, const double);
    template std::unique_ptr<Manifold<3>>
    cylinder_axis_manifold<3>(const double, const double);
    template std::vector<unsigned int>
    global_boundary_ids<2>(
      const parallel::fullydistributed::Triangulation<2> &);
    template std::vector<unsigned int>
    global_boundary_ids<3>(
      const parallel::fullydistributed::Triangulation<3> &);
    template <int dim>
    double
    smallest_cell_edge(const Triangulation<dim> &tria, MPI_Comm comm)
    {
      double h = std::numeric_limits<double>::max();
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          h = std::min(h, cell->minimum_vertex_distance());
      return Utilities::MPI::min(h, comm);
    }

    template double
    smallest_cell_edge<2>(const Triangulation<2> &, MPI_Comm);
    template double
    smallest_cell_edge<3>(const Triangulation<3> &, MPI_Comm);
    template std::pair<Point<2>, Point<2>>
    global_bounding_box<2>(const Triangulation<2> &, MPI_Comm);
    template std::pair<Point<3>, Point<3>>
    global_bounding_box<3>(const Triangulation<3> &, MPI_Comm);
  } // namespace core
} // namespace particulate
