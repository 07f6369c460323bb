#include <particulate/core/choice_names.h>
#include <particulate/core/parameter_text.h>
#include <particulate/cuda/containment_engine.h>
#include <particulate/fbm/particle_parameters.h>
#include <particulate/fbm/particle_shape.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "entry_values.h"

namespace particulate {
  namespace fbm {
    using namespace dealii;

    namespace {
      std::array<bool, 3>
      parse_axes(const std::string &text, const std::string &where)
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
              internal::fail_at(where,
                                "'" + a
                                  + "' is not an axis; write a list of x, y, "
                                    "z.");
          }
        return axes;
      }

      const std::array<std::string, 3> axis_names = {{"x", "y", "z"}};
      const std::array<std::string, 6> face_names
        = {{"x-", "x+", "y-", "y+", "z-", "z+"}};

      std::string
      axes_text(const std::array<bool, 3> &axes)
      {
        std::string text;
        for (unsigned int d = 0; d < 3; ++d)
          if (axes[d])
            text += (text.empty() ? "" : ", ") + axis_names[d];
        return text;
      }

      /// 'all', 'none' or the list of faces
      std::string
      faces_text(const std::array<bool, 6> &faces)
      {
        const auto n = std::count(faces.begin(), faces.end(), true);
        if (n == 6)
          return "all";
        if (n == 0)
          return "none";
        std::string text;
        for (unsigned int f = 0; f < 6; ++f)
          if (faces[f])
            text += (text.empty() ? "" : ", ") + face_names[f];
        return text;
      }

      std::string
      gravity_text(const Eigen::Vector3d &g)
      {
        return core::number_text(g[0]) + ", " + core::number_text(g[1]) + ", "
               + core::number_text(g[2]);
      }

      const core::ChoiceNames<CoveredNodes> covered_nodes_names
        = {{CoveredNodes::inside, "inside"},
           {CoveredNodes::halfway, "halfway"},
           {CoveredNodes::nearest, "nearest"}};
      const core::ChoiceNames<PartFilms> part_films_names
        = {{PartFilms::resolve, "resolve"}, {PartFilms::cover, "cover"}};
      const core::ChoiceNames<Coupling> coupling_names
        = {{Coupling::explicit_step, "explicit"},
           {Coupling::iterated, "iterated"}};
      const core::ChoiceNames<ContainmentBackend> backend_names
        = {{ContainmentBackend::automatic, "auto"},
           {ContainmentBackend::cpu, "cpu"},
           {ContainmentBackend::cuda, "cuda"}};

