// Laplace-alpha adaptation to a cylinder that spans a slab (Shape =
// cylinder, Length = the slab's depth): every vertex layer sees the same
// lateral surface.
//
// The cylinder's caps lie on the front and back walls. The mesh must treat
// it as the infinite cylinder it is inside the domain: the vertices that
// the method projects onto the body lie on its lateral surface, as many on
// the end walls as on the layers between them. With the caps in the
// distance field, a vertex of an end wall inside the disk is already on the
// body's surface (a cap) and is never projected: the wall layers had no
// vertex on the lateral surface, the cut cells next to them were the
// distorted ones, and the first time step of the 3D oscillating-cylinder
// slab stalled (doc/deformation.md).

#include <particulate/core/mesh.h>
#include <particulate/fbm/body_adapted_mesh.h>
#include <particulate/fbm/particulate_flow_simulation.h>

#include <deal.II/distributed/fully_distributed_tria.h>

#include <cmath>
#include <map>

#include "../fluid/test_utilities.h"

using namespace particulate;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             span = 0.1025, radius = 0.05;
  // a short piece of the slab of prm/oscillating-cylinder (3 cells per
  // diameter after two refinements, 4 cell layers across the span)
  const auto parameters = fbm::read_particulate_flow_case(
    testing::source_path("prm/oscillating-cylinder/slab-3d-laplace-alpha.prm"),
    "subsection Mesh\n set Lower corner = 0.8, 0, 0\n"
    " set Upper corner = 1.4, 0.41, 0.1025\n set Subdivisions = 6, 4, 1\nend\n");
  dealii::parallel::fullydistributed::Triangulation<3> tria(MPI_COMM_WORLD);
  core::create_mesh(parameters.flow.mesh, tria);
  fbm::BodyAdaptedMesh<3> mesh(parameters.flow.mesh,
                               parameters.deformation,
                               parameters.particles,
                               tria);
  const Eigen::Vector3d   centre = parameters.particles.positions.at(0);
  const auto              report = mesh.adapt({centre});

  // vertices on the lateral surface, per vertex layer z (one rank: the
  // whole mesh)
  std::map<long, unsigned int> on_surface;
  const auto                  &vertices = tria.get_vertices();
  const auto                  &used     = tria.get_used_vertices();
  for (unsigned int i = 0; i < vertices.size(); ++i)
    if (used[i])
      {
        const auto  &x = vertices[i];
        const double r = std::hypot(x[0] - centre[0], x[1] - centre[1]);
        if (std::abs(r - radius) < 1e-9 * radius)
          on_surface[std::lround(x[2] / span * 4.)] += 1;
      }

  bool ok = report.quality.min_scaled_jacobian > 0.;
  std::printf("min scaled Jacobian %.3f\nlayer z/span  vertices on the "
              "lateral surface\n",
              report.quality.min_scaled_jacobian);
  for (long layer = 0; layer <= 4; ++layer)
    {
      std::printf("  %.2f          %u\n", layer / 4., on_surface[layer]);
      ok &= on_surface[layer] > 0 && on_surface[layer] == on_surface[2];
    }
  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
