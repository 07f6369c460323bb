#ifndef particulate_rigid_scene_h
#define particulate_rigid_scene_h

#include <particulate/geometry/shape.h>
#include <particulate/rigid/material.h>
#include <particulate/rigid/world.h>

#include <memory>
#include <string>
#include <vector>

namespace particulate {
  namespace rigid {
    /** A shape by value, as an input file describes it. */
    struct ShapeDescription
    {
      /** Which shape. For geometry::ShapeKind::general set `custom`. */
      geometry::ShapeKind kind = geometry::ShapeKind::sphere;
      /** Sphere, cylinder, capsule radius in m. */
      double radius = 0.;
      /** Cylinder half height / capsule half length in m. */
      double half_length = 0.;
      /** Box half extents or ellipsoid semi-axes in m. */
      Eigen::Vector3d extents = Eigen::Vector3d::Zero();
      /** Half-space outward normal (body frame). */
      Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
      /** Half-space offset in m. */
      double offset = 0.;
      /** A ready-made shape (meshes); used when type is general. */
      std::shared_ptr<const geometry::Shape> custom;

      /** Builds the shape; throws std::invalid_argument with the reason for
       * inconsistent values. */
      std::shared_ptr<const geometry::Shape>
      create() const;
    };

    /** One body placed explicitly. */
    struct BodyDescription
    {
      /** Geometry. */
      ShapeDescription shape;
      /** Index into SceneDescription::materials. */
      unsigned int material = 0;
      /** Centre of mass in m. */
      Eigen::Vector3d position = Eigen::Vector3d::Zero();
      /** Body-to-world rotation. */
      Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
      /** Initial linear velocity in m/s. */
      Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
      /** Initial angular velocity in rad/s (world frame). */
      Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
      /** Whether the body is immovable. */
      bool fixed = false;
    };

    /** Radius distribution of poured spheres. */
    enum class SizeDistribution
    {
      /** Radius uniform in [min, max]. */
      uniform,
      /** log(radius) uniform in [log min, log max]. */
      log_uniform
    };

    /**
     * N spheres poured into an open box: the box becomes five fixed
     * half-spaces (floor and four sides, open at the top) and the spheres
     * start on a jittered lattice inside it, stacked upwards from the floor
     * as high as needed, with small random velocities.
     */
    struct PouringDescription
    {
      /** Number of spheres (0: no pouring). */
      unsigned int n_spheres = 0;
      /** Smallest and largest radius in m. */
      double radius_min = 0.01, radius_max = 0.01;
      /** Radius distribution. */
      SizeDistribution distribution = SizeDistribution::uniform;
      /** Lower corner of the box interior in m. */
      Eigen::Vector3d box_min = Eigen::Vector3d::Zero();
      /** Upper corner of the box interior in m (the top stays open). */
      Eigen::Vector3d box_max = Eigen::Vector3d::Ones();
      /** Material of the spheres and of the walls. */
      unsigned int material = 0;
      /** Seed of the random numbers (positions, radii, velocities). */
      unsigned int seed = 1;
      /** Magnitude in m/s of the random initial velocities. */
      double initial_speed = 0.01;

      /** The bodies: five walls first, then the spheres. */
      std::vector<BodyDescription>
      generate() const;
    };

    /**
     * Everything needed to run a rigid-body scene without a fluid. A later
     * parameter-file front end fills this struct; build_world() turns it into
     * a World.
     */
    struct SceneDescription
    {
      /** World settings (gravity, solver, substeps, margin, ...). */
      WorldParameters world;
      /** Materials; bodies refer to them by index. */
      std::vector<Material> materials = {Material()};
      /** Explicitly placed bodies. */
      std::vector<BodyDescription> bodies;
      /** Optional pouring generator (added after the explicit bodies). */
      PouringDescription pouring;
      /** Time step in s. */
      double time_step = 1.e-3;
      /** End time in s. */
      double end_time = 1.;
      /** Write output every this many steps (0: never). */
      unsigned int output_interval = 0;
      /** Folder of the output files. */
      std::string output_directory = "output";

      /** Throws std::invalid_argument naming the first inconsistent entry. */
      void
      check() const;

      /** Builds the world with all materials and bodies. */
      World
      build_world() const;
    };
  } // namespace rigid
} // namespace particulate

#endif
