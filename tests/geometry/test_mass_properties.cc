// Mass properties by the divergence theorem (thesis §4.2.2): exact for
// polyhedra (boxes), second-order convergent for meshed spheres, and the
// transformation rule of eq. (4.30) for moved meshes.
#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mass_properties.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/mesh_io.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "check.h"

using namespace particulate::geometry;
using Eigen::Matrix3d;
using Eigen::Vector3d;

int
main()
{
  // Box [-a, a] x [-b, b] x [-c, c]: V = 8abc, I_xx = V (b^2 + c^2) / 3.
  {
    const Vector3d h(0.5, 1.25, 2.);
    for (unsigned int n : {1u, 4u})
      {
        const MassProperties mp
          = compute_mass_properties(mesh_generators::box(h, n));
        const double V = 8. * h.prod();
        Matrix3d     I = Matrix3d::Zero();
        I(0, 0)        = V * (h[1] * h[1] + h[2] * h[2]) / 3.;
        I(1, 1)        = V * (h[0] * h[0] + h[2] * h[2]) / 3.;
        I(2, 2)        = V * (h[0] * h[0] + h[1] * h[1]) / 3.;
        CHECK(std::abs(mp.volume - V) < 1e-13 * V);
        CHECK(mp.centre.norm() < 1e-14);
        CHECK_MSG((mp.inertia - I).norm() < 1e-13 * I.norm(),
                  "box inertia exact");
      }
  }

  // Icosphere: the inscribed polyhedron converges to the ball with error
  // O(edge^2), i.e. a factor ~4 per refinement; V -> 4/3 pi r^3,
  // I -> 2/5 V r^2 (unit density).
  {
    const double r = 0.8;
    const double V = 4. / 3. * M_PI * r * r * r, I = 0.4 * V * r * r;
    double       prev_v = 0., prev_i = 0.;
    std::cout << "icosphere: refinements, |V - V_ball| / V, |I - I_ball| / I\n";
    for (unsigned int k = 1; k <= 6; ++k)
      {
        const MassProperties mp
          = compute_mass_properties(mesh_generators::icosphere(r, k));
        const double ev = std::abs(mp.volume - V) / V;
        const double ei = (mp.inertia - I * Matrix3d::Identity()).norm() / I;
        std::cout << "  " << k << "  " << ev << "  " << ei << "\n";
        // Isotropic: the icosahedral symmetry makes the tensor a multiple of
        // the identity; the centre is the origin.
        const double iso
          = (mp.inertia - mp.inertia.trace() / 3. * Matrix3d::Identity())
              .norm();
        CHECK(iso < 1e-12 * I && mp.centre.norm() < 1e-12);
        if (k > 1)
          {
            CHECK_MSG(ev < prev_v / 3.5 && ev > prev_v / 4.5,
                      "volume error falls by ~4 per refinement");
            CHECK_MSG(ei < prev_i / 3.5 && ei > prev_i / 4.5,
                      "inertia error falls by ~4 per refinement");
          }
        prev_v = ev;
        prev_i = ei;
      }
    CHECK(prev_v < 1e-3 && prev_i < 2e-3);
  }

  // A moved mesh gives the moved properties: same volume, centre R c + t,
  // tensor R I R^T (eq. 4.30). Use a non-symmetric body: a box with a
  // moved copy's tensor compared to the rotated one, and the elephant.
  {
    const Pose                pose(Eigen::Quaterniond(
                      Eigen::AngleAxisd(1.1,
                                        Vector3d(0.3, -1., 0.5).normalized())),
                    Vector3d(10., -3., 7.));
    std::vector<TriangleMesh> bodies
      = {mesh_generators::box(Vector3d(0.3, 0.7, 1.1), 2)};
    const char       *env = std::getenv("PARTICULATE_CGAL_DATA_DIR");
    const std::string elephant
      = std::string(env ? env : "cgal-data") + "/data/meshes/elephant.off";
    if (std::filesystem::exists(elephant))
      bodies.push_back(read_surface_mesh(elephant));
    for (const auto &m : bodies)
      {
        const MassProperties a = compute_mass_properties(m);
        const MassProperties b = compute_mass_properties(m.transformed(pose));
        const MassProperties c = a.transformed(pose);
        CHECK(std::abs(a.volume - b.volume) < 1e-10 * a.volume);
        CHECK((b.centre - c.centre).norm() < 1e-10 * (1. + c.centre.norm()));
        std::ostringstream msg;
        msg << "moved tensor "
            << (b.inertia - c.inertia).norm() / c.inertia.norm();
        CHECK_MSG((b.inertia - c.inertia).norm() < 1e-9 * c.inertia.norm(),
                  msg.str());
        // Principal frame: in it the tensor is diagonal with the moments.
        Vector3d       moments;
        const Pose     frame = a.principal_frame(&moments);
        const Matrix3d D
          = frame.rotation().transpose() * a.inertia * frame.rotation();
        CHECK((D - Matrix3d(moments.asDiagonal())).norm()
              < 1e-10 * moments.norm());
        CHECK(std::abs(frame.rotation().determinant() - 1.) < 1e-12);
        // Parallel axis: about the origin of the moved frame.
        const Matrix3d about = a.inertia_about(a.centre + Vector3d(1, 0, 0));
        CHECK(std::abs(about(1, 1) - a.inertia(1, 1) - a.volume)
              < 1e-10 * about.norm());
      }
  }

  // Inward orientation is an error, not a negative mass.
  {
    TriangleMesh m = mesh_generators::icosphere(1., 1);
    m.flip_orientation();
    bool threw = false;
    try
      {
        compute_mass_properties(m);
      }
    catch (const GeometryError &e)
      {
        threw
          = std::string(e.what()).find("oriented outward") != std::string::npos;
      }
    CHECK(threw);
  }
  return test::finish("geometry_mass_properties");
}
