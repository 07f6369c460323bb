#ifndef particulate_rigid_shape_h
#define particulate_rigid_shape_h

#include <Eigen/Core>

#include <string>
#include <vector>

namespace particulate::rigid {
  /** The kinds of shapes the narrow phase knows how to pair. The order is
   * used by the narrow-phase dispatch (lower kind is always body "a"). */
  enum class ShapeType
  {
    sphere          = 0,
    box             = 1,
    capsule         = 2,
    cylinder        = 3,
    ellipsoid       = 4,
    signed_distance = 5,
    half_space      = 6
  };

  /**
   * Abstract geometry of a rigid body, expressed in the body frame: the
   * origin is the centre of mass and the axes are the principal axes of
   * inertia. Every shape provides a signed distance (negative inside), its
   * gradient, a bounding radius about the origin and its volume and inertia
   * for unit density; convex shapes also provide a support function, which
   * GJK/EPA use (thesis §3.4.2). Meshes plug in through
   * SignedDistanceShape.
   */
  class Shape
  {
  public:
    virtual ~Shape() = default;

    /** Which concrete shape this is. */
    virtual ShapeType
    type() const = 0;

    /** Short name for messages and output ("sphere", "box", ...). */
    virtual std::string
    name() const = 0;

    /** Volume in m^3 (infinite for unbounded shapes). */
    virtual double
    volume() const = 0;

    /** Principal moments of inertia (about the body axes through the centre
     * of mass) for density 1 kg/m^3, in kg m^2 per (kg/m^3). */
    virtual Eigen::Vector3d
    unit_density_inertia() const = 0;

    /** Radius in m of a sphere about the body origin that contains the
     * shape (infinite for unbounded shapes). */
    virtual double
    bounding_radius() const = 0;

    /** Whether the shape is bounded (false only for half-spaces). */
    virtual bool
    is_bounded() const
    {
      return true;
    }

    /** Signed distance in m from @p p_body (body frame) to the surface;
     * negative inside. */
    virtual double
    signed_distance(const Eigen::Vector3d &p_body) const = 0;

    /** Gradient of signed_distance() at @p p_body (unit outward normal on
     * the surface). The default uses central differences. */
    virtual Eigen::Vector3d
    gradient(const Eigen::Vector3d &p_body) const;

    /** Whether support() is available. */
    virtual bool
    is_convex() const = 0;

    /** Support point: the point of the shape that lies furthest along the
     * body-frame direction @p d_body (need not be unit). Throws for shapes
     * that are not convex or not bounded. */
    virtual Eigen::Vector3d
    support(const Eigen::Vector3d &d_body) const;

    /** Radius of the sphere swept over the shape's core: r for spheres
     * (core: the centre) and capsules (core: the axis segment), 0 for the
     * rest. GJK works on the cores when they are apart, which is exact and
     * needs no EPA for shallow overlaps of round shapes. */
    virtual double
    core_radius() const
    {
      return 0.;
    }

    /** Representative points on the surface in the body frame (mesh
     * vertices for mesh shapes). Used to test non-convex shapes against the
     * signed distance of the partner. Default: none. */
    virtual std::vector<Eigen::Vector3d>
    surface_points() const
    {
      return {};
    }
  };
} // namespace particulate::rigid

#endif
