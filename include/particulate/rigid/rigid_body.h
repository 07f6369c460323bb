#ifndef particulate_rigid_rigid_body_h
#define particulate_rigid_rigid_body_h

#include <particulate/geometry/shape.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <memory>

namespace particulate {
  namespace rigid {
    /** Index of a body in its World (stable: bodies are never removed). */
    using BodyId = unsigned int;

    /**
     * One rigid body (thesis §4.2): its shape and material, its mass
     * properties in the principal frame, and its state. The body frame has its
     * origin at the centre of mass and its axes along the principal axes of
     * inertia; `orientation` maps body to world coordinates.
     *
     * The state members are public on purpose (as in Box2D/Bullet): the
     * fluid–particle coupling reads X, q, U, omega directly and adds the
     * hydrodynamic force and torque with add_force()/add_torque() before each
     * World::step(). All vectors are in the world frame unless stated.
     *
     * A fixed body has infinite mass: contacts never move it and the
     * integrator leaves it alone (walls, obstacles; thesis Fig. 3.10).
     */
    class RigidBody
    {
    public:
      /**
       * @param shape Geometry in the body frame (shared, may be reused by many
       * bodies).
       * @param material Index of the body's material in the World.
       * @param density Mass density in kg/m^3 (ignored for fixed bodies).
       * @param fixed Whether the body is immovable.
       */
      RigidBody(std::shared_ptr<const geometry::Shape> shape,
                unsigned int                           material,
                double                                 density,
                bool                                   fixed);

      /** @name State (public, SI units, world frame) */
      /** @{ */
      /** Centre of mass X in m. */
      Eigen::Vector3d position = Eigen::Vector3d::Zero();
      /** Unit quaternion q that rotates body coordinates into world ones. */
      Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
      /** Linear velocity U of the centre of mass in m/s. */
      Eigen::Vector3d linear_velocity = Eigen::Vector3d::Zero();
      /** Angular velocity omega in rad/s, world frame. */
      Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
      /** @} */

      /** @name Force and torque accumulators
       * Summed by add_force()/add_torque(); World::step() applies them over
       * the whole step (all substeps) and then clears them. Gravity and
       * buoyancy are added by the World, not here. */
      /** @{ */
      /** Accumulated external force in N. */
      Eigen::Vector3d force = Eigen::Vector3d::Zero();
      /** Accumulated external torque about the centre of mass in N m. */
      Eigen::Vector3d torque = Eigen::Vector3d::Zero();
      /** @} */

      /** Adds a force @p f (N) through the centre of mass. */
      void
      add_force(const Eigen::Vector3d &f)
      {
        force += f;
      }
      /** Adds a torque @p t (N m) about the centre of mass. */
      void
      add_torque(const Eigen::Vector3d &t)
      {
        torque += t;
      }
      /** Adds a force @p f (N) acting at the world point @p p (m). */
      void
      add_force_at(const Eigen::Vector3d &f, const Eigen::Vector3d &p)
      {
        force += f;
        torque += (p - position).cross(f);
      }
      /** Clears the force and torque accumulators. */
      void
      clear_accumulators()
      {
        force.setZero();
        torque.setZero();
      }

      /** Applies the impulse @p P (N s) at the world point @p p (m). */
      void
      apply_impulse(const Eigen::Vector3d &P, const Eigen::Vector3d &p);

