// The deal.II adapter on a distributed mesh (2 ranks,
// parallel::fullydistributed::Triangulation): on every rank the hash grid
// equals brute force on that rank's points, the ranks' locally owned Q2
// nodes partition the global set, and the number of nodes inside the bodies
// summed over ranks equals the serial count.
#include <particulate/geometry/box.h>
#include <particulate/geometry/dealii/mesh_point_classifier.h>
#include <particulate/geometry/ellipsoid.h>
#include <particulate/geometry/sphere.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <cmath>

#include "check.h"

using namespace particulate::geometry;
using Eigen::Vector3d;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const unsigned int rank  = dealii::Utilities::MPI::this_mpi_process(comm);
  const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(comm);

  dealii::Triangulation<3> serial;
  dealii::GridGenerator::subdivided_hyper_cube(serial, 12, 0., 1.);
  dealii::GridTools::partition_triangulation(ranks, serial);
  const auto description = dealii::TriangulationDescription::Utilities::
    create_description_from_triangulation(serial, comm);
  dealii::parallel::fullydistributed::Triangulation<3> tria(comm);
  tria.create_triangulation(description);

  Sphere                         ball(0.3);
  Box                            box(Vector3d(0.2, 0.1, 0.15));
  Ellipsoid                      egg(Vector3d(0.15, 0.1, 0.08));
  const std::vector<PlacedShape> bodies
    = {{&ball, Pose(Eigen::Matrix3d::Identity(), Vector3d(0.4, 0.5, 0.5))},
       {&box,
        Pose(Eigen::Quaterniond(
               Eigen::AngleAxisd(0.6, Vector3d(1, 1, 0).normalized())),
             Vector3d(0.75, 0.3, 0.6))},
       {&egg,
        Pose(Eigen::Quaterniond(
               Eigen::AngleAxisd(1.2, Vector3d(0, 1, 1).normalized())),
             Vector3d(0.2, 0.8, 0.3))}};

  dealii::FESystem<3>  fe(dealii::FE_Q<3>(2), 3);
  dealii::MappingQ1<3> mapping;

  // Distributed: this rank's owned nodes.
  dealii::DoFHandler<3> dh(tria);
  dh.distribute_dofs(fe);
  const MeshPointClassifier local(mapping, dh, 0);
  const auto                fast = local.classify(bodies);
  const auto slow = classify_points_brute_force(local.points(), bodies);
  long       diff = 0, inside = 0;
  for (std::size_t i = 0; i < fast.size(); ++i)
    {
      diff += fast[i] != slow[i];
      inside += fast[i] >= 0;
    }
  // Vertices of the locally owned cells, too.
  const MeshPointClassifier vertices(tria);
  const auto                vf = vertices.classify(bodies);
  const auto vs = classify_points_brute_force(vertices.points(), bodies);
  for (std::size_t i = 0; i < vf.size(); ++i)
    diff += vf[i] != vs[i];

  const long total_diff   = dealii::Utilities::MPI::sum(diff, comm);
  const long total_inside = dealii::Utilities::MPI::sum(inside, comm);
  const long total_points
    = dealii::Utilities::MPI::sum(static_cast<long>(local.points().size()),
                                  comm);
  const long min_points
    = dealii::Utilities::MPI::min(static_cast<long>(local.points().size()),
                                  comm);

  // Serial reference on the same mesh.
  dealii::DoFHandler<3> sdh(serial);
  sdh.distribute_dofs(fe);
  const MeshPointClassifier all(mapping, sdh, 0);
  long                      serial_inside = 0;
  for (const int b : classify_points_brute_force(all.points(), bodies))
    serial_inside += b >= 0;

  if (rank == 0)
    std::cout << ranks << " ranks: " << total_points
              << " owned Q2 nodes (serial " << all.points().size()
              << "), inside " << total_inside << " (serial " << serial_inside
              << "), hash grid vs brute force "
              << "differences " << total_diff << std::endl;
  CHECK(total_diff == 0);
  CHECK(total_points == static_cast<long>(all.points().size()));
  CHECK(total_inside == serial_inside && serial_inside > 0);
  CHECK_MSG(ranks == 1 || min_points > 0, "every rank owns nodes");
  return rank == 0 ? test::finish("geometry_mesh_point_classifier_mpi") :
                     (test::failures > 0 ? 1 : 0);
}