      /**
       * subsection 'Particles / Experimental': coupling variants kept to
       * study the coupling (the added-mass study compares them), not for
       * production runs: each is less accurate than the default.
       */
      void
      declare_experimental(ParameterHandler         &prm,
                           const ParticleParameters &defaults)
      {
        prm.enter_subsection("Experimental");
        prm.declare_entry(
          "Constraint velocity",
          defaults.extrapolate_constraint_velocity ? "extrapolated" : "current",
          Patterns::Selection("current|extrapolated"),
          "Experimental. Rigid velocity the covered nodes get for a time step "
          "of a free particle. 'extrapolated' (default): U_n + dt a_n with a_n "
          "the acceleration of the last step, the velocity predicted for the "
          "end of the step (likewise for rotation). 'current': the "
          "particle's velocity at the start of the step, U_n (the fluid lags "
          "the particle by dt a: a first-order error in time).");
        prm.declare_entry(
          "Interface position",
          defaults.midpoint_interface_position ? "midpoint" : "start",
          Patterns::Selection("start|midpoint"),
          "Experimental. Where a free particle is when its covered nodes are "
          "marked for a time step. 'midpoint' (default): at X_n + dt/2 (U_n + "
          "dt/2 a_n), the position predicted for the middle of the step, and "
          "turned likewise by dt/2 (omega_n + dt/2 alpha_n); the "
          "hydrodynamic torque is taken about that point too. 'start': at "
          "X_n, so the fluid sees the particle half a step behind on average "
          "(first order in time).");
        prm.declare_entry(
          "Stage velocities",
          defaults.interpolate_free_stage_velocities ? "interpolated" : "held",
          Patterns::Selection("held|interpolated"),
          "Experimental. What a free particle's covered nodes hold in the "
          "stages of a time step (a prescribed particle's are always "
          "interpolated). 'interpolated' (default): linearly in time from "
          "its velocity at t_n to the constraint velocity, so the pressure "
          "at the end of the step, and with it the force, holds the fluid's "
          "answer to the particle's acceleration (its added mass); the "
          "explicit coupling is then stable while that added mass stays "
          "below m + 2 C rho_f V ('Added mass coefficient'). 'held': the "
          "constraint velocity from the first stage on; the force holds "
          "none of the added mass and the particle accelerates too fast ("
          "doc/developer/fbm.md, 'Constraint values through the stages').");
        prm.leave_subsection();
      }
    } // namespace



    std::string
    to_string(const CoveredNodes choice)
    {
      return core::name_of(covered_nodes_names, choice);
    }



    std::string
    to_string(const Coupling choice)
    {
      return core::name_of(coupling_names, choice);
    }



    std::string
    to_string(const PartFilms choice)
    {
      return core::name_of(part_films_names, choice);
    }



    std::string
    to_string(const ContainmentBackend choice)
    {
      return core::name_of(backend_names, choice);
    }



    void
    ParticleParameters::declare(ParameterHandler        &prm,
                                const ParticleSetLayout &layout)
    {
      const ParticleParameters defaults;
      prm.enter_subsection("Particles");
      declare_particle_set(prm, layout);
      prm.declare_entry("Gravity",
                        gravity_text(defaults.gravity),
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Gravitational acceleration g [m/s^2] (the first dim "
                        "values are used). It acts on the particles as "
                        "(rho_p - rho_f) V g; the fluid's hydrostatic "
                        "pressure is left out of its equations (do not put "
                        "gravity into 'Fluid / Body force').");
      prm.declare_entry("Locked translations",
                        axes_text(defaults.locked_translation),
                        Patterns::Anything(),
                        "World axes (list of x, y, z) along which the "
                        "particles may not move, e.g. 'x, y' for a sphere on "
                        "the symmetry line of a quarter domain.");
      prm.declare_entry("Locked rotations",
                        axes_text(defaults.locked_rotation),
                        Patterns::Anything(),
                        "World axes about which the particles may not "
                        "rotate. 2D runs lock x and y themselves.");
      prm.declare_entry("Symmetry planes",
                        faces_text(defaults.symmetry_planes),
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
                        core::number_text(defaults.added_mass_coefficient),
                        Patterns::Double(0.),
                        "C in the added mass m_a = C rho_f V that stabilises "
                        "the explicit coupling: the particle is integrated "
                        "with mass m + m_a under the force F + m_a a_old "
                        "(and likewise for rotation), which equals m a = F "
                        "at convergence. The force holds the fluid's added "
                        "mass, which grows without bound as a particle "
                        "nears a wall or another particle; the step stays "
                        "stable while it is below m + 2 m_a. 0 gives the "
                        "plain explicit coupling.");
      prm.declare_entry(
        "Coupling",
        to_string(defaults.coupling),
        Patterns::Selection(core::selection_of(coupling_names)),
        "How a time step couples the fluid and the free bodies. explicit: "
        "the fluid is solved once, with the bodies' velocities predicted "
        "from the last step, and its loads move the bodies (thesis §5.3). "
        "The added mass keeps it stable but delays the bodies' answer to "
        "the fluid: for a light body under strong viscous forces the error "
        "is of the size of C rho_f V / k (doc/developer/fbm.md, 'Viscous "
        "stiffness'). iterated: the step is solved again from its start "
        "with the velocities the bodies reached, accelerated by a "
        "quasi-Newton method (IQN-ILS), until the two agree to 'Coupling tolerance': the "
        "bodies' motion no longer depends on the added mass, at the cost "
        "of that many fluid solves per step.");
      prm.declare_entry("Coupling tolerance",
                        core::number_text(defaults.coupling_tolerance),
                        Patterns::Double(0.),
                        "'Coupling = iterated': the largest difference "
                        "between the velocities the fluid was given and "
                        "those the free bodies reached, as a fraction of "
                        "their speed (rotation counted at the body's "
                        "bounding radius), or of the largest speed a free "
                        "body has reached so far where that is more. The "
                        "loads are only as precise as the flow's solvers: "
                        "the iteration needs their 'Relative tolerance' "
                        "well below the default (doc/developer/fbm.md, "
                        "'Iterated coupling').");
      prm.declare_entry(
        "Maximum coupling iterations",
        std::to_string(defaults.max_coupling_iterations),
        Patterns::Integer(1),
        "'Coupling = iterated': fluid solves a step may take; a step that "
        "has not met 'Coupling tolerance' after them stops the run.");
      declare_experimental(prm, defaults);
      prm.declare_entry(
        "Force integral",
        defaults.force_includes_fluid_inertia ? "stress and inertia" : "stress",
        Patterns::Selection("stress|stress and inertia"),
        "How the hydrodynamic force and torque are computed. 'stress': the "
        "volume integral -int sigma . grad alpha over the cut cells (thesis "
        "eq. 5.12-5.13), alpha the Q2 interpolant of the covered nodes. "
        "'stress and inertia': plus -rho_f int (Du/Dt - a_body) alpha, the "
        "momentum of the fluid in the cut cells and of the nodes the body "
        "covers during a step, which the stress integral leaves out; the "
        "sum is the reaction of the discrete momentum equation at the "
        "covered nodes (doc/developer/fbm.md, 'Force integral').");
      prm.declare_entry("Contact solver",
                        rigid::to_string(defaults.contact_solver),
                        Patterns::Selection(
                          "sequential impulses|projected Gauss-Seidel|DEM"),
                        "Contact model of the rigid-body engine (thesis "
                        "§4.4).");
      prm.declare_entry("Restitution",
                        core::number_text(defaults.restitution),
                        Patterns::Double(0., 1.),
                        "Coefficient of restitution of particle-particle and "
                        "particle-wall contacts [-].");
      prm.declare_entry("Friction",
                        core::number_text(defaults.friction),
                        Patterns::Double(0.),
                        "Coulomb friction coefficient of contacts [-].");
      prm.declare_entry(
        "Contact distance",
        defaults.contact_distance ?
          core::number_text(*defaults.contact_distance) :
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
                        faces_text(defaults.walls),
                        Patterns::Anything(),
                        "Faces of the mesh's bounding box that are fixed "
                        "walls of the rigid-body engine, so that particles "
                        "collide with the container: 'all', 'none', or a "
                        "list of x-, x+, y-, y+, z-, z+ (leave out symmetry "
                        "planes). The side of a 'column' mesh is one wall, "
                        "'mantle' (the four faces x-, x+, y-, y+ together); "
                        "a particle meets it as a tube around the column.");
      prm.declare_entry(
        "Distributor height",
        "",
        Patterns::Anything(),
        "Height [m] of a fluidized bed's distributor, the porous plate "
        "through which the liquid enters from below: the lowest wall of the "
        "rigid-body engine (z-, y- in 2D; it must be one of 'Domain walls') "
        "lies at this height instead of on the mesh's lowest face, so that "
        "the particles rest on it while the liquid flows through it freely "
        "from the inflow on that face. Keeps the particles away from the "
        "inflow, whose velocity they would otherwise meet within a cell. "
        "Empty: the wall lies on the mesh's face.");
      prm.declare_entry("Rigid substeps",
                        std::to_string(defaults.substeps),
                        Patterns::Integer(1),
                        "Rigid-body substeps per fluid time step.");
      prm.declare_entry(
        "Containment backend",
        to_string(defaults.containment_backend),
        Patterns::Selection(core::selection_of(backend_names)),
        "How the velocity nodes inside the particles are found every step. "
        "cpu: a hash grid over the nodes and the particles' signed "
        "distances in double precision (exact for the analytic shapes, the "
        "distance map for a mesh). cuda: the cuda/ library's "
        "containment kernel on the GPU (float arithmetic; a node within "
        "about 1e-7 of the particle size from its surface may be "
        "classified differently than by cpu); it takes spheres, surface "
        "meshes and 2D disks; needs a CUDA build and a device. auto: cuda "
        "when a device is present, 'Covered nodes' is 'inside' and the "
        "engine takes every particle, cpu otherwise.");
      prm.declare_entry(
        "Covered nodes",
        to_string(defaults.covered_nodes),
        Patterns::Selection(core::selection_of(covered_nodes_names)),
        "Which velocity nodes take a particle's rigid velocity. inside: the "
        "nodes inside it or on its surface (signed distance <= 0, thesis eq. "
        "5.9, up to 1e-10 of the node spacing against rounding); the flow "
        "sees a body shrunk to its innermost nodes. nearest: also the nodes "
        "outside by less than half the local node spacing (a quarter of the "
        "shortest edge of the cells around the node); the flow sees a body "
        "enlarged by up to that. The two bracket the body's drag from below "
        "and above on coarse meshes (doc/developer/fbm.md, 'Which nodes'). halfway: the nodes outside by less than a quarter "
        "of the local node spacing, half the reach of nearest. The "
        "cuda containment backend supports 'inside' only.");
      prm.declare_entry(
        "Films between parts",
        to_string(defaults.part_films),
        Patterns::Selection(core::selection_of(part_films_names)),
        "The liquid between two parts of one articulated body ('Motion = "
        "hinged') where they come closer than a cell. resolve: its nodes "
        "stay free; a node that parts close in on from two sides must "
        "carry the whole squeeze flow, and the loads on the parts can jump "
        "by orders of magnitude. cover: a free node within one node spacing "
        "of two parts takes the motion of the nearer part, as if the film "
        "moved with them (the contact distance does the like between "
        "particles). Set cover where parts close on each other on a fine or "
        "adapted mesh (doc/developer/fbm.md, 'Articulated bodies').");
      prm.leave_subsection();
    }



    void
    ParticleParameters::parse(ParameterHandler         &prm,
                              const unsigned int        dim,
                              const core::InputOutline &outline)
    {
      const auto fail = [&](const std::string &entry, const std::string &what) {
        internal::fail_at(outline.where({"Particles"}, entry), what);
      };
      prm.enter_subsection("Particles");
      bodies       = read_particle_set(prm, dim, outline);
      const auto g = Utilities::split_string_list(prm.get("Gravity"), ',');
      gravity.setZero();
      if (g.size() < dim)
        fail("Gravity",
             "a " + std::to_string(dim) + "D run needs " + std::to_string(dim)
               + " components.");
      for (unsigned int d = 0; d < dim; ++d)
        gravity[d] = Utilities::string_to_double(g[d]);
      locked_translation
        = parse_axes(prm.get("Locked translations"),
                     outline.where({"Particles"}, "Locked translations"));
      locked_rotation
        = parse_axes(prm.get("Locked rotations"),
                     outline.where({"Particles"}, "Locked rotations"));
      added_mass_coefficient = prm.get_double("Added mass coefficient");
      coupling = core::choice_named(coupling_names, prm.get("Coupling"));
      coupling_tolerance      = prm.get_double("Coupling tolerance");
      max_coupling_iterations = prm.get_integer("Maximum coupling iterations");
      prm.enter_subsection("Experimental");
      extrapolate_constraint_velocity
        = prm.get("Constraint velocity") == "extrapolated";
      midpoint_interface_position = prm.get("Interface position") == "midpoint";
      interpolate_free_stage_velocities
        = prm.get("Stage velocities") == "interpolated";
      prm.leave_subsection();
      if (coupling == Coupling::iterated && !extrapolate_constraint_velocity)
        fail("Coupling",
             "'iterated' gives the fluid the velocities the bodies are "
             "predicted to reach, which 'Experimental / Constraint velocity "
             "= current' leaves out; set it to 'extrapolated' or the "
             "coupling to 'explicit'.");
      force_includes_fluid_inertia
        = prm.get("Force integral") == "stress and inertia";
      contact_solver
        = rigid::contact_solver_type_from_string(prm.get("Contact solver"));
      restitution = prm.get_double("Restitution");
      friction    = prm.get_double("Friction");
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
      {
        const std::string text = Utilities::trim(prm.get("Distributor height"));
        distributor_height.reset();
        if (!text.empty())
          {
            double value = std::numeric_limits<double>::quiet_NaN();
            try
              {
                value = Utilities::string_to_double(text);
              }
            catch (...)
              {}
            if (!std::isfinite(value))
              fail("Distributor height",
                   "'" + text + "' is not a height in m (or leave it empty).");
            distributor_height = value;
          }
      }
      const auto read_faces = [&](const std::string &entry) {
        const std::string   text = Utilities::trim(prm.get(entry));
        std::array<bool, 6> faces;
        faces.fill(text == "all");
        if (text != "all" && text != "none")
          {
            const auto &names = face_names;
            for (const std::string &w : Utilities::split_string_list(text, ','))
              {
                if (w == "mantle" && dim == 3)
                  {
                    std::fill(faces.begin(), faces.begin() + 4, true);
                    continue;
                  }
                const auto it = std::find(names.begin(), names.end(), w);
                if (it == names.end()
                    || int(it - names.begin()) >= 2 * int(dim))
                  fail(entry,
                       "'" + w + "' is not a face of this "
                         + std::to_string(dim)
                         + "D box; write 'all', 'none' or a list of x-, x+, "
                           "y-, y+"
                         + (dim == 3 ? ", z-, z+ (mantle: a column's side)." :
                                       "."));
                faces[it - names.begin()] = true;
              }
          }
        return faces;
      };
      walls           = read_faces("Domain walls");
      symmetry_planes = read_faces("Symmetry planes");
      substeps        = prm.get_integer("Rigid substeps");
      containment_backend
        = core::choice_named(backend_names, prm.get("Containment backend"));
      covered_nodes
        = core::choice_named(covered_nodes_names, prm.get("Covered nodes"));
      part_films
        = core::choice_named(part_films_names, prm.get("Films between parts"));
      prm.leave_subsection();
      if (containment_backend == ContainmentBackend::cuda
          && covered_nodes != CoveredNodes::inside)
        fail("Containment backend",
             "the cuda containment engine marks the nodes inside the "
             "particles only; set 'Covered nodes = inside' or choose "
             "'Containment backend = cpu' (or 'auto').");
      if (containment_backend == ContainmentBackend::cuda
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
      if (bodies.empty())
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
      if (containment_backend == ContainmentBackend::cuda)
        for (const ParticleDescription &p : bodies)
          if (!containment_engine_takes(*p.shape, dim))
            fail("Containment backend",
                 "the cuda containment engine takes spheres, surface meshes "
                 "and 2D disks only, and "
                   + p.origin + " is a " + p.shape->name()
                   + "; set 'cpu' or 'auto'.");
    }



    bool
    ParticleParameters::any(const ParticleMotion motion) const
    {
      return std::any_of(bodies.begin(),
                         bodies.end(),
                         [&](const ParticleDescription &p) {
                           return p.motion == motion;
                         });
    }
  } // namespace fbm
} // namespace particulate