      /** The shape (body frame). */
      const geometry::Shape &
      shape() const
      {
        return *shape_;
      }
      /** The shared pointer to the shape. */
      const std::shared_ptr<const geometry::Shape> &
      shape_ptr() const
      {
        return shape_;
      }
      /** Material index in the World. */
      unsigned int
      material() const
      {
        return material_;
      }
      /** Whether the body is fixed (infinite mass). */
      bool
      is_fixed() const
      {
        return fixed_;
      }
      /** Mass in kg (infinity for fixed bodies). */
      double
      mass() const;
      /**
       * Replaces the mass and principal moments that the shape and density
       * gave (a dynamic body only): for a body that stands for more than its
       * shape, the head of an articulated assembly carrying its parts.
       * @param mass in kg, positive
       * @param principal_inertia in kg m^2 about the body axes, positive
       * @throw std::invalid_argument for a fixed body or values that are
       *   not positive and finite
       */
      void
      set_mass_properties(double                 mass,
                          const Eigen::Vector3d &principal_inertia);
      /** 1/mass in 1/kg (0 for fixed bodies). */
      double
      inverse_mass() const
      {
        return inverse_mass_;
      }
      /** Volume in m^3. */
      double
      volume() const
      {
        return shape_->volume();
      }
      /** Bounding radius in m about the centre of mass. */
      double
      bounding_radius() const
      {
        return shape_->bounding_radius();
      }
      /** Principal moments of inertia in kg m^2 (body frame). */
      const Eigen::Vector3d &
      principal_inertia() const
      {
        return inertia_;
      }
      /** Inverse principal moments in 1/(kg m^2) (zero for fixed bodies). */
      const Eigen::Vector3d &
      inverse_principal_inertia() const
      {
        return inverse_inertia_;
      }
      /** Rotation matrix R (body to world). */
      Eigen::Matrix3d
      rotation() const
      {
        return orientation.toRotationMatrix();
      }
      /** Inertia tensor in the world frame, R I R^T (thesis eq. 4.30),
       *  kg m^2. */
      Eigen::Matrix3d
      inertia_world() const;
      /** Inverse inertia tensor in the world frame (zero for fixed bodies).
       * With locked rotation axes it is the inverse of the inertia restricted
       * to the free axes, zero along the locked ones, so that no torque or
       * contact impulse turns the body about them. */
      Eigen::Matrix3d
      inverse_inertia_world() const;

      /** Forbids rotation about the world axes flagged in @p axes (x, y, z),
       * e.g. x and y for a disk in a planar (2D) simulation: contacts away
       * from the body's mid-plane then cannot tilt it, and the whole impulse
       * goes into the in-plane motion. The angular velocity's components
       * about these axes are set to zero. */
      void
      lock_rotation(const std::array<bool, 3> &axes);
      /** Whether rotation about some world axis is locked. */
      bool
      rotation_locked() const
      {
        return rotation_locked_[0] || rotation_locked_[1]
               || rotation_locked_[2];
      }

      /** World point of the body-frame point @p p_body. */
      Eigen::Vector3d
      to_world(const Eigen::Vector3d &p_body) const
      {
        return position + orientation * p_body;
      }
      /** Body-frame coordinates of the world point @p p. */
      Eigen::Vector3d
      to_body(const Eigen::Vector3d &p) const
      {
        return orientation.conjugate() * (p - position);
      }
      /** Velocity in m/s of the material point at world position @p p:
       * U + omega x (p - X). */
      Eigen::Vector3d
      velocity_at(const Eigen::Vector3d &p) const
      {
        return linear_velocity + angular_velocity.cross(p - position);
      }
      /** Signed distance in m from the world point @p p to the body surface
       * (negative inside). */
      double
      signed_distance(const Eigen::Vector3d &p) const
      {
        return shape_->signed_distance(to_body(p));
      }
      /** Kinetic energy in J (0 for fixed bodies). */
      double
      kinetic_energy() const;
      /** Linear momentum m U in kg m/s. */
      Eigen::Vector3d
      linear_momentum() const;
      /** Angular momentum about the world origin, X x mU + I_w omega, in
       * kg m^2/s. */
      Eigen::Vector3d
      angular_momentum() const;

    private:
      std::array<bool, 3> rotation_locked_ = {{false, false, false}};
      std::shared_ptr<const geometry::Shape> shape_;
      unsigned int                           material_;
      bool                                   fixed_;
      double                                 inverse_mass_;
      Eigen::Vector3d                        inertia_;
      Eigen::Vector3d                        inverse_inertia_;
    };
  } // namespace rigid
} // namespace particulate

#endif
