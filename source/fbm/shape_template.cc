#include <particulate/core/input_file.h>
#include <particulate/fbm/shape_template.h>
#include <particulate/geometry/box.h>
#include <particulate/geometry/capsule.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/elliptic_cylinder.h>
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_body.h>
#include <particulate/geometry/sphere.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include "entry_values.h"
#include <unistd.h>

namespace particulate {
  namespace fbm {
    using namespace dealii;

    namespace {
      using Type = ShapeTemplate::Type;

      const std::array<std::pair<Type, const char *>, 9> type_names{
        {{Type::sphere, "sphere"},
         {Type::ellipsoid, "ellipsoid"},
         {Type::box, "box"},
         {Type::cylinder, "cylinder"},
         {Type::capsule, "capsule"},
         {Type::disk, "disk"},
         {Type::ellipse, "ellipse"},
         {Type::rectangle, "rectangle"},
         {Type::mesh, "mesh"}}};

      /** Where distance maps are cached: $XDG_CACHE_HOME/particulate or
       *  ~/.cache/particulate; empty (no cache) without either. */
      std::string
      distance_map_cache_folder()
      {
        if (const char *xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
          return std::string(xdg) + "/particulate/distance-maps";
        if (const char *home = std::getenv("HOME"); home && *home)
          return std::string(home) + "/.cache/particulate/distance-maps";
        return "";
      }

      /** The largest distance map a run builds: half the machine's memory
       *  (0, no limit, where it cannot be told). */
      std::size_t
      half_the_physical_memory()
      {
        const long pages = sysconf(_SC_PHYS_PAGES);
        const long size  = sysconf(_SC_PAGE_SIZE);
        return pages > 0 && size > 0 ?
                 static_cast<std::size_t>(pages) * size / 2 :
                 0;
      }

      bool
      is_planar(const Type type)
      {
        return type == Type::disk || type == Type::ellipse
               || type == Type::rectangle;
      }

      /// The entry that holds the size of @p type besides 'Length'.
      std::string
      size_entry(const Type type)
      {
        switch (type)
          {
            case Type::ellipsoid:
            case Type::ellipse:
              return "Semi-axes";
            case Type::box:
            case Type::rectangle:
              return "Half-extents";
            default:
              return "Radius";
          }
      }
    } // namespace



