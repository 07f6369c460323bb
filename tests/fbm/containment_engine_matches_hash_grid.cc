// The FBM's two ways of finding the velocity nodes inside the particles
// agree: the hash grid with the bodies' exact signed distances (double) and
// the cuda/ library's containment engine (float; here on its CPU path,
// which computes bit for bit what its GPU kernel does, cuda/README.md).
// Random spheres in the DFG 3D channel (level 0, Q2 nodes), random disks
// in the 2D channel (level 2), and 60 surface-mesh ellipsoids (one mesh of
// 5 120 triangles, semi-axes 0.06, 0.04, 0.03 m, its distance map uploaded
// once) at random poses in the 3D channel: the same nodes must be marked, by
// the same body, except nodes closer to a surface than float rounding can
// resolve (1e-6 of the body's size), which are counted and must be rare.

#include <particulate/core/mesh.h>
#include <particulate/fbm/fictitious_boundary.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/mesh_body.h>
#include <particulate/geometry/mesh_generators.h>
#include <particulate/geometry/sphere.h>

#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <random>

#include "../fluid/test_utilities.h"

using namespace particulate;

namespace {
  template <int dim>
  void
  compare(const std::string &library_name,
          const bool         with_meshes,
          testing::Checker  &checker)
  {
    const auto parameters = testing::library_case(library_name, "");
    dealii::parallel::fullydistributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    core::create_mesh(parameters.mesh, tria);
    dealii::TimerOutput      timer(MPI_COMM_WORLD,
                              std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    fluid::NavierStokes<dim> flow(parameters.fluid, tria, timer);
    flow.setup_dofs();

    // bodies at random places in the channel, some overlapping, so that
    // "the first body that contains a node" matters too
    rigid::World                           world;
    const auto                             material = world.add_material({});
    std::mt19937                           random(11);
    std::uniform_real_distribution<double> x(0.05, 2.0), y(0.05, 0.36),
      radius(0.02, 0.08), angle(0., 2. * M_PI), component(-1., 1.);
    std::vector<unsigned int> ids;
    std::vector<double>       radii;
    const auto                random_centre = [&]() {
      return Eigen::Vector3d(x(random), y(random), dim == 3 ? y(random) : 0.);
    };
    for (unsigned int b = 0; b < 12; ++b)
      {
        const double                           r      = radius(random);
        const Eigen::Vector3d                  centre = random_centre();
        std::shared_ptr<const geometry::Shape> shape;
        if (dim == 3)
          shape = std::make_shared<geometry::Sphere>(r);
        else
          shape = std::make_shared<geometry::Cylinder>(r, 0.5);
        const Eigen::Quaterniond orientation(
          Eigen::AngleAxisd(angle(random),
                            dim == 3 ?
                              Eigen::Vector3d(1., 2., 3.).normalized() :
                              Eigen::Vector3d::UnitZ()));
        ids.push_back(
          world.add_body(shape, material, centre, orientation, true));
        radii.push_back(r);
      }
    if (with_meshes)
      {
        const Eigen::Vector3d  semi_axes(0.06, 0.04, 0.03);
        geometry::TriangleMesh mesh
          = geometry::mesh_generators::icosphere(1., 4);
        for (auto &v : mesh.vertices)
          v = semi_axes.cwiseProduct(v);
        const auto ellipsoid
          = geometry::make_mesh_body(mesh, {}, "the ellipsoid mesh").shape;
        for (unsigned int b = 0; b < 60; ++b)
          {
            const Eigen::Vector3d centre = random_centre();
            const Eigen::Vector3d axis(component(random),
                                       component(random),
                                       component(random));
            ids.push_back(world.add_body(
              ellipsoid,
              material,
              centre,
              Eigen::Quaterniond(
                Eigen::AngleAxisd(angle(random), axis.normalized())),
              true));
            radii.push_back(semi_axes.minCoeff());
          }
      }
    // pointers only once the world holds all bodies
    std::vector<typename fbm::FictitiousBoundary<dim>::Body> bodies;
    for (unsigned int b = 0; b < ids.size(); ++b)
      bodies.push_back({&world.body(ids[b])});

    fbm::FictitiousBoundary<dim> grid_path(flow), engine_path(flow);
    grid_path.setup();
    engine_path.setup();
    engine_path.use_containment_engine(cuda::Backend::cpu);
    grid_path.classify(bodies);
    engine_path.classify(bodies);

    unsigned long inside = 0, differ = 0, unresolved = 0, n = 0;
    for (unsigned int i = 0; i < grid_path.n_nodes(); ++i)
      {
        ++n;
        const int a = grid_path.body_of_node(i),
                  b = engine_path.body_of_node(i);
        inside += a >= 0;
        if (a == b)
          continue;
        // allowed only where a surface passes within float rounding
        bool near_surface = false;
        for (unsigned int b = 0; b < bodies.size(); ++b)
          near_surface |= std::abs(bodies[b].body->signed_distance(
                            engine_path.node_position(i)))
                          < 1e-6 * radii[b];
        (near_surface ? unresolved : differ) += 1;
      }
    char what[200];
    std::snprintf(what,
                  sizeof(what),
                  "%s%s: %lu of %lu nodes inside; engine and hash grid "
                  "differ on %lu nodes off the surfaces (%lu within 1e-6 r)",
                  library_name.c_str(),
                  with_meshes ? " with mesh bodies" : "",
                  inside,
                  n,
                  differ,
                  unresolved);
    checker.check(differ == 0 && inside > 100 && unresolved * 1000 <= inside,
                  what);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                         checker;
  compare<2>("dfg-2d-2", false, checker);
  compare<3>("dfg-3d-1z", false, checker);
  compare<3>("dfg-3d-1z", true, checker);
  return checker.exit_code();
}
