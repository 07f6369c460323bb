#include <particulate/fbm/particle_file.h>
#include <particulate/fbm/particle_generators.h>
#include <particulate/fbm/particle_set_checks.h>
#include <particulate/fbm/particle_set_parameters.h>
#include <particulate/fbm/shape_template.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "entry_values.h"

namespace particulate {
  namespace fbm {
    using namespace dealii;

    namespace {
      const std::string particles_section = "Particles";

      /** Where the entries of one list subsection are, for messages. */
      struct Place
      {
        const core::InputOutline &outline;
        std::vector<std::string>  path;

        std::string
        operator()(const std::string &entry = "") const
        {
          return outline.where(path, entry);
        }
      };

      void
      declare_shape_entry(ParameterHandler &prm)
      {
        prm.declare_entry("Shape",
                          "",
                          Patterns::Anything(),
                          "The name of the particles' shape: a subsection "
                          "'Shape <name>' of subsection 'Particles' (which "
                          "gives the solid, its size and its density).");
      }

      void
      declare_orientation(ParameterHandler &prm)
      {
        prm.declare_entry("Orientation axis",
                          "0, 0, 1",
                          Patterns::Anything(),
                          "The orientation turns the body frame of the "
                          "shape by 'Orientation angle' about this world "
                          "axis (3 components; 2D runs turn about z only).");
        prm.declare_entry("Orientation angle",
                          "0",
                          Patterns::Double(),
                          "Angle [rad] of the initial orientation about "
                          "'Orientation axis'.");
        prm.declare_entry("Orientation quaternion",
                          "",
                          Patterns::Anything(),
                          "The initial orientation as a unit quaternion w, "
                          "x, y, z (body to world), instead of the axis and "
                          "angle; empty: use those.");
      }

      Eigen::Quaterniond
      read_orientation(const ParameterHandler &prm,
                       const unsigned int      dim,
                       const Place            &place)
      {
        const std::string quaternion
          = Utilities::trim(prm.get("Orientation quaternion"));
        const Eigen::Vector3d axis
          = internal::read_vector(prm.get("Orientation axis"),
                                  3,
                                  place("Orientation axis"));
        const double       angle = prm.get_double("Orientation angle");
        Eigen::Quaterniond q     = Eigen::Quaterniond::Identity();
        if (!quaternion.empty())
          {
            if (angle != 0.)
              internal::fail_at(place("Orientation quaternion"),
                                "give the orientation either as a quaternion "
                                "or by 'Orientation angle', not both.");
            q = internal::read_quaternion(quaternion,
                                          place("Orientation quaternion"));
          }
        else
          q = internal::rotation_about(axis, angle, place("Orientation axis"));
        if (dim == 2 && q.vec().head<2>().norm() > 1e-12)
          internal::fail_at(place(quaternion.empty() ?
                                    "Orientation axis" :
                                    "Orientation quaternion"),
                            "a 2D run turns bodies about z only.");
        return q;
      }

      void
      declare_motion(ParameterHandler &prm, const bool prescribed)
      {
        prm.declare_entry(
          "Motion",
          "free",
          Patterns::Selection(prescribed ? "free|fixed|prescribed|hinged" :
                                           "free|fixed"),
          prescribed ?
            "'free': moves under the fluid force, buoyancy-corrected "
            "gravity and contacts (thesis eq. 5.3). 'fixed': stays at rest, "
            "an obstacle of the flow and of the contacts. 'prescribed': "
            "moves by 'Prescribed displacement' and 'Prescribed rotation' "
            "(e.g. an oscillating cylinder, thesis §6.3), whatever the fluid "
            "does. 'hinged': a part of an articulated body (a swimmer's "
            "shell, thesis §6.5), carried by the particle 'Hinged to' and "
            "turned relative to it by 'Hinge angle' about 'Hinge axis' "
            "through 'Hinge point'; its loads move that particle, which "
            "carries its mass. The parts of one body do not collide with "
            "each other; with other particles and the walls, a part is an "
            "obstacle that gives way to nothing." :
            "'free': the particles move under the fluid force, gravity and "
            "contacts. 'fixed': they stay at rest (obstacles).");
      }

