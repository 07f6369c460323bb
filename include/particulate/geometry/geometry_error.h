#ifndef particulate_geometry_geometry_error_h
#define particulate_geometry_geometry_error_h

#include <stdexcept>
#include <string>

namespace particulate {
  namespace geometry {

    /**
     * Thrown for input the geometry module cannot use: an unreadable or broken
     * surface mesh, a parameter out of range, a corrupt cache file. The message
     * says what is wrong, where, and what to do about it.
     */
    class GeometryError : public std::runtime_error
    {
    public:
      /** @param message the full sentence shown to the user */
      explicit GeometryError(const std::string &message)
        : std::runtime_error(message)
      {}
    };

  } // namespace geometry
} // namespace particulate

#endif
