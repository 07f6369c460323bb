#ifndef particulate_geometry_distance_map_data_h
#define particulate_geometry_distance_map_data_h

#include <vector>

namespace particulate {
  namespace geometry {

    /**
     * A distance map as raw arrays, the layout the CUDA containment kernels
     * (cuda/) read; no methods, no dependencies, so that it can be copied to
     * the device as is. Grid point (i, j, k), 0 <= i < nx etc., sits at
     * origin + (i * spacing[0], j * spacing[1], k * spacing[2]) in the body
     * frame [m], and its signed distance [m] (negative inside) is
     * values[i + nx * (j + ny * k)].
     */
    struct DistanceMapData
    {
      int                nx, ny, nz;
      float              origin[3];
      float              spacing[3];
      std::vector<float> values;
    };

  } // namespace geometry
} // namespace particulate

#endif