      ParticleMotion
      read_motion(const ParameterHandler &prm)
      {
        const std::string m = prm.get("Motion");
        return m == "fixed"      ? ParticleMotion::fixed :
               m == "prescribed" ? ParticleMotion::prescribed :
               m == "hinged"     ? ParticleMotion::hinged :
                                   ParticleMotion::free;
      }

      /** The velocity entry, 0 when empty. */
      Eigen::Vector3d
      read_optional_vector(const ParameterHandler &prm,
                           const std::string      &entry,
                           const unsigned int      n,
                           const Place            &place)
      {
        const std::string text = prm.get(entry);
        if (Utilities::trim(text).empty())
          return Eigen::Vector3d::Zero();
        return internal::read_vector(text, n, place(entry));
      }

      /** A particle of @p shape with what all ways of describing one
       *  share. */
      ParticleDescription
      particle_of(const ShapeLibrary::Entry &shape, const std::string &origin)
      {
        ParticleDescription p;
        p.shape      = shape.shape;
        p.shape_name = shape.description.name;
        p.density    = shape.description.density;
        p.origin     = origin;
        return p;
      }

      /** The expressions of a prescribed motion have their component
       *  counts (checked here, before any work). */
      void
      check_prescribed_motion(const ParticleDescription &p,
                              const unsigned int         dim,
                              const Place               &place)
      {
        const auto check = [&](const core::FunctionExpression &f,
                               const std::string              &entry,
                               const unsigned int              n) {
          try
            {
              if (dim == 2)
                f.create<2>(n, entry);
              else
                f.create<3>(n, entry);
            }
          catch (const std::exception &e)
            {
              internal::fail_at(place(entry), e.what());
            }
        };
        check(p.prescribed_displacement, "Prescribed displacement", dim);
        check(p.prescribed_rotation, "Prescribed rotation", dim == 2 ? 1 : 3);
      }

      void
      declare_hinge(ParameterHandler &prm)
      {
        prm.declare_entry("Hinged to",
                          "",
                          Patterns::Anything(),
                          "'Motion = hinged': the number n of the 'Particle "
                          "n' that carries this part (free, fixed or "
                          "prescribed; not itself hinged).");
        prm.declare_entry("Hinge point",
                          "",
                          Patterns::Anything(),
                          "'Motion = hinged': a point [m] on the hinge's "
                          "axis, one coordinate per space dimension, with "
                          "the parent where it starts.");
        prm.declare_entry("Hinge axis",
                          "0, 0, 1",
                          Patterns::Anything(),
                          "'Motion = hinged': the hinge's axis (3 "
                          "components, world frame with the parent where it "
                          "starts; 2D runs turn about z only).");
        core::FunctionExpression::declare(
          prm,
          "Hinge angle",
          "",
          "'Motion = hinged': the angle beta(t) [rad] by which the part is "
          "turned about the hinge's axis (right-handed) from the pose that "
          "'Position' and the orientation give it, one expression in t, "
          "e.g. 'if(t < 1, t, 2 - t)'. The turn's rate is its time "
          "derivative, taken numerically.");
      }

      /** A point or axis entry holds no value. */
      bool
      is_empty(const ParameterHandler &prm, const std::string &entry)
      {
        return Utilities::trim(prm.get(entry)).empty();
      }

