#include <particulate/rigid/sphere.h>

#include <cmath>
#include <stdexcept>

namespace particulate::rigid {
  namespace {
    /** The 26 directions to the neighbours of a cube cell, normalised: a
     * cheap, symmetric sampling of the unit sphere. */
    std::vector<Eigen::Vector3d>
    sphere_directions()
    {
      std::vector<Eigen::Vector3d> d;
      for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
          for (int k = -1; k <= 1; ++k)
            if (i != 0 || j != 0 || k != 0)
              d.push_back(Eigen::Vector3d(i, j, k).normalized());
      return d;
    }
  } // namespace

  Sphere::Sphere(const double r)
    : radius(r)
  {
    if (!(r > 0.) || !std::isfinite(r))
      throw std::invalid_argument("rigid::Sphere: the radius must be a "
                                  "positive finite length in m, got "
                                  + std::to_string(r) + ".");
  }
  ShapeType
  Sphere::type() const
  {
    return ShapeType::sphere;
  }
  std::string
  Sphere::name() const
  {
    return "sphere";
  }
  double
  Sphere::volume() const
  {
    return 4. / 3. * M_PI * radius * radius * radius;
  }
  Eigen::Vector3d
  Sphere::unit_density_inertia() const
  {
    return Eigen::Vector3d::Constant(0.4 * volume() * radius * radius);
  }
  double
  Sphere::bounding_radius() const
  {
    return radius;
  }
  double
  Sphere::signed_distance(const Eigen::Vector3d &p) const
  {
    return p.norm() - radius;
  }
  Eigen::Vector3d
  Sphere::gradient(const Eigen::Vector3d &p) const
  {
    const double n = p.norm();
    return n > 0. ? Eigen::Vector3d(p / n) : Eigen::Vector3d::UnitZ();
  }
  Eigen::Vector3d
  Sphere::support(const Eigen::Vector3d &d) const
  {
    const double n = d.norm();
    return n > 0. ? Eigen::Vector3d(radius / n * d) :
                    Eigen::Vector3d(0, 0, radius);
  }
  std::vector<Eigen::Vector3d>
  Sphere::surface_points() const
  {
    auto d = sphere_directions();
    for (auto &p : d)
      p *= radius;
    return d;
  }
} // namespace particulate::rigid
