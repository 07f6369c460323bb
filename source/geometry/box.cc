#include <particulate/geometry/box.h>
#include <particulate/geometry/geometry_error.h>

namespace particulate::geometry {

  Box::Box(const Eigen::Vector3d &half_extents)
    : h(half_extents)
  {
    if (!(half_extents.array() > 0.).all() || !half_extents.allFinite())
      throw GeometryError("Box: all half extents must be positive and finite.");
  }

  double
  Box::signed_distance(const Eigen::Vector3d &p, Eigen::Vector3d *normal) const
  {
    // q_i > 0: p is beyond face pair i. Outside, the distance is the length of
    // the positive part of q; inside, the largest (least negative) q_i.
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

} // namespace particulate::geometry