      /** The hinge of a part ('Motion = hinged'); for another motion, the
       *  hinge's entries must be left out. Its parent is checked with the
       *  whole set (check_hinges()). */
      void
      read_hinge(const ParameterHandler &prm,
                 ParticleDescription    &p,
                 const unsigned int      dim,
                 const Place            &place)
      {
        p.hinge.angle.parse(prm, "Hinge angle");
        if (p.motion != ParticleMotion::hinged)
          {
            if (!is_empty(prm, "Hinged to") || !is_empty(prm, "Hinge point")
                || !Utilities::trim(p.hinge.angle.expression).empty())
              internal::fail_at(place("Motion"),
                                "a hinge ('Hinged to', 'Hinge point' or "
                                "'Hinge angle') is given, but the motion is "
                                "not 'hinged'; set 'Motion = hinged' or "
                                "remove them.");
            return;
          }
        for (const std::string entry : {"Hinged to", "Hinge point"})
          if (is_empty(prm, entry))
            internal::fail_at(place(entry),
                              "'Motion = hinged' needs '" + entry + "'.");
        const double parent
          = internal::read_numbers(prm.get("Hinged to"), 1, place("Hinged to"))
              .front();
        if (!(parent >= 0.) || parent != std::floor(parent))
          internal::fail_at(place("Hinged to"),
                            "write the number n of a 'Particle n'.");
        p.hinge.parent = static_cast<unsigned int>(parent);
        p.hinge.point  = internal::read_vector(prm.get("Hinge point"),
                                              dim,
                                              place("Hinge point"));
        const Eigen::Vector3d axis
          = internal::read_vector(prm.get("Hinge axis"),
                                  3,
                                  place("Hinge axis"));
        const double largest = axis.cwiseAbs().maxCoeff();
        if (!(largest > 0.))
          internal::fail_at(place("Hinge axis"), "the axis must not be zero.");
        p.hinge.axis = (axis / largest).normalized();
        if (dim == 2 && p.hinge.axis.head<2>().norm() > 1e-12)
          internal::fail_at(place("Hinge axis"),
                            "a 2D run turns bodies about z only.");
        try
          {
            if (dim == 2)
              p.hinge.angle.create<2>(1, "Hinge angle");
            else
              p.hinge.angle.create<3>(1, "Hinge angle");
          }
        catch (const std::exception &e)
          {
            internal::fail_at(place("Hinge angle"), e.what());
          }
      }

      /** Each part is hinged to another 'Particle n' that is not hinged
       *  itself. @p labels are the particles' subsection labels. */
      void
      check_hinges(const std::vector<ParticleDescription> &particles,
                   const std::vector<std::string>         &labels,
                   const core::InputOutline               &outline)
      {
        for (unsigned int i = 0; i < particles.size(); ++i)
          {
            const ParticleDescription &p = particles[i];
            if (p.motion != ParticleMotion::hinged)
              continue;
            const std::string where
              = outline.where({particles_section, "Particle " + labels[i]},
                              "Hinged to");
            const unsigned int parent = p.hinge.parent;
            if (parent >= particles.size())
              internal::fail_at(where,
                                "there is no 'Particle "
                                  + std::to_string(parent) + "'.");
            if (parent == i)
              internal::fail_at(where, "a part cannot be hinged to itself.");
            if (particles[parent].motion == ParticleMotion::hinged)
              internal::fail_at(where,
                                "'Particle " + std::to_string(parent)
                                  + "' is itself hinged; hinge every part "
                                    "to the body's head.");
          }
      }

      void
      declare_particle(ParameterHandler &prm)
      {
        declare_shape_entry(prm);
        prm.declare_entry("Position",
                          "",
                          Patterns::Anything(),
                          "Initial centre [m], one coordinate per space "
                          "dimension separated by ','.");
        declare_orientation(prm);
        prm.declare_entry("Velocity",
                          "",
                          Patterns::Anything(),
                          "Initial velocity [m/s] of a free particle, like "
                          "'Position' (empty: at rest).");
        prm.declare_entry("Angular velocity",
                          "",
                          Patterns::Anything(),
                          "Initial angular velocity [rad/s] of a free "
                          "particle: 3 components in 3D, the one about z in "
                          "2D (empty: none).");
        declare_motion(prm, true);
        core::FunctionExpression::declare(
          prm,
          "Prescribed displacement",
          "",
          "'Motion = prescribed': the displacement d(t) [m] from 'Position', "
          "one expression in t per space dimension (x, y and z are not "
          "used), e.g. 'A*sin(2*pi*f*t); 0' with 'A=0.25, f=0.25' in the "
          "constants entry. The velocity is its time derivative, taken "
          "numerically.");
        core::FunctionExpression::declare(
          prm,
          "Prescribed rotation",
          "",
          "'Motion = prescribed': the rotation phi(t) [rad] applied to the "
          "initial orientation: in 3D a rotation vector (3 expressions in t, "
          "world axes, its length the angle), in 2D the angle about z (one "
          "expression). The angular velocity is its time derivative, taken "
          "numerically.");
        declare_hinge(prm);
      }

