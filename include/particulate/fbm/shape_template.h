#ifndef particulate_fbm_shape_template_h
#define particulate_fbm_shape_template_h

#include <particulate/core/input_outline.h>
#include <particulate/geometry/shape.h>

#include <deal.II/base/parameter_handler.h>

#include <Eigen/Core>

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
        rectangle  ///< 2D: 'Half-extents'
      };

      std::string     name;
      Type            type    = Type::sphere;
      double          radius  = 0.;                      ///< [m]
      double          length  = 0.;                      ///< [m]
      Eigen::Vector3d extents = Eigen::Vector3d::Zero(); ///< [m]
      double          density = 0.;                      ///< [kg/m^3]

      /** Declare the entries of one `Shape <name>` subsection (entered). */
      static void
      declare(dealii::ParameterHandler &prm);

      /**
       * Read the entered subsection `Shape @p label` of a @p dim-dimensional
       * run; @p path is its subsection path, for messages.
       * @throw std::runtime_error naming the file, line and entry for a
       *   type of the other dimension or a missing or non-positive size
       */
      void
      parse(const dealii::ParameterHandler &prm,
            const std::string              &label,
            const unsigned int              dim,
            const core::InputOutline       &outline,
            const std::vector<std::string> &path);

      /** The solid in its body frame. */
      std::shared_ptr<const geometry::Shape>
      create() const;
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
