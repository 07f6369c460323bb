#include <particulate/cuda/containment_engine.h>
#include <particulate/fbm/particle_parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace fbm {
    using namespace dealii;

    namespace {
      [[noreturn]] void
      fail(const std::string &entry, const std::string &what)
      {
        throw std::runtime_error("subsection 'Particles', entry '" + entry
                                 + "': " + what);
      }

      /** "x, y[, z]; x, y[, z]; ..." with @p dim coordinates each. */
      std::vector<Eigen::Vector3d>
      parse_points(const std::string &text,
                   const unsigned int dim,
                   const std::string &entry)
      {
        std::vector<Eigen::Vector3d> points;
        if (Utilities::trim(text).empty())
          return points;
        for (const std::string &item : Utilities::split_string_list(text, ';'))
          {
            const auto coordinates = Utilities::split_string_list(item, ',');
            if (coordinates.size() != dim)
              fail(entry,
                   "'" + item + "' has " + std::to_string(coordinates.size())
                     + " coordinates; a " + std::to_string(dim) + "D run needs "
                     + std::to_string(dim)
                     + " per point, points separated by ';'.");
            Eigen::Vector3d p = Eigen::Vector3d::Zero();
            for (unsigned int d = 0; d < dim; ++d)
              try
                {
                  p[d] = Utilities::string_to_double(coordinates[d]);
                }
              catch (...)
                {
                  fail(entry, "'" + coordinates[d] + "' is not a number.");
                }
            points.push_back(p);
          }
        return points;
      }

      std::array<bool, 3>
      parse_axes(const std::string &text, const std::string &entry)
      {
        std::array<bool, 3> axes = {{false, false, false}};
        for (const std::string &a : Utilities::split_string_list(text, ','))
          {
            if (a == "x")
              axes[0] = true;
            else if (a == "y")
              axes[1] = true;
            else if (a == "z")
              axes[2] = true;
            else
              fail(entry,
                   "'" + a + "' is not an axis; write a list of x, y, z.");
          }
        return axes;
      }
    } // namespace



    void
    ParticleParameters::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Particles");
      prm.declare_entry("Shape",
                        "sphere",
                        Patterns::Selection("sphere|disk|cylinder"),
                        "Shape of every particle: 'sphere' (3D runs), "
                        "'disk' (2D runs; a cylinder of unit depth) or "
                        "'cylinder' (3D runs: a circular cylinder of radius "
                        "'Radius' whose axis runs along z through the "
                        "particle's position, of length 'Length'; e.g. a "
                        "cylinder spanning a slab-shaped channel).");
      prm.declare_entry("Radius",
                        "0.0075",
                        Patterns::Double(0.),
                        "Particle radius [m].");
      prm.declare_entry("Length",
                        "0",
                        Patterns::Double(0.),
                        "Shape = cylinder: length of the cylinder along z "
                        "[m], centred at the particle's position. A cylinder "
                        "that spans a channel from wall to wall has the "
                        "channel's depth; leave the z faces out of 'Domain "
                        "walls' then, or the engine sees it touching them.");
      prm.declare_entry("Density",
                        "1120",
                        Patterns::Double(0.),
                        "Particle density rho_p [kg/m^3]. The buoyancy uses "
                        "the fluid 'Density' of subsection 'Fluid'.");
      prm.declare_entry("Motion",
                        "free",
                        Patterns::Selection("free|fixed|prescribed"),
                        "'free': the particles move under the fluid force, "
                        "buoyancy-corrected gravity and contacts (thesis eq. "
                        "5.3). 'fixed': they stay at rest, obstacles described "
                        "by the fictitious boundary method. 'prescribed': "
                        "they translate by 'Prescribed displacement' (e.g. an "
                        "oscillating cylinder, thesis §6.3), whatever the "
                        "fluid does.");
      core::FunctionExpression::declare(
        prm,
        "Prescribed displacement",
        "0; 0; 0",
        "'Motion = prescribed': the displacement d(t) [m] of every particle "
        "from its initial position, one expression in t per space dimension "
        "(x, y and z are not used), e.g. 'A*sin(2*pi*f*t); 0' with 'A=0.25, "
        "f=0.25' in the constants entry. The velocity is its time "
        "derivative, taken numerically.");
      prm.declare_entry("Positions",
                        "",
                        Patterns::Anything(),
                        "Initial centres [m], one point per particle, "
                        "coordinates separated by ',' and points by ';', "
                        "e.g. '0.05, 0.05, 0.1275' or '1, 7.2; 1, 6.8'. "
                        "The number of points is the number of particles.");
      prm.declare_entry("Velocities",
                        "",
                        Patterns::Anything(),
                        "Initial velocities [m/s], written like 'Positions' "
                        "(empty: at rest).");
      prm.declare_entry("Gravity",
                        "0, 0, -9.81",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Gravitational acceleration g [m/s^2] (the first dim "
                        "values are used). It acts on the particles as "
                        "(rho_p - rho_f) V g; the fluid's hydrostatic "
                        "pressure is left out of its equations (do not put "
                        "gravity into 'Fluid / Body force').");
      prm.declare_entry("Locked translations",
                        "",
                        Patterns::Anything(),
                        "World axes (list of x, y, z) along which the "
                        "particles may not move, e.g. 'x, y' for a sphere on "
                        "the symmetry line of a quarter domain.");
      prm.declare_entry("Locked rotations",
                        "",
                        Patterns::Anything(),
                        "World axes about which the particles may not "
                        "rotate. 2D runs lock x and y themselves.");
      prm.declare_entry("Symmetry planes",
                        "none",
                        Patterns::Anything(),
                        "Faces of the mesh's bounding box (list of x-, x+, "
                        "y-, y+, z-, z+, or 'none') that are mirror planes "
                        "of a symmetric set-up, e.g. 'x-, y-' for a quarter "
                        "domain. The particles' centres must lie on them and "
                        "their translation across them must be locked; the "
                        "force, torque and fluid kinetic energy computed in "
                        "the mesh are completed by the mirror images, so "
                        "the output is that of the full set-up. Give these "
                        "faces a free-slip condition.");
      prm.declare_entry("Added mass coefficient",
                        "1",
                        Patterns::Double(0.),
                        "C in the added mass m_a = C rho_f V that stabilises "
                        "the explicit coupling of light particles: the "
                        "particle is integrated with mass m + m_a under the "
                        "force F + m_a a_old (and likewise for rotation), "
                        "which equals m a = F at convergence but stays stable "
                        "for density ratios near 1 at small time steps. 0 "
                        "gives the plain explicit coupling.");
      prm.declare_entry("Constraint velocity",
                        "extrapolated",
                        Patterns::Selection("current|extrapolated"),
                        "Rigid velocity the covered nodes get for a time "
                        "step of a free particle. 'extrapolated' (default): "
                        "U_n + dt a_n with a_n the acceleration of the last "
                        "step, the velocity predicted for the end of the "
                        "step (likewise for rotation). 'current': the "
                        "particle's velocity at the start of the step, U_n "
                        "(the fluid lags the particle by dt a: a first-order "
                        "error in time).");
      prm.declare_entry("Interface position",
                        "midpoint",
                        Patterns::Selection("start|midpoint"),
                        "Where a free particle is when its covered nodes are "
                        "marked for a time step. 'midpoint' (default): at "
                        "X_n + dt/2 (U_n + dt/2 a_n), the position predicted "
                        "for the middle of the step; the hydrodynamic torque "
                        "is taken about that point too. 'start': at X_n, so "
                        "the fluid sees the particle half a step behind on "
                        "average (first order in time). The default changes "
                        "a light disk's velocity 19 times less between "
                        "dt = 10 ms and 0.25 ms than 'start' with "
                        "'current' (doc/fbm.md, added-mass study).");
      prm.declare_entry(
        "Force integral",
        "stress",
        Patterns::Selection("stress|stress and inertia"),
        "How the hydrodynamic force and torque are computed. 'stress': the "
        "volume integral -int sigma . grad alpha over the cut cells (thesis "
        "eq. 5.12-5.13), alpha the Q2 interpolant of the covered nodes. "
        "'stress and inertia': plus -rho_f int (Du/Dt - a_body) alpha, the "
        "momentum of the fluid in the cut cells and of the nodes the body "
        "covers during a step, which the stress integral leaves out; the "
        "sum is the reaction of the discrete momentum equation at the "
        "covered nodes (doc/fbm.md, 'Force integral').");
      prm.declare_entry("Contact solver",
                        "sequential impulses",
                        Patterns::Selection(
                          "sequential impulses|projected Gauss-Seidel|DEM"),
                        "Contact model of the rigid-body engine (thesis "
                        "§4.4).");
      prm.declare_entry("Restitution",
                        "0",
                        Patterns::Double(0., 1.),
                        "Coefficient of restitution of particle-particle and "
                        "particle-wall contacts [-].");
      prm.declare_entry("Friction",
                        "0",
                        Patterns::Double(0.),
                        "Coulomb friction coefficient of contacts [-].");
      prm.declare_entry(
        "Contact distance",
        "auto",
        Patterns::Anything(),
        "Gap [m] below which the rigid-body engine's contact model keeps two "
        "surfaces apart (particle-particle and particle-wall), or 'auto' for "
        "the edge length of the smallest cell. A film thinner than about one "
        "cell is not resolved by the mesh: its few free velocity nodes would "
        "have to carry the whole squeeze flow, and the pressure, with the "
        "force on the particle, spikes. The contact model stops the approach "
        "there instead (thesis §5.1: collisions by the rigid-body methods, "
        "not by repulsive forces). 0 lets the surfaces touch.");
      prm.declare_entry("Domain walls",
                        "all",
                        Patterns::Anything(),
                        "Faces of the mesh's bounding box that are fixed "
                        "walls of the rigid-body engine, so that particles "
                        "collide with the container: 'all', 'none', or a "
                        "list of x-, x+, y-, y+, z-, z+ (leave out symmetry "
                        "planes).");
      prm.declare_entry("Rigid substeps",
                        "1",
                        Patterns::Integer(1),
                        "Rigid-body substeps per fluid time step.");
      prm.declare_entry(
        "Containment backend",
        "auto",
        Patterns::Selection("auto|cpu|cuda"),
        "How the velocity nodes inside the particles are found every step. "
        "cpu: a hash grid over the nodes and the particles' exact signed "
        "distances in double precision. cuda: the cuda/ library's "
        "containment kernel on the GPU (float arithmetic; a node within "
        "about 1e-7 of the particle size from its surface may be "
        "classified differently than by cpu); needs a CUDA build and a "
        "device. auto: cuda when a device is present and 'Covered nodes' "
        "is 'inside', cpu otherwise.");
      prm.declare_entry(
        "Covered nodes",
        "inside",
        Patterns::Selection("inside|halfway|nearest"),
        "Which velocity nodes take a particle's rigid velocity. inside: the "
        "nodes inside it or on its surface (signed distance <= 0, thesis eq. "
        "5.9, up to 1e-10 of the node spacing against rounding); the flow "
        "sees a body shrunk to its innermost nodes. nearest: also the nodes "
        "outside by less than half the local node spacing (a quarter of the "
        "shortest edge of the cells around the node); the flow sees a body "
        "enlarged by up to that. The two bracket the body: creeping flow "
        "past a sphere at 2.7 cells per diameter gives drags 7.7 % below "
        "(inside) and 7.3 % above (nearest) the closed form (doc/fbm.md, "
        "'Which nodes'). halfway: the nodes outside by less than a quarter "
        "of the local node spacing, half the reach of nearest. The "
        "cuda containment backend supports 'inside' only.");
      prm.leave_subsection();
    }



    void
    ParticleParameters::parse(ParameterHandler &prm, const unsigned int dim)
    {
      prm.enter_subsection("Particles");
      const std::string shape_name = prm.get("Shape");
      shape                        = shape_name == "disk"     ? Shape::disk :
                                     shape_name == "cylinder" ? Shape::cylinder :
                                                                Shape::sphere;
      radius                       = prm.get_double("Radius");
      length                       = prm.get_double("Length");
      density                      = prm.get_double("Density");
      const std::string m          = prm.get("Motion");
      motion                       = m == "fixed"      ? Motion::fixed :
                                     m == "prescribed" ? Motion::prescribed :
                                                         Motion::free;
      prescribed_displacement.parse(prm, "Prescribed displacement");
      positions    = parse_points(prm.get("Positions"), dim, "Positions");
      velocities   = parse_points(prm.get("Velocities"), dim, "Velocities");
      const auto g = Utilities::split_string_list(prm.get("Gravity"), ',');
      gravity.setZero();
      if (g.size() < dim)
        fail("Gravity",
             "a " + std::to_string(dim) + "D run needs " + std::to_string(dim)
               + " components.");
      for (unsigned int d = 0; d < dim; ++d)
        gravity[d] = Utilities::string_to_double(g[d]);
      locked_translation
        = parse_axes(prm.get("Locked translations"), "Locked translations");
      locked_rotation
        = parse_axes(prm.get("Locked rotations"), "Locked rotations");
      added_mass_coefficient = prm.get_double("Added mass coefficient");
      extrapolate_constraint_velocity
        = prm.get("Constraint velocity") == "extrapolated";
      midpoint_interface_position = prm.get("Interface position") == "midpoint";
      force_includes_fluid_inertia
        = prm.get("Force integral") == "stress and inertia";
      contact_solver = prm.get("Contact solver");
      restitution    = prm.get_double("Restitution");
      friction       = prm.get_double("Friction");
      {
        const std::string text = Utilities::trim(prm.get("Contact distance"));
        contact_distance.reset();
        if (text != "auto")
          {
            double value = -1.;
            try
              {
                value = Utilities::string_to_double(text);
              }
            catch (...)
              {}
            if (!(value >= 0.) || !std::isfinite(value))
              fail("Contact distance",
                   "'" + text + "' is neither 'auto' nor a length >= 0 in m.");
            contact_distance = value;
          }
      }
      const auto read_faces = [&](const std::string &entry) {
        const std::string   text = Utilities::trim(prm.get(entry));
        std::array<bool, 6> faces;
        faces.fill(text == "all");
        if (text != "all" && text != "none")
          {
            const std::array<std::string, 6> names{
              {"x-", "x+", "y-", "y+", "z-", "z+"}};
            for (const std::string &w : Utilities::split_string_list(text, ','))
              {
                const auto it = std::find(names.begin(), names.end(), w);
                if (it == names.end()
                    || int(it - names.begin()) >= 2 * int(dim))
                  fail(entry,
                       "'" + w + "' is not a face of this "
                         + std::to_string(dim)
                         + "D box; write 'all', 'none' or a list of x-, x+, "
                           "y-, y+"
                         + (dim == 3 ? ", z-, z+." : "."));
                faces[it - names.begin()] = true;
              }
          }
        return faces;
      };
      walls               = read_faces("Domain walls");
      symmetry_planes     = read_faces("Symmetry planes");
      substeps            = prm.get_integer("Rigid substeps");
      containment_backend = prm.get("Containment backend");
      covered_nodes       = prm.get("Covered nodes");
      prm.leave_subsection();
      if (containment_backend == "cuda" && covered_nodes != "inside")
        fail("Containment backend",
             "the cuda containment engine marks the nodes inside the "
             "particles only; set 'Covered nodes = inside' or choose "
             "'Containment backend = cpu' (or 'auto').");
      if (containment_backend == "cuda"
          && !cuda::ContainmentEngine::cuda_device_available())
        fail("Containment backend",
             cuda::ContainmentEngine::cuda_compiled() ?
               "'cuda' needs a CUDA device and this machine has none; set "
               "'auto' or 'cpu'." :
               "'cuda' needs a build with CUDA (nvcc was not found when "
               "this build was configured); set 'auto' or 'cpu'.");

      if (dim == 2)
        {
          // planar motion: no z translation, rotation only about z
          locked_translation[2] = true;
          locked_rotation[0] = locked_rotation[1] = true;
        }
      // a pure fluid run has no particles: nothing below concerns it
      if (positions.empty())
        return;
      for (unsigned int f = 0; f < 6; ++f)
        if (symmetry_planes[f] && !locked_translation[f / 2])
          fail("Symmetry planes",
               std::string("a particle on the mirror plane ") + "xyz"[f / 2]
                 + (f % 2 ? "+" : "-") + " may not move across it: add '"
                 + "xyz"[f / 2] + "' to 'Locked translations'.");
        else if (symmetry_planes[f] && walls[f])
          fail("Symmetry planes",
               std::string("face ") + "xyz"[f / 2] + (f % 2 ? "+" : "-")
                 + " is also listed in 'Domain walls'; a mirror plane is not "
                   "a wall.");
      if (dim == 2 && shape != Shape::disk)
        fail("Shape", "a 2D run needs 'disk'.");
      if (dim == 3 && shape == Shape::disk)
        fail("Shape", "a 3D run needs 'sphere' or 'cylinder'.");
      if (shape == Shape::cylinder && !(length > 0.))
        fail("Length",
             "a 'cylinder' needs its length along z [m] (the channel's depth "
             "for a cylinder that spans it).");
      if (shape == Shape::cylinder && containment_backend == "cuda")
        fail("Containment backend",
             "the cuda containment engine takes spheres and 2D disks only; "
             "set 'cpu' or 'auto' for a 'cylinder'.");
      if (!(radius > 0.))
        fail("Radius", "must be positive.");
      if (!(density > 0.))
        fail("Density", "must be positive.");
      if (motion == Motion::prescribed)
        {
          // the component count of the expression is checked here, so a
          // forgotten ';' is reported before the run starts
          try
            {
              if (dim == 2)
                prescribed_displacement.create<2>(2,
                                                  "Particles / Prescribed "
                                                  "displacement");
              else
                prescribed_displacement.create<3>(3,
                                                  "Particles / Prescribed "
                                                  "displacement");
            }
          catch (const std::exception &e)
            {
              fail("Prescribed displacement", e.what());
            }
        }
      if (!velocities.empty() && velocities.size() != positions.size())
        fail("Velocities",
             "gives " + std::to_string(velocities.size()) + " velocities for "
               + std::to_string(positions.size())
               + " particles; give one per particle or none.");
    }
  } // namespace fbm
} // namespace particulate