      ParticleDescription
      read_particle(const ParameterHandler &prm,
                    const ShapeLibrary     &shapes,
                    const unsigned int      dim,
                    const Place            &place)
      {
        const auto &shape
          = shapes.find(Utilities::trim(prm.get("Shape")), place("Shape"));
        ParticleDescription p = particle_of(shape, place());
        p.position
          = internal::read_vector(prm.get("Position"), dim, place("Position"));
        p.orientation
          = shape.body_orientation(read_orientation(prm, dim, place));
        p.velocity = read_optional_vector(prm, "Velocity", dim, place);
        const std::string omega = prm.get("Angular velocity");
        if (!Utilities::trim(omega).empty())
          p.angular_velocity
            = internal::read_angular_velocity(omega,
                                              dim,
                                              place("Angular velocity"));
        p.motion = read_motion(prm);
        p.prescribed_displacement.parse(prm, "Prescribed displacement");
        p.prescribed_rotation.parse(prm, "Prescribed rotation");
        if (p.motion == ParticleMotion::prescribed)
          check_prescribed_motion(p, dim, place);
        else if (!Utilities::trim(p.prescribed_displacement.expression).empty()
                 || !Utilities::trim(p.prescribed_rotation.expression).empty())
          internal::fail_at(place("Motion"),
                            "a prescribed displacement or rotation is given, "
                            "but the motion is not 'prescribed'; set 'Motion "
                            "= prescribed' or remove them.");
        read_hinge(prm, p, dim, place);
        return p;
      }

      void
      declare_lattice(ParameterHandler &prm)
      {
        declare_shape_entry(prm);
        prm.declare_entry("First position",
                          "",
                          Patterns::Anything(),
                          "Centre [m] of the lattice's first particle (the "
                          "one with the smallest coordinates).");
        prm.declare_entry("Spacing",
                          "",
                          Patterns::Anything(),
                          "Distance [m] between neighbouring centres along "
                          "x, y (and z).");
        prm.declare_entry("Counts",
                          "1, 1, 1",
                          Patterns::List(Patterns::Integer(1), 2, 3),
                          "Number of particles along x, y (and z).");
        declare_orientation(prm);
        prm.declare_entry("Velocity",
                          "",
                          Patterns::Anything(),
                          "Initial velocity [m/s] of every particle (empty: "
                          "at rest).");
        declare_motion(prm, false);
      }

      std::vector<ParticleDescription>
      read_lattice(const ParameterHandler &prm,
                   const ShapeLibrary     &shapes,
                   const unsigned int      dim,
                   const Place            &place)
      {
        const auto &shape
          = shapes.find(Utilities::trim(prm.get("Shape")), place("Shape"));
        ParticleLattice lattice;
        lattice.first = internal::read_vector(prm.get("First position"),
                                              dim,
                                              place("First position"));
        lattice.spacing
          = internal::read_vector(prm.get("Spacing"), dim, place("Spacing"));
        const auto counts
          = internal::read_numbers(prm.get("Counts"), dim, place("Counts"));
        for (unsigned int d = 0; d < dim; ++d)
          lattice.counts[d] = static_cast<unsigned int>(counts[d]);
        const Eigen::Quaterniond q
          = shape.body_orientation(read_orientation(prm, dim, place));
        const Eigen::Vector3d v
          = read_optional_vector(prm, "Velocity", dim, place);
        const ParticleMotion             motion = read_motion(prm);
        std::vector<ParticleDescription> particles;
        std::vector<Eigen::Vector3d>     centres;
        try
          {
            centres = lattice.centres(dim);
          }
        catch (const std::runtime_error &e)
          {
            internal::fail_at(place("Counts"), e.what());
          }
        for (unsigned int i = 0; i < centres.size(); ++i)
          {
            ParticleDescription p = particle_of(shape,
                                                place() + ", lattice particle "
                                                  + std::to_string(i));
            p.position            = centres[i];
            p.orientation         = q;
            p.velocity            = v;
            p.motion              = motion;
            particles.push_back(p);
          }
        return particles;
      }

