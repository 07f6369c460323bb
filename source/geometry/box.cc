#include <particulate/geometry/box.h>
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_generators.h>

#include "shape_formulas.h"

namespace particulate {
  namespace geometry {

    Box::Box(const Eigen::Vector3d &half_extents)
      : h(half_extents)
    {
      if (!(half_extents.array() > 0.).all() || !half_extents.allFinite())
        throw GeometryError("Box: all three half extents must be positive "
                            "finite lengths in m (half, not full, edge "
                            "lengths).");
    }

    double
    Box::signed_distance(const Eigen::Vector3d &p,
                         Eigen::Vector3d       *normal) const
    {
      // q_i > 0: p is beyond face pair i. Outside, the distance is the length
      // of the positive part of q; inside, the largest (least negative) q_i.
      const Eigen::Vector3d q = p.cwiseAbs() - h;
      const Eigen::Vector3d s(p[0] < 0. ? -1. : 1.,
                              p[1] < 0. ? -1. : 1.,
                              p[2] < 0. ? -1. : 1.);
      if ((q.array() > 0.).any())
        {
          const Eigen::Vector3d out = q.cwiseMax(0.);
          const double          d   = out.norm();
          if (normal)
            *normal = s.cwiseProduct(out) / d;
          return d;
        }
      int          axis = 0;
      const double d    = q.maxCoeff(&axis);
      if (normal)
        {
          normal->setZero();
          (*normal)[axis] = s[axis];
        }
      return d;
    }

    BoundingBox
    Box::bounding_box() const
    {
      return BoundingBox(-h, h);
    }

    double
    Box::volume() const
    {
      return 8. * h.prod();
    }



    Eigen::Matrix3d
    Box::unit_inertia() const
    {
      return detail::axis_aligned_inertia(3., volume(), h);
    }



    Eigen::Vector3d
    Box::support(const Eigen::Vector3d &d) const
    {
      return Eigen::Vector3d(d[0] >= 0. ? h[0] : -h[0],
                             d[1] >= 0. ? h[1] : -h[1],
                             d[2] >= 0. ? h[2] : -h[2]);
    }



    std::vector<Eigen::Vector3d>
    Box::surface_points() const
    {
      std::vector<Eigen::Vector3d> points = detail::cube_neighbour_directions();
      for (auto &p : points)
        p = h.cwiseProduct(p);
      return points;
    }



    TriangleMesh
    Box::surface_mesh() const
    {
      return mesh_generators::box(h);
    }

  } // namespace geometry
} // namespace particulate
