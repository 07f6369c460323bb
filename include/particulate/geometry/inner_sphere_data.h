#ifndef particulate_geometry_inner_sphere_data_h
#define particulate_geometry_inner_sphere_data_h

#include <vector>

namespace particulate {
  namespace geometry {

    /**
     * Inner spheres as raw arrays (structure of arrays), the layout the CUDA
     * containment kernels (cuda/) read: sphere s has centre (cx[s], cy[s],
     * cz[s]) in the body frame and radius r[s] [m]. A point is inside the body
     * if it is inside any sphere.
     */
    struct InnerSphereData
    {
      std::vector<float> cx, cy, cz, r;
    };

  } // namespace geometry
} // namespace particulate

#endif
