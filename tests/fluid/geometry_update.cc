// After the mesh vertices move, the matrix-free velocity operator and the
// geometric multigrid V-cycle recompute only their geometric data
// (MatrixFree::update_mapping): DoF numbering, partitioners and the level
// transfer stay. What they apply must be what objects built afresh on the
// moved mesh apply. On a 2D channel whose interior vertices are pushed
// along it by up to 0.4 h, the updated operator must agree with the fresh
// one to 1e-13 of the result and the updated V-cycle (single precision
// levels) to 1e-6 (both agree bit for bit with deal.II 9.4); the operator
// and the V-cycle from before the motion differ from the fresh ones by
// more than 1e-3 (about 0.04), so the test sees the motion.

#include <particulate/core/mesh.h>
#include <particulate/fluid/velocity_multigrid.h>
#include <particulate/fluid/viscosity_model.h>

#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <utility>

#include "../../source/fluid/momentum_operator.h"
#include "test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  constexpr int dim    = 2;
  using TrilinosVector = TrilinosWrappers::MPI::Vector;

  /** A velocity field u(p) padded with a zero pressure (dim + 1
   *  components, the system's). */
  class VelocityField : public Function<dim>
  {
  public:
    explicit VelocityField(std::function<Tensor<1, dim>(const Point<dim> &)> u)
      : Function<dim>(dim + 1)
      , u(std::move(u))
    {}
    double
    value(const Point<dim> &p, const unsigned int c) const override
    {
      return c < dim ? u(p)[c] : 0.;
    }

  private:
    std::function<Tensor<1, dim>(const Point<dim> &)> u;
  };

  /** |a - b|_inf / |b|_inf */
  double
  relative_difference(const TrilinosVector &a, const TrilinosVector &b)
  {
    TrilinosVector difference(a);
    difference -= b;
    return difference.linfty_norm() / b.linfty_norm();
  }

  /** The operator and the V-cycle of one geometry, applied to @p src. */
  struct Applied
  {
    TrilinosVector op, cycle;
  };

  class Channel
  {
  public:
    Channel()
      : tria(MPI_COMM_WORLD)
      , fe(FE_Q<dim>(2), dim, FE_DGP<dim>(1), 1)
      , dofs(tria)
      , mapping(2)
      , timer(MPI_COMM_WORLD,
              std::cout,
              TimerOutput::never,
              TimerOutput::wall_times)
    {
      const auto parameters = testing::parameters_from_text(
        "subsection Mesh\n set Type = hyper rectangle\n"
        " set Upper corner = 2, 1\n set Subdivisions = 4, 2\n"
        " set Refinements = 2\nend\n",
        "geometry_update");
      core::create_mesh(parameters.mesh, tria);
      dofs.distribute_dofs(fe);
      DoFRenumbering::component_wise(dofs, std::vector<unsigned int>{0, 0, 1});
      const auto n_velocity = DoFTools::count_dofs_per_fe_block(
        dofs,
        std::vector<unsigned int>{0, 0, 1})[0];
      owned_velocity = dofs.locally_owned_dofs().get_view(0, n_velocity);
      settings.dirichlet_ids = {0, 1, 2, 3};
      fluid::FluidProperties properties;
      properties.dynamic_viscosity = 0.05;
      viscosity                    = fluid::ViscosityModel::create(properties);
      rest                         = tria.get_vertices();
    }

    /** Interior vertices pushed along x by up to 0.4 h (h = 1/8). */
    void
    move_vertices()
    {
      const double a = 0.4 / 8.;
      for (const auto &cell : tria.cell_iterators())
        for (const auto v : cell->vertex_indices())
          {
            Point<dim> x = rest[cell->vertex_index(v)];
            x[0] += a * std::sin(M_PI * x[0] / 2.) * std::sin(M_PI * x[1]);
            cell->vertex(v) = x;
          }
    }

    /** @p field at the velocity DoFs (the velocity block's layout). */
    TrilinosVector
    velocity_of(const VelocityField &field) const
    {
      TrilinosVector all(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
      VectorTools::interpolate(mapping, dofs, field, all);
      TrilinosVector v(owned_velocity, MPI_COMM_WORLD);
      for (const auto i : owned_velocity)
        v(i) = all(i);
      v.compress(VectorOperation::insert);
      return v;
    }

    /** The operator and the V-cycle of @p op and @p cycle on @p src. */
    Applied
    apply(fluid::MomentumOperator<dim>  &op,
          fluid::VelocityMultigrid<dim> &cycle,
          const TrilinosVector          &src,
          const TrilinosVector          &iterate) const
    {
      op.set_linearisation(iterate, nullptr, mass, theta, 1., true, *viscosity);
      cycle.set_linearisation(iterate, mass, theta, *viscosity);
      Applied out{TrilinosVector(owned_velocity, MPI_COMM_WORLD),
                  TrilinosVector(owned_velocity, MPI_COMM_WORLD)};
      op.vmult(out.op, src);
      cycle.vmult(out.cycle, src);
      return out;
    }

    parallel::fullydistributed::Triangulation<dim> tria;
    const FESystem<dim>                            fe;
    DoFHandler<dim>                                dofs;
    const MappingQ<dim>                            mapping;
    TimerOutput                                    timer;
    IndexSet                                       owned_velocity;
    fluid::VelocityMultigrid<dim>::Settings        settings;
    std::unique_ptr<fluid::ViscosityModel>         viscosity;
    std::vector<Point<dim>>                        rest;
    const double                                   mass = 100., theta = 0.5;
  };

  /** A matrix-free operator and a V-cycle built on @p channel's mesh as
   *  it is now. */
  struct OperatorAndCycle
  {
    explicit OperatorAndCycle(Channel &channel)
      : cycle(channel.dofs,
              channel.owned_velocity,
              channel.mapping,
              channel.settings,
              channel.timer)
      , op(cycle.get_dof_handler(), channel.owned_velocity, channel.mapping)
    {}
    fluid::VelocityMultigrid<dim> cycle;
    fluid::MomentumOperator<dim>  op;
  };

  void
  check_operator_and_cycle(testing::Checker &checker)
  {
    Channel channel;
    // a source with all scales, and a smooth linearisation point
    const TrilinosVector src
      = channel.velocity_of(VelocityField([](const Point<dim> &p) {
          return Tensor<1, dim>({std::cos(7. * p[0] + 3. * p[1]), p[0] * p[1]});
        }));
    const TrilinosVector iterate
      = channel.velocity_of(VelocityField([](const Point<dim> &p) {
          return Tensor<1, dim>({std::sin(M_PI * p[1]) * (1. + p[0]),
                                 0.3 * std::cos(M_PI * p[0]) * p[1]});
        }));
    OperatorAndCycle kept(channel);
    const Applied    before = channel.apply(kept.op, kept.cycle, src, iterate);

    channel.move_vertices();
    kept.op.update_geometry();
    kept.cycle.update_geometry();
    const Applied updated = channel.apply(kept.op, kept.cycle, src, iterate);

    OperatorAndCycle fresh_objects(channel);
    const Applied    fresh
      = channel.apply(fresh_objects.op, fresh_objects.cycle, src, iterate);

    const double op_updated = relative_difference(updated.op, fresh.op);
    const double op_before  = relative_difference(before.op, fresh.op);
    const double cycle_updated
      = relative_difference(updated.cycle, fresh.cycle);
    const double cycle_before = relative_difference(before.cycle, fresh.cycle);
    std::cout << "operator: updated " << op_updated << ", before the motion "
              << op_before << " from the fresh one; V-cycle: updated "
              << cycle_updated << ", before the motion " << cycle_before
              << std::endl;
    checker.check(op_updated <= 1e-13,
                  "the updated operator applies what a fresh one does");
    checker.check(cycle_updated <= 1e-6,
                  "the updated V-cycle applies what a fresh one does");
    checker.check(op_before > 1e-3 && cycle_before > 1e-3,
                  "the motion changes both (the test sees it)");
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  check_operator_and_cycle(checker);
  return checker.exit_code();
}
