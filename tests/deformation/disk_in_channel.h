// A disk sinking through the uniform channel [0, 1] x [0, 2] of cells
// h = 1/32, shared by the tests of the carried zone's fresh starts.
#ifndef particulate_tests_deformation_disk_in_channel_h
#define particulate_tests_deformation_disk_in_channel_h

#include <particulate/core/mesh.h>
#include <particulate/deformation/distance_field.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace particulate {
  namespace sinking_disk {
    constexpr double disk_radius = 0.1, channel_cell = 1. / 32.;

    /** The channel: 4 x 8 coarse cells refined three times. */
    inline core::MeshParameters
    uniform_channel()
    {
      core::MeshParameters mesh;
      mesh.type         = core::MeshParameters::Type::hyper_rectangle;
      mesh.lower_corner = {0., 0.};
      mesh.upper_corner = {1., 2.};
      mesh.subdivisions = {4, 8};
      mesh.refinements  = 3;
      return mesh;
    }

    /** The signed distance from the disk at @p centre. */
    inline deformation::FunctionDistanceField<2>
    disk_at(const dealii::Point<2> &centre)
    {
      return deformation::FunctionDistanceField<2>(
        [centre](const dealii::Point<2> &x) {
          return x.distance(centre) - disk_radius;
        });
    }

    /** The vertices inside the disk at @p centre, relative to it, sorted
     *  (a realigned zone holds other vertices at the same places). */
    inline std::vector<dealii::Tensor<1, 2>>
    inside_relative(const std::vector<dealii::Point<2>> &vertices,
                    const dealii::Point<2>              &centre)
    {
      std::vector<dealii::Tensor<1, 2>> inside;
      for (const auto &x : vertices)
        if (x.distance(centre) < disk_radius)
          inside.push_back(x - centre);
      std::sort(inside.begin(),
                inside.end(),
                [](const dealii::Tensor<1, 2> &a,
                   const dealii::Tensor<1, 2> &b) {
                  return a[1] < b[1] - 1e-12
                         || (std::abs(a[1] - b[1]) <= 1e-12 && a[0] < b[0]);
                });
      return inside;
    }
  } // namespace sinking_disk
} // namespace particulate

#endif
