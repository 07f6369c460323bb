#include <particulate/deformation/pde_deformation.h>
#include <particulate/deformation/point_locator.h>
#include <particulate/deformation/vertex_hierarchy.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    namespace {
      /**
       * Q1 functions on a fixed mesh, given by their vertex values, that can
       * be evaluated at points which move a little between calls.
       */
      template <int dim>
      class VertexFields
      {
      public:
        using Cell = typename PointLocator<dim>::Cell;

        VertexFields(const Triangulation<dim> &tria, const unsigned int n)
          : fe(1)
          , dof_handler(tria)
          , locator(tria)
        {
          dof_handler.distribute_dofs(fe);
          dof_of_vertex.assign(tria.n_vertices(),
                               numbers::invalid_unsigned_int);
          cell_at_vertex.resize(tria.n_vertices());
          for (const auto &cell : dof_handler.active_cell_iterators())
            for (const unsigned int v : cell->vertex_indices())
              {
                dof_of_vertex[cell->vertex_index(v)]
                  = cell->vertex_dof_index(v, 0);
                cell_at_vertex[cell->vertex_index(v)] = cell;
              }
          fields.assign(n, Vector<double>(dof_handler.n_dofs()));
        }

        /** Values of all fields at @p p, searched from @p hint (updated). */
        void
        evaluate(const Point<dim>    &p,
                 Cell                &hint,
                 std::vector<double> &out) const
        {
          const auto location = locator.locate(p, hint);
          hint                = location.cell;
          const typename DoFHandler<dim>::active_cell_iterator dof_cell(
            &dof_handler.get_triangulation(),
            location.cell->level(),
            location.cell->index(),
            &dof_handler);
          dof_cell->get_dof_indices(dofs);
          out.assign(fields.size(), 0.);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const double phi = fe.shape_value(i, location.unit_point);
              for (unsigned int k = 0; k < fields.size(); ++k)
                out[k] += phi * fields[k][dofs[i]];
            }
        }

        FE_Q<dim>                                    fe;
        DoFHandler<dim>                              dof_handler;
        PointLocator<dim>                            locator;
        std::vector<unsigned int>                    dof_of_vertex;
        std::vector<Cell>                            cell_at_vertex;
        std::vector<Vector<double>>                  fields;
        mutable std::vector<types::global_dof_index> dofs
          = std::vector<types::global_dof_index>(
            GeometryInfo<dim>::vertices_per_cell);
      };



      /** The mean size of the active cells around each vertex (g_0). */
      template <int dim>
      std::vector<double>
      area_function(const Triangulation<dim> &tria)
      {
        std::vector<double>       sum(tria.n_vertices(), 0.);
        std::vector<unsigned int> count(tria.n_vertices(), 0);
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            {
              sum[cell->vertex_index(v)] += cell->measure();
              ++count[cell->vertex_index(v)];
            }
        for (unsigned int i = 0; i < sum.size(); ++i)
          if (count[i] > 0)
            sum[i] /= count[i];
        return sum;
      }



      /** |Omega| / int 1/u_h for the Q1 function with vertex values u. */
      template <int dim>
      double
      harmonic_mean(const VertexFields<dim>   &space,
                    const std::vector<double> &u)
      {
        const QGauss<dim>                    quadrature(2);
        FEValues<dim>                        fe_values(space.fe,
                                quadrature,
                                update_values | update_JxW_values);
        std::vector<types::global_dof_index> dofs(space.fe.n_dofs_per_cell());
        double                               volume = 0., integral = 0.;
        for (const auto &cell : space.dof_handler.active_cell_iterators())
          {
            fe_values.reinit(cell);
            std::array<double, GeometryInfo<dim>::vertices_per_cell> inverse;
            for (const unsigned int v : cell->vertex_indices())
              inverse[v] = 1. / u[cell->vertex_index(v)];
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                double value = 0.;
                for (const unsigned int v : cell->vertex_indices())
                  value += fe_values.shape_value(v, q) * inverse[v];
                integral += value * fe_values.JxW(q);
                volume += fe_values.JxW(q);
              }
          }
        return volume / integral;
      }
    } // namespace



    template <int dim>
    PdeDeformation<dim>::PdeDeformation(const Settings &settings_)
      : settings(settings_)
    {}



    template <int dim>
    std::string
    PdeDeformation<dim>::name() const
    {
      return settings.robust ? "robust deformation method" :
                               "basic deformation method";
    }



    template <int dim>
    DeformationReport
    PdeDeformation<dim>::deform(Triangulation<dim>       &tria,
                                const DistanceField<dim> &distance) const
    {
      const double width = settings.width, eps = settings.smallest_cell_ratio;
      return deform_to_monitor(tria, [&](const Point<dim> &x) {
        return std::min(1.,
                        std::max(std::abs(distance.signed_distance(x)) / width,
                                 eps));
      });
    }



    template <int dim>
    std::vector<double>
    PdeDeformation<dim>::blending_parameters(const double extreme_ratio) const
    {
      const double       logarithm = std::abs(std::log(extreme_ratio));
      const unsigned int n
        = std::max(1u,
                   static_cast<unsigned int>(std::ceil(
                     logarithm / std::log(settings.step_ratio) - 1e-12)));
      std::vector<double> s(n, 1.);
      if (std::abs(extreme_ratio - 1.) > 1e-12)
        for (unsigned int i = 1; i < n; ++i)
          s[i - 1] = (std::pow(extreme_ratio, double(i) / n) - 1.)
                     / (extreme_ratio - 1.);
      return s;
    }



    template <int dim>
    DeformationReport
    PdeDeformation<dim>::deform_to_monitor(
      Triangulation<dim>                              &tria,
      const std::function<double(const Point<dim> &)> &monitor) const
    {
      DeformationReport   report;
      const auto         &vertices = tria.get_vertices();
      std::vector<double> f(vertices.size());
      for (unsigned int i = 0; i < vertices.size(); ++i)
        {
          f[i] = monitor(vertices[i]);
          if (!(f[i] > 0. && std::isfinite(f[i])))
            throw DeformationError("The deformation monitor must be positive "
                                   "and finite everywhere.");
        }

      if (!settings.robust)
        {
          VertexHierarchy<dim>::write_positions(tria,
                                                basic_step(tria, f, report));
          report.steps   = 1;
          report.quality = compute_mesh_quality(tria);
          return report;
        }

      // Algorithm 11. The blend f_s = s f + (1 - s) g_0 mixes two size
      // functions, so both are first scaled to a harmonic mean of one. The
      // area function g_0 belongs to the original mesh and is read there
      // at the present vertex positions.
      Triangulation<dim> original;
      original.copy_triangulation(tria);
      VertexFields<dim>         g0(original, 1);
      const std::vector<double> g0_at_vertices = area_function(original);
      const double              f_scale        = harmonic_mean(g0, f),
                   g_scale = harmonic_mean(g0, g0_at_vertices);
      double extreme       = 1.;
      for (unsigned int i = 0; i < vertices.size(); ++i)
        {
          const double ratio = (f[i] / f_scale) / (g0_at_vertices[i] / g_scale);
          if (std::abs(std::log(ratio)) > std::abs(std::log(extreme)))
            extreme = ratio;
          g0.fields[0][g0.dof_of_vertex[i]] = g0_at_vertices[i] / g_scale;
        }

      std::vector<typename VertexFields<dim>::Cell> hint = g0.cell_at_vertex;
      std::vector<double>                           value;
      const std::vector<Point<dim>>                 start = vertices;
      try
        {
          for (const double s : blending_parameters(extreme))
            {
              std::vector<double> target(vertices.size());
              for (unsigned int i = 0; i < vertices.size(); ++i)
                {
                  g0.evaluate(vertices[i], hint[i], value);
                  target[i]
                    = s * monitor(vertices[i]) / f_scale + (1. - s) * value[0];
                }
              VertexHierarchy<dim>::write_positions(tria,
                                                    basic_step(tria,
                                                               target,
                                                               report));
              ++report.steps;
            }
        }
      catch (const DeformationError &)
        {
          VertexHierarchy<dim>::write_positions(tria, start);
          throw;
        }
      report.quality = compute_mesh_quality(tria);
      return report;
    }



    template <int dim>
    std::vector<Point<dim>>
    PdeDeformation<dim>::basic_step(const Triangulation<dim>  &tria,
                                    const std::vector<double> &target,
                                    DeformationReport         &report) const
    {
      // Fields 0 ... dim-1: recovered grad v; dim: f~; dim+1: g~.
      VertexFields<dim>         space(tria, dim + 2);
      const unsigned int        n_dofs  = space.dof_handler.n_dofs();
      const std::vector<double> g       = area_function(tria);
      const double              c_f     = harmonic_mean(space, target);
      const double              c_g     = harmonic_mean(space, g);
      Vector<double>           &f_tilde = space.fields[dim];
      Vector<double>           &g_tilde = space.fields[dim + 1];
      for (unsigned int i = 0; i < tria.n_vertices(); ++i)
        if (space.dof_of_vertex[i] != numbers::invalid_unsigned_int)
          {
            f_tilde[space.dof_of_vertex[i]] = c_f / target[i];
            g_tilde[space.dof_of_vertex[i]] = c_g / g[i];
          }

      // eq. 5.21: with both densities normalised to the same integral the
      // right-hand side has mean zero, so fixing v at one vertex picks the
      // solution without disturbing any equation.
      AffineConstraints<double> constraints;
      constraints.add_line(0);
      constraints.close();
      DynamicSparsityPattern dsp(n_dofs);
      DoFTools::make_sparsity_pattern(space.dof_handler, dsp, constraints);
      SparsityPattern sparsity;
      sparsity.copy_from(dsp);
      // Every rank deforms its own copy of the mesh: a serial matrix.
      SparseMatrix<double> matrix(sparsity);
      Vector<double>       rhs(n_dofs), v(n_dofs);

      const QGauss<dim>                    quadrature(2);
      FEValues<dim>                        fe_values(space.fe,
                              quadrature,
                              update_values | update_gradients
                                | update_JxW_values);
      const unsigned int                   n = space.fe.n_dofs_per_cell();
      FullMatrix<double>                   cell_matrix(n, n);
      Vector<double>                       cell_rhs(n);
      std::vector<types::global_dof_index> dofs(n);
      for (const auto &cell : space.dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          cell_matrix = 0.;
          cell_rhs    = 0.;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              double source = 0.;
              for (unsigned int j = 0; j < n; ++j)
                source += fe_values.shape_value(j, q)
                          * (f_tilde[dofs[j]] - g_tilde[dofs[j]]);
              for (unsigned int i = 0; i < n; ++i)
                {
                  for (unsigned int j = 0; j < n; ++j)
                    cell_matrix(i, j) += fe_values.shape_grad(i, q)
                                         * fe_values.shape_grad(j, q)
                                         * fe_values.JxW(q);
                  cell_rhs(i)
                    += fe_values.shape_value(i, q) * source * fe_values.JxW(q);
                }
            }
          constraints.distribute_local_to_global(cell_matrix,
                                                 cell_rhs,
                                                 dofs,
                                                 matrix,
                                                 rhs);
        }

      PreconditionSSOR<SparseMatrix<double>> ssor;
      ssor.initialize(matrix, 1.5);
      SolverControl control(10 * n_dofs, 1e-12 * rhs.l2_norm() + 1e-300);
      SolverCG<Vector<double>> cg(control);
      cg.solve(matrix, v, rhs, ssor);
      constraints.distribute(v);

      // Gradient recovery: the volume-weighted mean of the cells' gradients
      // at each vertex (Grajewski found the choice of recovery immaterial).
      {
        std::vector<Point<dim>> corners;
        for (const unsigned int v : GeometryInfo<dim>::vertex_indices())
          corners.push_back(GeometryInfo<dim>::unit_cell_vertex(v));
        const Quadrature<dim> at_vertices(corners);
        FEValues<dim>  corner_values(space.fe, at_vertices, update_gradients);
        Vector<double> weight(n_dofs);
        for (const auto &cell : space.dof_handler.active_cell_iterators())
          {
            corner_values.reinit(cell);
            cell->get_dof_indices(dofs);
            const double volume = cell->measure();
            for (const unsigned int c : GeometryInfo<dim>::vertex_indices())
              {
                Tensor<1, dim> gradient;
                for (unsigned int j = 0; j < n; ++j)
                  gradient += v[dofs[j]] * corner_values.shape_grad(j, c);
                const types::global_dof_index dof
                  = cell->vertex_dof_index(c, 0);
                for (unsigned int d = 0; d < dim; ++d)
                  space.fields[d][dof] += volume * gradient[d];
                weight[dof] += volume;
              }
          }
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            space.fields[d][i] /= weight[i];
      }

      // eq. 5.22-5.23 for every vertex, classical Runge-Kutta in t.
      const VertexHierarchy<dim> boundary(tria);
      std::vector<Point<dim>>    positions = tria.get_vertices();
      const double               h         = 1. / settings.ode_steps;
      std::vector<double>        value;
      for (unsigned int i = 0; i < positions.size(); ++i)
        {
          if (space.dof_of_vertex[i] == numbers::invalid_unsigned_int
              || boundary.is_fixed(i))
            continue;
          auto cell     = space.cell_at_vertex[i];
          auto velocity = [&](const Point<dim> &y, const double t) {
            space.evaluate(y, cell, value);
            Tensor<1, dim> eta;
            for (unsigned int d = 0; d < dim; ++d)
              eta[d] = value[d];
            eta /= t * value[dim] + (1. - t) * value[dim + 1];
            return boundary.admissible_displacement(i, eta);
          };
          Point<dim> y = positions[i];
          for (unsigned int step = 0; step < settings.ode_steps; ++step)
            {
              const double         t  = step * h;
              const Tensor<1, dim> k1 = velocity(y, t);
              const Tensor<1, dim> k2 = velocity(y + 0.5 * h * k1, t + 0.5 * h);
              const Tensor<1, dim> k3 = velocity(y + 0.5 * h * k2, t + 0.5 * h);
              const Tensor<1, dim> k4 = velocity(y + h * k3, t + h);
              y += h / 6. * (k1 + 2. * k2 + 2. * k3 + k4);
            }
          positions[i] = y;
        }
      report.location_fallbacks += space.locator.n_fallbacks();

      // Refuse a tangled result: the mesh stays as it was.
      unsigned int inverted = 0;
      double       worst    = 1.;
      for (const auto &cell : tria.active_cell_iterators())
        {
          std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell> x;
          for (const unsigned int v : cell->vertex_indices())
            x[v] = positions[cell->vertex_index(v)];
          const double q = scaled_jacobian<dim>(x);
          worst          = std::min(worst, q);
          inverted += (q <= 0.);
        }
      if (inverted > 0)
        {
          std::ostringstream message;
          message << "The " << name() << " would invert " << inverted << " of "
                  << tria.n_active_cells()
                  << " cells (smallest scaled Jacobian " << worst
                  << "); the mesh is left undeformed. Use 'Method = "
                     "pde-robust', a smaller 'Robust step ratio', or a larger "
                     "'Smallest cell ratio' in subsection 'Mesh deformation'.";
          throw DeformationError(message.str());
        }
      return positions;
    }

    template class PdeDeformation<2>;
    template class PdeDeformation<3>;
  } // namespace deformation
} // namespace particulate
