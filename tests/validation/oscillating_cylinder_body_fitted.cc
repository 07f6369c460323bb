// Validation (label validation): the oscillating cylinder of thesis §6.3 on a
// body-fitted moving mesh, our own reference for the fictitious-boundary
// runs of prm/oscillating-cylinder. Reads prm/oscillating-cylinder/
// body-fitted.prm (2D) or another case file of its kind, such as
// body-fitted-slab-3d.prm (the cylinder spanning a 3D slab); each step moves
// the mesh (a rigid translation with the cylinder within 0.2 m of its rest
// position, fading linearly to nothing at the channel's ends), which gives
// the ALE mesh velocity, then advances the flow and integrates drag and lift
// over the hole.
// Writes OUT/forces.dat: time, x_c, c_d, c_l (surface integrals) and c_d,
// c_l (volume integrals), with c = 2 F / (rho U^2 D), U = 2 pi f A, per unit
// span in 3D (F divided by the channel's depth).
// Gate (2D): the drag extrema of the second period lie within 10 % of the
// published +3.24 / -3.26 (Wan & Turek), and |c_l| stays below 0.2.
// Usage: validation_oscillating_cylinder_body_fitted OUT [end time
// [refinements [case file]]]

#include <particulate/core/input_file.h>
#include <particulate/core/mesh.h>
#include <particulate/core/progress_reporter.h>
#include <particulate/core/time_series_writer.h>
#include <particulate/fluid/flow_diagnostics.h>
#include <particulate/fluid/flow_simulation.h>
#include <particulate/fluid/navier_stokes.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "../fluid/test_utilities.h"

using namespace dealii;
using namespace particulate;

namespace {
  template <int dim>
  void
  run(fluid::FlowCaseParameters &p,
      const std::string         &out,
      const double               end_time,
      testing::Checker          &checker)
  {
    MPI_Comm   comm = MPI_COMM_WORLD;
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;

    // the motion: x_c(t) = X0 + A sin(2 pi f t)
    const double X0 = 1.1, Y0 = 0.2, A = 0.25, f = 0.25, D = 0.1;
    const double U = 2. * M_PI * f * A, rho = p.fluid.properties.density;
    const double L = 2.2, rigid_half_width = 0.2;
    // share of the cylinder's displacement that a vertex at x takes
    const auto share = [&](const double x) {
      if (x < X0 - rigid_half_width)
        return x / (X0 - rigid_half_width);
      if (x > X0 + rigid_half_width)
        return (L - x) / (L - X0 - rigid_half_width);
      return 1.;
    };

    // per unit span in 3D, as the thesis scales its slab (eq. 6.4)
    const double span = dim == 3 ? p.mesh.channel_depth : 1.;

    parallel::fullydistributed::Triangulation<dim> tria(comm);
    core::create_mesh(p.mesh, tria);
    const std::vector<Point<dim>> rest = tria.get_vertices();
    TimerOutput                   timer(comm,
                      std::cout,
                      TimerOutput::never,
                      TimerOutput::wall_times);
    fluid::NavierStokes<dim>      flow(p.fluid, tria, timer);
    flow.setup_dofs();
    flow.set_initial_condition(0.);
    if (root)
      std::cout << "Body-fitted oscillating cylinder: "
                << tria.n_global_active_cells() << " cells, " << flow.n_dofs()
                << " DoFs, dt = " << p.time.time_step
                << " s, to t = " << end_time << " s\n";

    const auto place = [&](const double s) {
      for (const auto &cell : tria.cell_iterators())
        for (const auto v : cell->vertex_indices())
          {
            Point<dim> x = rest[cell->vertex_index(v)];
            x[0] += s * share(x[0]);
            cell->vertex(v) = x;
          }
      // the curved wall of the hole moves with the cylinder
      tria.set_manifold(0, *core::cylinder_axis_manifold<dim>(X0 + s, Y0));
    };

    core::TimeSeriesWriter series(
      out + "/forces.dat",
      {"time", "x_c", "c_d", "c_l", "c_d_volume", "c_l_volume"},
      comm);
    const double           scale  = 2. / (rho * U * U * D * span);
    double                 t      = 0.;
    double                 max_d2 = -1e9, min_d2 = 1e9, max_l = 0.;
    core::ProgressReporter progress(std::cout, 0., end_time);
    unsigned int           step = 0;
    while (t < end_time - 1e-9)
      {
        const double dt = std::min(p.time.time_step, end_time - t);
        const double s  = A * std::sin(2. * M_PI * f * (t + dt));
        flow.move_mesh([&]() { place(s); }, dt);
        const auto stats = flow.advance(t, dt, p.time.scheme);
        t += dt;
        ++step;
        const auto F = fluid::surface_force(flow, {2});
        const auto Fv
          = fluid::volume_force(flow, fluid::boundary_indicator(flow, {2}));
        const double c_d = scale * F[0], c_l = scale * F[1];
        series.write_row({t, X0 + s, c_d, c_l, scale * Fv[0], scale * Fv[1]});
        if (t > 4. && t <= 8. + 1e-9)
          {
            max_d2 = std::max(max_d2, c_d);
            min_d2 = std::min(min_d2, c_d);
          }
        max_l = std::max(max_l, std::abs(c_l));
        if (root)
          {
            char line[96];
            std::snprintf(line,
                          sizeof(line),
                          "nonlinear %2u linear %4u  c_d %8.4f  c_l %8.4f",
                          stats.nonlinear_iterations,
                          stats.linear_iterations,
                          c_d,
                          c_l);
            progress.report(step, t, dt, line);
          }
      }
    if (dim == 2 && end_time >= 8.)
      {
        if (root)
          std::cout << "second period: c_d between " << min_d2 << " and "
                    << max_d2 << " (published -3.26 / +3.24); largest |c_l| "
                    << max_l << '\n';
        checker.check(std::abs(max_d2 - 3.24) < 0.1 * 3.24
                        && std::abs(min_d2 + 3.26) < 0.1 * 3.26,
                      "drag extrema of the second period within 10 % of "
                      "Wan & Turek's");
        checker.check(max_l < 0.2, "|c_l| stays small");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::Checker                 checker;
  const std::string                out
    = argc > 1 ? argv[1] : "oscillating_cylinder_body_fitted";
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::filesystem::create_directories(out);

  const std::string file
    = argc > 4 ?
        std::string(argv[4]) :
        testing::source_path("prm/oscillating-cylinder/body-fitted.prm");
  ParameterHandler prm;
  fluid::FlowCaseParameters::declare(prm);
  core::parse_input_file(prm, file);
  fluid::FlowCaseParameters p;
  p.parse(prm);
  const double end_time = argc > 2 ? std::atof(argv[2]) : p.time.end_time;
  if (argc > 3)
    p.mesh.refinements = std::atoi(argv[3]);
  if (p.simulation.dimension == 3)
    run<3>(p, out, end_time, checker);
  else
    run<2>(p, out, end_time, checker);
  return checker.exit_code();
}
