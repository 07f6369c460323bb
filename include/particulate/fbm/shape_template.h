#ifndef particulate_fbm_shape_template_h
#define particulate_fbm_shape_template_h

#include <particulate/core/input_outline.h>
#include <particulate/geometry/shape.h>

#include <deal.II/base/parameter_handler.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * subsection `Particles / Shape <name>`: a particle shape and material
     * defined once and used by any number of particles, which name it.
     *
     * A 2D run's bodies are prisms of unit depth along z (the rigid engine
     * is 3D; volume and inertia are per unit depth, and the flow's nodes lie
     * in the mid-plane z = 0): a disk is a circular cylinder, an ellipse an
     * elliptic cylinder, a rectangle a box, each of length 1 along z.
     */
    struct ShapeTemplate
    {
      /** The solids a case file can name. */
      enum class Type
      {
        sphere,    ///< 3D: 'Radius'
        ellipsoid, ///< 3D: 'Semi-axes' a, b, c
        box,       ///< 3D: 'Half-extents'
        cylinder,  ///< 3D: 'Radius', 'Length' along the body z axis
        capsule,   ///< 3D: 'Radius', 'Length' of the segment along body z
        disk,      ///< 2D: 'Radius'
        ellipse,   ///< 2D: 'Semi-axes' a, b
        rectangle, ///< 2D: 'Half-extents'
        mesh       ///< 3D: a closed surface mesh: 'File', 'Scale'
      };

      std::string     name;
      Type            type    = Type::sphere;
      double          radius  = 0.;                      ///< [m]
      double          length  = 0.;                      ///< [m]
      Eigen::Vector3d extents = Eigen::Vector3d::Zero(); ///< [m]
      double          density = 0.;                      ///< [kg/m^3]
      /// Type::mesh: the file (resolved against the case file's folder),
      /// the factor on its coordinates and the map spacing [m] (0:
      /// automatic)
      std::string mesh_file;
      double      mesh_scale  = 1.;
      double      map_spacing = 0.;
      /// the body frame's rotation as seen in the shape's own coordinates
      /// (a mesh file's; the identity for the analytic shapes): a particle
      /// given the orientation q is placed with q * frame_rotation, so that
      /// a mesh body looks as in its file turned by q
      Eigen::Quaterniond frame_rotation = Eigen::Quaterniond::Identity();

      /** Declare the entries of one `Shape <name>` subsection (entered). */
      static void
      declare(dealii::ParameterHandler &prm);

      /**
       * Read the entered subsection `Shape @p label` of a @p dim-dimensional
       * run; @p path is its subsection path, for messages. A mesh is read
       * and its distance map built here.
       * @throw std::runtime_error naming the file, line and entry for a
       *   type of the other dimension, a missing or non-positive size, or a
       *   mesh file that is missing or does not bound a solid
       */
      void
      parse(const dealii::ParameterHandler &prm,
            const std::string              &label,
            const unsigned int              dim,
            const core::InputOutline       &outline,
            const std::vector<std::string> &path);

      /** The solid in its body frame (a mesh's is the one parse() read). */
      std::shared_ptr<const geometry::Shape>
      create() const;

    private:
      /** Type::mesh: 'File', 'Scale' and 'Map spacing', then the mesh. */
      void
      read_mesh_entries(const dealii::ParameterHandler &prm,
                        const core::InputOutline       &outline,
                        const std::vector<std::string> &path);

      /** Type::mesh: read the file, move it to its principal frame and
       *  build its distance map (or read it from the cache).
       * @throw std::runtime_error naming @p where for a mesh that cannot be
       *   used */
      void
      load_mesh(const std::string &where);

      std::shared_ptr<const geometry::Shape> mesh;
    };

    /**
     * The shape templates of a case by name; each solid is made once and
     * shared by all particles of that shape.
     */
    class ShapeLibrary
    {
    public:
      /** A template and its solid. */
      struct Entry
      {
        ShapeTemplate                          description;
        std::shared_ptr<const geometry::Shape> shape;

        /** The orientation of a particle of this shape given the
         *  orientation @p q in the case (ShapeTemplate::frame_rotation). */
        Eigen::Quaterniond
        body_orientation(const Eigen::Quaterniond &q) const
        {
          return q * description.frame_rotation;
        }
      };

      void
      add(const ShapeTemplate &description);

      /**
       * The template called @p name.
       * @param where the file, line and entry that name it, for the message
       * @throw std::runtime_error if there is none, with the nearest name
       */
      const Entry &
      find(const std::string &name, const std::string &where) const;

    private:
      std::vector<Entry> entries;
    };
  } // namespace fbm
} // namespace particulate

#endif
