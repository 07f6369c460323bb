// Plain data exchanged with the containment library (thesis §3.4.2, §5.4.3).
//
// These structs mirror, field for field, what the geometry module exports for
// its distance maps and inner-sphere sets, so that cuda/ can be built without
// any geometry header (it depends on nothing but the C++ standard library and,
// optionally, the CUDA toolkit). They are grouped in one header because they
// are passive data with no behaviour of their own.
#ifndef particulate_cuda_containment_types_h
#define particulate_cuda_containment_types_h

#include <cstdint>
#include <vector>

namespace particulate {
  namespace cuda {
    /**
     * A signed distance map sampled on a Cartesian grid in the body frame
     * (thesis §3.4.2, algorithm 5).
     *
     * Grid point (i, j, k) sits at
     * `origin + (i*spacing[0], j*spacing[1], k*spacing[2])` and holds
     * `values[i + nx*(j + ny*k)]`, the signed distance to the body surface in
     * metres, negative inside. Between grid points the distance is the
     * trilinear interpolant. A point outside the box
     * `[origin, origin + (n-1)*spacing]` is outside the body.
     */
    struct DistanceMapData
    {
      /** Number of grid points along x, y, z (each at least 2). */
      int nx = 0, ny = 0, nz = 0;
      /** Body-frame position of grid point (0,0,0) [m]. */
      float origin[3] = {0.f, 0.f, 0.f};
      /** Grid spacing along x, y, z [m], each positive. */
      float spacing[3] = {0.f, 0.f, 0.f};
      /** Signed distances [m], `nx*ny*nz` of them, x fastest. */
      std::vector<float> values;
    };

    /**
     * An inner-sphere representation of a body's volume (thesis §3.4.2,
     * figure 3.19): a point is inside the body when it is inside (or on) at
     * least one sphere. All four arrays have the same length; centres [m] are
     * in the body frame, radii [m] are non-negative.
     */
    struct InnerSphereData
    {
      std::vector<float> cx, cy, cz, r;
    };

    /**
     * One rigid body to test against: a shape handle returned by
     * ContainmentEngine::add_distance_map() or
     * ContainmentEngine::add_inner_spheres(), and its pose.
     *
     * The pose maps body to world: `x_world = R x_body + t`, so a world point
     * is classified at `x_body = R^T (x_world - t)`.
     */
    struct BodyInstance
    {
      /** Handle of the uploaded shape. */
      int shape = -1;
      /** Rotation body -> world, row-major 3x3 (R[3*row + col]). */
      float R[9] = {1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f};
      /** World position of the body-frame origin [m]. */
      float t[3] = {0.f, 0.f, 0.f};
    };
  } // namespace cuda
} // namespace particulate

#endif