      void
      declare_random_fill(ParameterHandler &prm)
      {
        declare_shape_entry(prm);
        prm.declare_entry("Lower corner",
                          "",
                          Patterns::Anything(),
                          "Lower corner [m] of the box the particles fill "
                          "(they lie wholly inside it).");
        prm.declare_entry("Upper corner",
                          "",
                          Patterns::Anything(),
                          "Upper corner [m] of that box.");
        prm.declare_entry("Region",
                          "box",
                          Patterns::Selection("box|cylinder"),
                          "What the particles fill: 'box', or 'cylinder', "
                          "the circular cylinder along z inscribed in the "
                          "box (axis through the centre of its x-y "
                          "rectangle, radius half the rectangle's shorter "
                          "side; 3D), e.g. the part of a 'column' mesh "
                          "between two heights.");
        prm.declare_entry("Solid fraction",
                          "0.1",
                          Patterns::Double(0., 1.),
                          "Volume (2D: area) of the particles over that of "
                          "the region: the number of particles.");
        prm.declare_entry("Seed",
                          "1",
                          Patterns::Integer(0),
                          "Seed of the random numbers: the same seed gives "
                          "the same particles on every machine.");
        prm.declare_entry("Clearance",
                          "0",
                          Patterns::Double(0.),
                          "Smallest gap [m] the fill leaves between its "
                          "particles, and between them, the particles placed "
                          "before it and the boundary of its region (measured "
                          "between the balls that hold the particles). A run "
                          "refuses particles that start closer than "
                          "'Contact distance': give at least that.");
        prm.declare_entry("Random orientation",
                          "false",
                          Patterns::Bool(),
                          "Whether each particle is turned at random "
                          "(uniformly over all rotations; about z in 2D) "
                          "instead of by the orientation entries.");
        declare_orientation(prm);
        declare_motion(prm, false);
      }

      std::vector<ParticleDescription>
      read_random_fill(const ParameterHandler                 &prm,
                       const ShapeLibrary                     &shapes,
                       const unsigned int                      dim,
                       const Place                            &place,
                       const std::vector<ParticleDescription> &placed)
      {
        const auto &shape
          = shapes.find(Utilities::trim(prm.get("Shape")), place("Shape"));
        RandomFill fill;
        fill.lower              = internal::read_vector(prm.get("Lower corner"),
                                           dim,
                                           place("Lower corner"));
        fill.upper              = internal::read_vector(prm.get("Upper corner"),
                                           dim,
                                           place("Upper corner"));
        fill.region             = prm.get("Region") == "cylinder" ?
                                    RandomFill::Region::cylinder :
                                    RandomFill::Region::box;
        fill.solid_fraction     = prm.get_double("Solid fraction");
        fill.seed               = prm.get_integer("Seed");
        fill.clearance          = prm.get_double("Clearance");
        fill.random_orientation = prm.get_bool("Random orientation");
        const Eigen::Quaterniond q
          = shape.body_orientation(read_orientation(prm, dim, place));
        std::vector<OccupiedBall> occupied;
        for (const auto &p : placed)
          occupied.push_back({p.position, placement_radius(*p.shape, dim)});
        std::vector<geometry::Pose> poses;
        try
          {
            poses = fill.place(*shape.shape, dim, q, occupied);
          }
        catch (const std::runtime_error &e)
          {
            internal::fail_at(place(), e.what());
          }
        const ParticleMotion             motion = read_motion(prm);
        std::vector<ParticleDescription> particles;
        for (unsigned int i = 0; i < poses.size(); ++i)
          {
            ParticleDescription p
              = particle_of(shape,
                            place() + ", random particle " + std::to_string(i));
            p.position    = poses[i].translation();
            p.orientation = Eigen::Quaterniond(poses[i].rotation());
            p.motion      = motion;
            particles.push_back(p);
          }
        return particles;
      }

      /** The particles' numbers are 0, 1, ..., n-1: @p labels in the order
       *  of their numbers. */
      std::vector<std::string>
      numbered(const std::vector<std::string> &labels,
               const core::InputOutline       &outline)
      {
        std::vector<std::pair<unsigned long, std::string>> by_number;
        for (const std::string &label : labels)
          {
            const std::string where
              = outline.where({particles_section, "Particle " + label});
            if (label.find_first_not_of("0123456789") != std::string::npos)
              internal::fail_at(where,
                                "a particle's label is its number 0, 1, 2, "
                                "...; write e.g. 'subsection Particle 0'.");
            by_number.emplace_back(std::stoul(label), label);
          }
        std::sort(by_number.begin(), by_number.end());
        std::vector<std::string> ordered;
        for (unsigned long i = 0; i < by_number.size(); ++i)
          {
            if (by_number[i].first != i)
              internal::fail_at(
                outline.where(
                  {particles_section, "Particle " + by_number[i].second}),
                "particles are numbered 0, 1, 2, ... without gaps or "
                "repeats, and there is no 'Particle "
                  + std::to_string(i) + "'.");
            ordered.push_back(by_number[i].second);
          }
        return ordered;
      }
    } // namespace



