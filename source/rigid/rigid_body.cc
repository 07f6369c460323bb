#include <particulate/rigid/rigid_body.h>

#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace particulate {
  namespace rigid {
    namespace {
      /**
       * The principal moments of the shape's unit-density inertia. The body
       * frame of a rigid body is the principal frame (centroid at the origin,
       * principal axes along the body axes); a shape given in another frame
       * is refused with what to do.
       */
      Eigen::Vector3d
      principal_unit_inertia(const geometry::Shape &shape)
      {
        const Eigen::Matrix3d I     = shape.unit_inertia();
        const double          scale = std::cbrt(shape.volume());
        const double          size  = I.diagonal().maxCoeff();
        const Eigen::Matrix3d off
          = I - Eigen::Matrix3d(I.diagonal().asDiagonal());
        if (!(shape.centroid().norm() <= 1e-9 * scale)
            || !(off.cwiseAbs().maxCoeff() <= 1e-9 * size)
            || !(I.diagonal().minCoeff() > 0.))
          throw std::invalid_argument(
            "rigid::RigidBody: the " + shape.name()
            + " is not given in its principal frame: a dynamic body's shape "
              "must have its centroid at the origin and its principal axes of "
              "inertia along the body axes (move the surface mesh to the frame "
              "that geometry::MassProperties::principal_frame() gives).");
        return I.diagonal();
      }
    } // namespace

    RigidBody::RigidBody(std::shared_ptr<const geometry::Shape> shape,
                         const unsigned int                     material,
                         const double                           density,
                         const bool                             fixed)
      : shape_(std::move(shape))
      , material_(material)
      , fixed_(fixed)
      , inverse_mass_(0.)
      , inertia_(
          Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()))
      , inverse_inertia_(Eigen::Vector3d::Zero())
    {
      if (!shape_)
        throw std::invalid_argument("rigid::RigidBody: no shape given.");
      if (!shape_->is_bounded() && !fixed)
        throw std::invalid_argument(
          "rigid::RigidBody: a " + shape_->name()
          + " is unbounded and has infinite mass; add it as a fixed body.");
      if (!fixed)
        {
          if (!(density > 0.) || !std::isfinite(density))
            throw std::invalid_argument(
              "rigid::RigidBody: a dynamic body needs a positive finite "
              "density (kg/m^3); check the material.");
          const double m   = density * shape_->volume();
          inverse_mass_    = 1. / m;
          inertia_         = density * principal_unit_inertia(*shape_);
          inverse_inertia_ = inertia_.cwiseInverse();
        }
    }



    void
    RigidBody::set_mass_properties(const double           mass,
                                   const Eigen::Vector3d &principal_inertia)
    {
      if (fixed_)
        throw std::invalid_argument(
          "rigid::RigidBody::set_mass_properties(): a fixed body has no "
          "mass to set.");
      if (!(mass > 0.) || !std::isfinite(mass)
          || !(principal_inertia.minCoeff() > 0.)
          || !principal_inertia.allFinite())
        throw std::invalid_argument(
          "rigid::RigidBody::set_mass_properties(): the mass and the "
          "principal moments must be positive and finite.");
      inverse_mass_    = 1. / mass;
      inertia_         = principal_inertia;
      inverse_inertia_ = inertia_.cwiseInverse();
    }



    double
    RigidBody::mass() const
    {
      return fixed_ ? std::numeric_limits<double>::infinity() :
                      1. / inverse_mass_;
    }



    Eigen::Matrix3d
    RigidBody::inertia_world() const
    {
      const Eigen::Matrix3d R = rotation();
      return R * inertia_.asDiagonal() * R.transpose();
    }



    Eigen::Matrix3d
    RigidBody::inverse_inertia_world() const
    {
      const Eigen::Matrix3d R = rotation();
      if (fixed_
          || !(rotation_locked_[0] || rotation_locked_[1]
               || rotation_locked_[2]))
        return R * inverse_inertia_.asDiagonal() * R.transpose();
      // invert the free block of I_w: locked rows and columns become those
      // of the identity for the inversion and zero afterwards
      Eigen::Matrix3d I = inertia_world();
      for (int a = 0; a < 3; ++a)
        if (rotation_locked_[a])
          {
            I.row(a).setZero();
            I.col(a).setZero();
            I(a, a) = 1.;
          }
      Eigen::Matrix3d inverse = I.inverse();
      for (int a = 0; a < 3; ++a)
        if (rotation_locked_[a])
          {
            inverse.row(a).setZero();
            inverse.col(a).setZero();
          }
      return inverse;
    }



    void
    RigidBody::lock_rotation(const std::array<bool, 3> &axes)
    {
      rotation_locked_ = axes;
      for (int a = 0; a < 3; ++a)
        if (axes[a])
          angular_velocity[a] = 0.;
    }



    void
    RigidBody::apply_impulse(const Eigen::Vector3d &P, const Eigen::Vector3d &p)
    {
      if (fixed_)
        return;
      linear_velocity += inverse_mass_ * P;
      angular_velocity += inverse_inertia_world() * (p - position).cross(P);
    }



    double
    RigidBody::kinetic_energy() const
    {
      if (fixed_)
        return 0.;
      const Eigen::Vector3d wb = orientation.conjugate() * angular_velocity;
      return 0.5
             * (linear_velocity.squaredNorm() / inverse_mass_
                + wb.dot(inertia_.cwiseProduct(wb)));
    }



    Eigen::Vector3d
    RigidBody::linear_momentum() const
    {
      return fixed_ ? Eigen::Vector3d::Zero() :
                      Eigen::Vector3d(linear_velocity / inverse_mass_);
    }



    Eigen::Vector3d
    RigidBody::angular_momentum() const
    {
      if (fixed_)
        return Eigen::Vector3d::Zero();
      const Eigen::Vector3d wb = orientation.conjugate() * angular_velocity;
      return position.cross(linear_momentum())
             + orientation * inertia_.cwiseProduct(wb);
    }
  } // namespace rigid
} // namespace particulate
