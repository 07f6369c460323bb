#ifndef particulate_geometry_pose_h
#define particulate_geometry_pose_h

#include <particulate/geometry/bounding_box.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace particulate {
  namespace geometry {

    /**
     * The placement of a rigid body: world point x = R * b + t for a body-frame
     * point b. The body frame is the one the body's geometry (and its distance
     * map) was built in, usually centred at the centre of mass with the
     * principal axes as coordinate axes (thesis §4.2.1). A world point is
     * brought into the body frame by b = R^T (x - t), the transformation of
     * §3.4.2.
     */
    class Pose
    {
    public:
      /** The identity pose. */
      Pose() = default;

      /**
       * @param rotation orthonormal matrix with determinant +1 (body to world)
       * @param translation position of the body-frame origin in the world [m]
       */
      Pose(const Eigen::Matrix3d &rotation, const Eigen::Vector3d &translation)
        : R(rotation)
        , t(translation)
      {}

      /** Same, with the rotation given as a unit quaternion. */
      Pose(const Eigen::Quaterniond &q, const Eigen::Vector3d &translation)
        : R(q.normalized().toRotationMatrix())
        , t(translation)
      {}

      /** World coordinates of the body-frame point @p b. */
      Eigen::Vector3d
      to_world(const Eigen::Vector3d &b) const
      {
        return R * b + t;
      }

      /** Body-frame coordinates of the world point @p x. */
      Eigen::Vector3d
      to_body(const Eigen::Vector3d &x) const
      {
        return R.transpose() * (x - t);
      }

      /** Rotate a body-frame direction into the world. */
      Eigen::Vector3d
      direction_to_world(const Eigen::Vector3d &v) const
      {
        return R * v;
      }

      /** Rotate a world direction into the body frame. */
      Eigen::Vector3d
      direction_to_body(const Eigen::Vector3d &v) const
      {
        return R.transpose() * v;
      }

      /**
       * The world-aligned box that contains the body-frame box @p b placed by
       * this pose (the box of its eight transformed corners).
       */
      BoundingBox
      to_world(const BoundingBox &b) const
      {
        BoundingBox out;
        for (int c = 0; c < 8; ++c)
          out.extend(
            to_world(Eigen::Vector3d(c & 1 ? b.upper[0] : b.lower[0],
                                     c & 2 ? b.upper[1] : b.lower[1],
                                     c & 4 ? b.upper[2] : b.lower[2])));
        return out;
      }

      /** Rotation, body to world. */
      const Eigen::Matrix3d &
      rotation() const
      {
        return R;
      }

      /** Position of the body-frame origin in the world [m]. */
      const Eigen::Vector3d &
      translation() const
      {
        return t;
      }

    private:
      Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
      Eigen::Vector3d t = Eigen::Vector3d::Zero();
    };

  } // namespace geometry
} // namespace particulate

#endif