    void
    ShapeTemplate::declare(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Type",
        "sphere",
        Patterns::Selection(
          "sphere|ellipsoid|box|cylinder|capsule|disk|ellipse|rectangle|mesh"),
        "The solid, centred at the particle's position and given in its body "
        "frame (rotated by the particle's orientation). 3D runs: 'sphere' "
        "('Radius'), 'ellipsoid' ('Semi-axes' a, b, c along body x, y, z), "
        "'box' ('Half-extents'), 'cylinder' ('Radius', 'Length' along body "
        "z, flat caps), 'capsule' ('Radius', 'Length' of the segment along "
        "body z between the centres of its hemispherical caps), 'mesh' (a "
        "closed surface mesh: 'File', 'Scale', 'Map spacing'). 2D runs "
        "(prisms of unit depth): 'disk' ('Radius'), 'ellipse' ('Semi-axes' "
        "a, b along body x, y), 'rectangle' ('Half-extents' along body x, "
        "y).");
      prm.declare_entry(
        "File",
        "",
        Patterns::Anything(),
        "Mesh: a closed, manifold surface mesh (OFF, STL, OBJ or PLY; a "
        "relative path starts at the case file's folder). Triangles facing "
        "inwards are turned outwards. The particle's 'Position' is where the "
        "mesh's centroid goes, and its orientation turns the mesh as it is "
        "in the file. Mass, centroid and inertia are the polyhedron's exact "
        "ones; contacts, the fictitious boundary and the mesh deformation "
        "read its distance map.");
      prm.declare_entry("Scale",
                        "1",
                        Patterns::Double(0.),
                        "Mesh: the factor that turns the file's coordinates "
                        "into metres (0.001 for a file in millimetres).");
      prm.declare_entry(
        "Map spacing",
        "0",
        Patterns::Double(0.),
        "Mesh: the grid spacing of its distance map [m]. 0: the smallest "
        "edge of the mesh's bounding box over 16. The map's distance is "
        "about h^2 / (8 R) off near a surface of curvature radius R; refine "
        "it for thin parts (a warning names a body thinner than two map "
        "cells). Maps are cached by mesh, spacing and margin in "
        "$XDG_CACHE_HOME/particulate/distance-maps (or "
        "~/.cache/particulate/distance-maps).");
      prm.declare_entry("Radius",
                        "0",
                        Patterns::Double(0.),
                        "Radius [m] of a sphere, cylinder, capsule or disk.");
      prm.declare_entry("Length",
                        "0",
                        Patterns::Double(0.),
                        "Cylinder: its length along the body z axis [m]. "
                        "Capsule: the length of its core segment [m] (the "
                        "capsule is 'Length' + 2 'Radius' long).");
      prm.declare_entry("Semi-axes",
                        "",
                        Patterns::Anything(),
                        "Ellipsoid (3 values) or ellipse (2 values): the "
                        "semi-axes along the body axes [m], e.g. '0.002, "
                        "0.001, 0.001' for a prolate spheroid of aspect "
                        "ratio 2 along body x.");
      prm.declare_entry("Half-extents",
                        "",
                        Patterns::Anything(),
                        "Box (3 values) or rectangle (2 values): half the "
                        "edge lengths along the body axes [m].");
      prm.declare_entry("Density",
                        "1120",
                        Patterns::Double(0.),
                        "Density rho_p of the particles of this shape "
                        "[kg/m^3]. The buoyancy uses the fluid 'Density' of "
                        "subsection 'Fluid'.");
    }



    void
    ShapeTemplate::parse(const ParameterHandler         &prm,
                         const std::string              &label,
                         const unsigned int              dim,
                         const core::InputOutline       &outline,
                         const std::vector<std::string> &path)
    {
      name                    = label;
      const std::string typed = prm.get("Type");
      for (const auto &[t, n] : type_names)
        if (typed == n)
          type = t;
      if (is_planar(type) != (dim == 2))
        internal::fail_at(outline.where(path, "Type"),
                          "'" + typed + "' is a shape of "
                            + (dim == 2 ? "3D" : "2D") + " runs; a "
                            + std::to_string(dim) + "D run takes "
                            + (dim == 2 ? "disk, ellipse or rectangle." :
                                          "sphere, ellipsoid, box, cylinder, "
                                          "capsule or mesh."));
      density = prm.get_double("Density");
      if (!(density > 0.))
        internal::fail_at(outline.where(path, "Density"), "must be positive.");
      length = prm.get_double("Length");
      radius = prm.get_double("Radius");
      extents.setZero();

      const std::string  size  = size_entry(type);
      const unsigned int n_ext = is_planar(type) ? 2 : 3;
      if (type == Type::mesh)
        read_mesh_entries(prm, outline, path);
      else if (size == "Radius")
        {
          if (!(radius > 0.))
            internal::fail_at(outline.where(path, "Radius"),
                              "a " + typed + " needs a positive radius [m].");
        }
      else
        {
          extents = internal::read_vector(prm.get(size),
                                          n_ext,
                                          outline.where(path, size));
          if (!(extents.head(n_ext).minCoeff() > 0.))
            internal::fail_at(outline.where(path, size),
                              "the sizes of a " + typed
                                + " must all be positive.");
        }
      if (type == Type::cylinder && !(length > 0.))
        internal::fail_at(outline.where(path, "Length"),
                          "a cylinder needs its length along the body z axis "
                          "[m].");
    }