    ParticleSetLayout
    ParticleSetLayout::of(const core::InputOutline &outline)
    {
      ParticleSetLayout layout;
      layout.shapes       = outline.labels({particles_section}, "Shape");
      layout.particles    = outline.labels({particles_section}, "Particle");
      layout.lattices     = outline.labels({particles_section}, "Lattice");
      layout.random_fills = outline.labels({particles_section}, "Random fill");
      return layout;
    }



    ParticleSetLayout
    ParticleSetLayout::documentation()
    {
      return {{"<name>"}, {"<n>"}, {"<name>"}, {"<name>"}};
    }



    void
    declare_particle_set(ParameterHandler &prm, const ParticleSetLayout &layout)
    {
      prm.declare_entry("Particle file",
                        "",
                        Patterns::Anything(),
                        "A file of particles, one per line after a header "
                        "line naming the columns (values separated by ',' "
                        "or blanks): shape, x, y (z), and optionally vx, vy "
                        "(vz), omega (2D) or omega_x, omega_y, omega_z, "
                        "angle (2D; 3D with axis_x, axis_y, axis_z) or qw, "
                        "qx, qy, qz, and motion (free or fixed). A relative "
                        "path starts at the case file's folder. Empty: "
                        "none.");
      const auto declare_all = [&](const std::vector<std::string> &labels,
                                   const std::string              &prefix,
                                   void (*declare)(ParameterHandler &)) {
        for (const std::string &label : labels)
          {
            prm.enter_subsection(prefix + " " + label);
            declare(prm);
            prm.leave_subsection();
          }
      };
      declare_all(layout.shapes, "Shape", &ShapeTemplate::declare);
      declare_all(layout.particles, "Particle", &declare_particle);
      declare_all(layout.lattices, "Lattice", &declare_lattice);
      declare_all(layout.random_fills, "Random fill", &declare_random_fill);
    }



    std::vector<ParticleDescription>
    read_particle_set(ParameterHandler         &prm,
                      const unsigned int        dim,
                      const core::InputOutline &outline)
    {
      const ParticleSetLayout layout = ParticleSetLayout::of(outline);
      const auto in_subsection       = [&](const std::string &name, auto read) {
        prm.enter_subsection(name);
        const Place place{outline, {particles_section, name}};
        auto        result = read(place);
        prm.leave_subsection();
        return result;
      };

      ShapeLibrary shapes;
      for (const std::string &label : layout.shapes)
        in_subsection("Shape " + label, [&](const Place &place) {
          ShapeTemplate shape;
          shape.parse(prm, label, dim, outline, place.path);
          shapes.add(shape);
          return 0;
        });

      std::vector<ParticleDescription> particles;
      const std::vector<std::string>   labels
        = numbered(layout.particles, outline);
      for (const std::string &label : labels)
        particles.push_back(
          in_subsection("Particle " + label, [&](const Place &place) {
            return read_particle(prm, shapes, dim, place);
          }));
      check_hinges(particles, labels, outline);

      const std::string file = Utilities::trim(prm.get("Particle file"));
      if (!file.empty())
        {
          std::filesystem::path path(file);
          if (path.is_relative())
            path
              = std::filesystem::path(outline.filename()).parent_path() / path;
          const auto from_file = read_particle_file(path.string(), shapes, dim);
          particles.insert(particles.end(), from_file.begin(), from_file.end());
        }
      for (const std::string &label : layout.lattices)
        {
          const auto lattice
            = in_subsection("Lattice " + label, [&](const Place &place) {
                return read_lattice(prm, shapes, dim, place);
              });
          particles.insert(particles.end(), lattice.begin(), lattice.end());
        }
      for (const std::string &label : layout.random_fills)
        {
          const auto fill
            = in_subsection("Random fill " + label, [&](const Place &place) {
                return read_random_fill(prm, shapes, dim, place, particles);
              });
          particles.insert(particles.end(), fill.begin(), fill.end());
        }
      check_no_overlap(particles, dim);
      return particles;
    }
  } // namespace fbm
} // namespace particulate