    void
    ShapeTemplate::read_mesh_entries(const ParameterHandler         &prm,
                                     const core::InputOutline       &outline,
                                     const std::vector<std::string> &path)
    {
      const std::string file = Utilities::trim(prm.get("File"));
      if (file.empty())
        internal::fail_at(outline.where(path, "Type"),
                          "a mesh needs its surface mesh file in 'File'.");
      std::filesystem::path resolved(file);
      if (resolved.is_relative())
        resolved
          = std::filesystem::path(outline.filename()).parent_path() / resolved;
      mesh_file   = resolved.string();
      mesh_scale  = prm.get_double("Scale");
      map_spacing = prm.get_double("Map spacing");
      if (!(mesh_scale > 0.))
        internal::fail_at(outline.where(path, "Scale"),
                          "must be positive: it multiplies the mesh file's "
                          "coordinates to give metres.");
      if (!std::filesystem::is_regular_file(resolved))
        internal::fail_at(outline.where(path, "File"),
                          "there is no file '" + mesh_file
                            + "' (a relative path starts at the case file's "
                              "folder).");
      load_mesh(outline.where(path, "File"));
    }



    void
    ShapeTemplate::load_mesh(const std::string &where)
    {
      geometry::MeshBodyOptions options;
      options.scale        = mesh_scale;
      options.map_spacing  = map_spacing;
      options.cache_folder = distance_map_cache_folder();
      options.memory_limit = half_the_physical_memory();
      try
        {
          const geometry::MeshBody body
            = geometry::load_mesh_body(mesh_file, options);
          mesh           = body.shape;
          frame_rotation = Eigen::Quaterniond(body.file_frame.rotation());
        }
      catch (const geometry::GeometryError &e)
        {
          internal::fail_at(where, e.what());
        }
    }



    std::shared_ptr<const geometry::Shape>
    ShapeTemplate::create() const
    {
      // a 2D body is a prism of unit depth: half height 1/2
      const double planar_half_depth = 0.5;
      switch (type)
        {
          case Type::ellipsoid:
            return std::make_shared<geometry::Ellipsoid>(extents);
          case Type::box:
            return std::make_shared<geometry::Box>(extents);
          case Type::cylinder:
            return std::make_shared<geometry::Cylinder>(radius, 0.5 * length);
          case Type::capsule:
            return std::make_shared<geometry::Capsule>(radius, 0.5 * length);
          case Type::disk:
            return std::make_shared<geometry::Cylinder>(radius,
                                                        planar_half_depth);
          case Type::ellipse:
            return std::make_shared<geometry::EllipticCylinder>(
              extents[0],
              extents[1],
              planar_half_depth);
          case Type::rectangle:
            return std::make_shared<geometry::Box>(
              Eigen::Vector3d(extents[0], extents[1], planar_half_depth));
          case Type::mesh:
            return mesh;
          case Type::sphere:
            break;
        }
      return std::make_shared<geometry::Sphere>(radius);
    }



    void
    ShapeLibrary::add(const ShapeTemplate &description)
    {
      entries.push_back({description, description.create()});
    }



    const ShapeLibrary::Entry &
    ShapeLibrary::find(const std::string &name, const std::string &where) const
    {
      for (const Entry &e : entries)
        if (e.description.name == name)
          return e;
      std::string  best;
      unsigned int best_distance = ~0u;
      for (const Entry &e : entries)
        {
          const unsigned int d = core::edit_distance(name, e.description.name);
          if (d < best_distance)
            {
              best_distance = d;
              best          = e.description.name;
            }
        }
      std::string hint
        = entries.empty() ?
            " The case defines no shapes: add a subsection 'Shape <name>' "
            "to subsection 'Particles'." :
            " Did you mean '" + best
              + "'? Shapes are defined by subsections 'Shape <name>' of "
                "subsection 'Particles'.";
      internal::fail_at(where, "there is no shape '" + name + "'." + hint);
    }
  } // namespace fbm
} // namespace particulate
