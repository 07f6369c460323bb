#include "uniform_grids.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace particulate {
  namespace cuda {
    namespace detail {
      namespace {
        /** Cell layout of a grid plus the safety margin used at insertion. */
        struct Frame
        {
          int    n[3];
          float  origin[3];
          float  inv_h[3];
          double h_query[3]; // cell edge as the float query sees it
          double eps_cells;  // margin in cell units
        };

        double
        max_abs(const Box &b)
        {
          double m = 0.;
          for (int a = 0; a < 3; ++a)
            m = std::max({m, std::abs(b.lo[a]), std::abs(b.hi[a])});
          return m;
        }

        /**
         * Lays a grid of cubic cells of edge about h over the box, with at
         * most max_per_axis cells per axis and max_cells in all, centred on
         * the box and leaving at least a thousandth of a cell free on each
         * side.
         */
        Frame
        make_frame(const Box        &box,
                   double            h,
                   const int         max_per_axis,
                   const std::size_t max_cells)
        {
          double ext[3], ext_max = 0.;
          for (int a = 0; a < 3; ++a)
            {
              ext[a]  = box.hi[a] - box.lo[a];
              ext_max = std::max(ext_max, ext[a]);
            }
          if (!(ext_max > 0.))
            ext_max = std::max(1e-3 * max_abs(box), 1e-30);
          if (!(h > 0.) || !std::isfinite(h))
            h = ext_max / 16.;
          h = std::max(h, ext_max / max_per_axis);

          Frame f;
          // Float rounding of a query coordinate c is about 6e-8 |c|; a
          // margin sixteen times that, plus 1e-3 cell, never lets a point
          // that touches an object fall into a cell that does not list it.
          for (;;)
            {
              f.eps_cells       = 1e-3 + 1e-6 * max_abs(box) / h;
              std::size_t total = 1;
              for (int a = 0; a < 3; ++a)
                {
                  f.n[a] = std::max(1,
                                    static_cast<int>(std::ceil(
                                      ext[a] / h + 4. * f.eps_cells)));
                  total *= static_cast<std::size_t>(f.n[a]);
                }
              if (total <= max_cells)
                break;
              h *= 1.25;
            }
          for (int a = 0; a < 3; ++a)
            {
              f.origin[a]
                = static_cast<float>(box.lo[a] - 0.5 * (f.n[a] * h - ext[a]));
              f.inv_h[a]   = static_cast<float>(1. / h);
              f.h_query[a] = 1. / static_cast<double>(f.inv_h[a]);
            }
          return f;
        }

        /**
         * Cells [i0, i1] along axis a that the interval [lo, hi] may touch,
         * widened by the margin; false if none.
         */
        bool
        cell_range(const Frame &f,
                   const int    a,
                   const double lo,
                   const double hi,
                   int         &i0,
                   int         &i1)
        {
          const double o  = f.origin[a];
          const double u0 = (lo - o) * f.inv_h[a] - f.eps_cells;
          const double u1 = (hi - o) * f.inv_h[a] + f.eps_cells;
          if (u1 < 0. || u0 >= f.n[a])
            return false;
          i0 = std::max(0, static_cast<int>(std::floor(u0)));
          i1 = std::min(f.n[a] - 1, static_cast<int>(std::floor(u1)));
          return i0 <= i1;
        }
      } // namespace

      SphereGrid
      build_sphere_grid(const InnerSphereData &s)
      {
        const std::size_t ns = s.r.size();
        SphereGrid        g;
        for (int a = 0; a < 3; ++a)
          {
            g.box.lo[a] = HUGE_VAL;
            g.box.hi[a] = -HUGE_VAL;
          }
        double r_sum = 0.;
        for (std::size_t q = 0; q < ns; ++q)
          {
            const double c[3] = {s.cx[q], s.cy[q], s.cz[q]};
            for (int a = 0; a < 3; ++a)
              {
                g.box.lo[a] = std::min(g.box.lo[a], c[a] - s.r[q]);
                g.box.hi[a] = std::max(g.box.hi[a], c[a] + s.r[q]);
              }
            r_sum += s.r[q];
          }
        // Cell edge about one sphere diameter: a sphere then touches at most
        // 8 cells and a cell is touched by a handful of spheres.
        const Frame f
          = make_frame(g.box, 2. * r_sum / ns, 1024, std::size_t(1) << 22);
        for (int a = 0; a < 3; ++a)
          {
            g.n[a]      = f.n[a];
            g.origin[a] = f.origin[a];
            g.inv_h[a]  = f.inv_h[a];
          }
        const std::size_t n_cells
          = std::size_t(f.n[0]) * std::size_t(f.n[1]) * std::size_t(f.n[2]);

        // Two passes (count, then fill) give a compact CSR layout.
        std::vector<int> count(n_cells + 1, 0);
        for (int pass = 0; pass < 2; ++pass)
          {
            if (pass == 1)
              {
                g.cell_start.assign(n_cells + 1, 0);
                for (std::size_t c = 0; c < n_cells; ++c)
                  g.cell_start[c + 1] = g.cell_start[c] + count[c];
                if (g.cell_start[n_cells] < 0)
                  throw std::invalid_argument(
                    "add_inner_spheres: the sphere grid would hold more than "
                    "2^31 entries; use fewer or smaller spheres.");
                g.entries.resize(
                  static_cast<std::size_t>(g.cell_start[n_cells]));
                std::fill(count.begin(), count.end(), 0);
              }
            for (std::size_t q = 0; q < ns; ++q)
              {
                const double c[3] = {s.cx[q], s.cy[q], s.cz[q]};
                const double r    = s.r[q];
                int          i0[3], i1[3];
                bool         any = true;
                for (int a = 0; a < 3; ++a)
                  any
                    = any && cell_range(f, a, c[a] - r, c[a] + r, i0[a], i1[a]);
                if (!any)
                  continue;
                const double margin = f.eps_cells * f.h_query[0];
                const double reach2 = (r + margin) * (r + margin);
                for (int k = i0[2]; k <= i1[2]; ++k)
                  for (int j = i0[1]; j <= i1[1]; ++j)
                    for (int i = i0[0]; i <= i1[0]; ++i)
                      {
                        // Keep only cells the sphere really touches.
                        const int idx[3] = {i, j, k};
                        double    d2     = 0.;
                        for (int a = 0; a < 3; ++a)
                          {
                            const double lo
                              = f.origin[a] + idx[a] * f.h_query[a];
                            const double hi = lo + f.h_query[a];
                            const double e
                              = std::max({lo - c[a], 0., c[a] - hi});
                            d2 += e * e;
                          }
                        if (d2 > reach2)
                          continue;
                        const std::size_t cell
                          = i
                            + std::size_t(f.n[0])
                                * (j + std::size_t(f.n[1]) * k);
                        if (pass == 1)
                          {
                            const float rf = s.r[q];
                            g.entries[g.cell_start[cell] + count[cell]]
                              = SphereEntry{s.cx[q], s.cy[q], s.cz[q], rf * rf};
                          }
                        ++count[cell];
                      }
              }
          }
        // Nearest spheres first: a point inside the body usually lies in the
        // sphere closest to its cell's centre, so the scan stops early. Any
        // order gives the same answer; this one only makes it faster.
        for (std::size_t cell = 0; cell < n_cells; ++cell)
          {
            const int i = static_cast<int>(cell % std::size_t(f.n[0]));
            const int j = static_cast<int>((cell / std::size_t(f.n[0]))
                                           % std::size_t(f.n[1]));
            const int k = static_cast<int>(
              cell / (std::size_t(f.n[0]) * std::size_t(f.n[1])));
            const double cc[3] = {f.origin[0] + (i + 0.5) * f.h_query[0],
                                  f.origin[1] + (j + 0.5) * f.h_query[1],
                                  f.origin[2] + (k + 0.5) * f.h_query[2]};
            auto         key   = [&](const SphereEntry &e) {
              const double dx = e.x - cc[0], dy = e.y - cc[1], dz = e.z - cc[2];
              // Depth of the cell centre inside the sphere, larger first.
              return std::sqrt(double(e.r2))
                     - std::sqrt(dx * dx + dy * dy + dz * dz);
            };
            std::stable_sort(g.entries.begin() + g.cell_start[cell],
                             g.entries.begin() + g.cell_start[cell + 1],
                             [&](const SphereEntry &a, const SphereEntry &b) {
                               return key(a) > key(b);
                             });
          }
        return g;
      }

      void
      build_scene_grid(const BodyInstance           *bodies,
                       const std::size_t             m,
                       const std::vector<ShapeView> &shape_views,
                       const std::vector<Box>       &shape_boxes,
                       SceneGrid                    &g)
      {
        g.n_direct
          = m <= std::size_t(max_direct_bodies) ? static_cast<int>(m) : 0;
        g.bodies.resize(m);
        // Scratch and results reuse the capacity of the previous call: no
        // allocation (and no fresh page) per time step.
        std::vector<Box>    &world = g.world;
        std::vector<double> &pads  = g.pads;
        world.resize(m);
        pads.resize(m);
        Box all;
        for (int a = 0; a < 3; ++a)
          {
            all.lo[a] = HUGE_VAL;
            all.hi[a] = -HUGE_VAL;
          }
        double h_sum = 0.;
        for (std::size_t b = 0; b < m; ++b)
          {
            const BodyInstance &in = bodies[b];
            BodyView           &v  = g.bodies[b];
            std::copy(in.R, in.R + 9, v.R);
            std::copy(in.t, in.t + 3, v.t);
            v.shape = shape_views[static_cast<std::size_t>(in.shape)];

            // World box of the rotated shape box: x_w = R x_b + t.
            const Box &sb = shape_boxes[static_cast<std::size_t>(in.shape)];
            Box       &wb = world[b];
            for (int a = 0; a < 3; ++a)
              {
                wb.lo[a] = HUGE_VAL;
                wb.hi[a] = -HUGE_VAL;
              }
            for (int corner = 0; corner < 8; ++corner)
              {
                const double xb[3] = {(corner & 1) ? sb.hi[0] : sb.lo[0],
                                      (corner & 2) ? sb.hi[1] : sb.lo[1],
                                      (corner & 4) ? sb.hi[2] : sb.lo[2]};
                for (int a = 0; a < 3; ++a)
                  {
                    const double xw = double(in.R[3 * a]) * xb[0]
                                      + double(in.R[3 * a + 1]) * xb[1]
                                      + double(in.R[3 * a + 2]) * xb[2]
                                      + in.t[a];
                    wb.lo[a] = std::min(wb.lo[a], xw);
                    wb.hi[a] = std::max(wb.hi[a], xw);
                  }
              }
            // The query rounds x - t and R^T(x - t) in float: widen the box
            // by far more than that error.
            double diag2 = 0.;
            for (int a = 0; a < 3; ++a)
              diag2 += (sb.hi[a] - sb.lo[a]) * (sb.hi[a] - sb.lo[a]);
            const double pad
              = 1e-5 * (std::sqrt(diag2) + max_abs(wb) + max_abs(sb));
            pads[b]    = pad;
            double ext = 0.;
            for (int a = 0; a < 3; ++a)
              {
                wb.lo[a] -= pad;
                wb.hi[a] += pad;
                all.lo[a] = std::min(all.lo[a], wb.lo[a]);
                all.hi[a] = std::max(all.hi[a], wb.hi[a]);
                ext       = std::max(ext, wb.hi[a] - wb.lo[a]);
              }
            h_sum += ext;
          }

        if (m == 0)
          {
            // An empty scene: one empty cell, every point outside.
            for (int a = 0; a < 3; ++a)
              {
                g.n[a]      = 1;
                g.origin[a] = 0.f;
                g.inv_h[a]  = 1.f;
              }
            g.cell_start.assign(2, 0);
            g.body_ids.clear();
            return;
          }

        // Cell edge about a quarter of the mean body size: a point then
        // meets one or two candidate bodies, whatever their number, and a
        // body spans only a few cells per axis.
        const Frame f
          = make_frame(all, 0.25 * h_sum / m, 256, std::size_t(1) << 18);
        for (int a = 0; a < 3; ++a)
          {
            g.n[a]      = f.n[a];
            g.origin[a] = f.origin[a];
            g.inv_h[a]  = f.inv_h[a];
          }
        const std::size_t n_cells
          = std::size_t(f.n[0]) * std::size_t(f.n[1]) * std::size_t(f.n[2]);
        // One pass over the bodies collects (cell, body) pairs, a stable
        // counting sort by cell then lists every cell's bodies in increasing
        // order.
        std::vector<std::pair<int, int>> &pairs = g.pairs;
        pairs.clear();
        const double half_diag = 0.5
                                 * std::sqrt(f.h_query[0] * f.h_query[0]
                                             + f.h_query[1] * f.h_query[1]
                                             + f.h_query[2] * f.h_query[2]);
        for (std::size_t b = 0; b < m; ++b)
          {
            int  i0[3], i1[3];
            bool any = true;
            for (int a = 0; a < 3; ++a)
              any = any
                    && cell_range(f,
                                  a,
                                  world[b].lo[a],
                                  world[b].hi[a],
                                  i0[a],
                                  i1[a]);
            if (!any)
              continue;
            // The world box of a rotated body is loose; test cells against
            // the body's own (oriented) box, widened by a cell's half
            // diagonal plus the padding of the world box. The body-frame
            // cell centre is affine in (i, j, k): x_b = base + i e_x + j e_y
            // + k e_z, with e_a = R^T h e_a.
            const BodyInstance &in = bodies[b];
            const Box   &sb = shape_boxes[static_cast<std::size_t>(in.shape)];
            const double reach
              = half_diag + pads[b] + f.eps_cells * f.h_query[0];
            const double c0[3]
              = {f.origin[0] + (i0[0] + 0.5) * f.h_query[0] - in.t[0],
                 f.origin[1] + (i0[1] + 0.5) * f.h_query[1] - in.t[1],
                 f.origin[2] + (i0[2] + 0.5) * f.h_query[2] - in.t[2]};
            double base[3], e[3][3];
            for (int a = 0; a < 3; ++a)
              {
                base[a] = double(in.R[a]) * c0[0] + double(in.R[3 + a]) * c0[1]
                          + double(in.R[6 + a]) * c0[2];
                for (int w = 0; w < 3; ++w)
                  e[w][a] = double(in.R[3 * w + a]) * f.h_query[w];
              }
            // A cell is kept when its centre lies in the body's box widened
            // by `reach` on every side (a superset of the cells whose
            // bounding sphere meets the box). Along a row of cells the
            // centre moves linearly, so each row's kept cells form one
            // interval, found per axis in O(1) instead of cell by cell.
            // (std::ceil/std::floor are library calls on baseline x86-64;
            // on values clamped to [-1, n_i + 1] a truncation does.)
            const int    n_i        = i1[0] - i0[0];
            const double t_lo_clamp = -1., t_hi_clamp = n_i + 1.;
            double       inv_u[3];
            bool         moves[3];
            for (int a = 0; a < 3; ++a)
              {
                moves[a] = std::abs(e[0][a]) >= 1e-12 * f.h_query[0];
                inv_u[a] = moves[a] ? 1. / e[0][a] : 0.;
              }
            for (int k = i0[2]; k <= i1[2]; ++k)
              for (int j = i0[1]; j <= i1[1]; ++j)
                {
                  const int dj = j - i0[1], dk = k - i0[2];
                  int       t_min = 0, t_max = n_i;
                  for (int a = 0; a < 3 && t_min <= t_max; ++a)
                    {
                      const double x0 = base[a] + dj * e[1][a] + dk * e[2][a];
                      const double lo = sb.lo[a] - reach, hi = sb.hi[a] + reach;
                      if (!moves[a])
                        {
                          if (x0 < lo || x0 > hi)
                            t_max = -1;
                          continue;
                        }
                      double ta = (lo - x0) * inv_u[a],
                             tb = (hi - x0) * inv_u[a];
                      if (ta > tb)
                        std::swap(ta, tb);
                      ta
                        = std::min(std::max(ta - 1e-9, t_lo_clamp), t_hi_clamp);
                      tb
                        = std::min(std::max(tb + 1e-9, t_lo_clamp), t_hi_clamp);
                      int ca = static_cast<int>(ta); // ceil(ta)
                      if (ca < ta)
                        ++ca;
                      int fb = static_cast<int>(tb); // floor(tb)
                      if (fb > tb)
                        --fb;
                      t_min = std::max(t_min, ca);
                      t_max = std::min(t_max, fb);
                    }
                  for (int t = t_min; t <= t_max; ++t)
                    pairs.emplace_back(i0[0] + t + f.n[0] * (j + f.n[1] * k),
                                       static_cast<int>(b));
                }
          }
        g.cell_start.assign(n_cells + 1, 0);
        for (const auto &pr : pairs)
          ++g.cell_start[static_cast<std::size_t>(pr.first) + 1];
        for (std::size_t c = 0; c < n_cells; ++c)
          g.cell_start[c + 1] += g.cell_start[c];
        g.body_ids.resize(pairs.size());
        std::vector<int> &fill = g.fill;
        fill.assign(g.cell_start.begin(), g.cell_start.end() - 1);
        for (const auto &pr : pairs)
          g.body_ids[static_cast<std::size_t>(fill[pr.first]++)] = pr.second;
      }

      SceneView
      make_scene_view(const SceneGrid &g,
                      const BodyView  *bodies,
                      const int       *cell_start,
                      const int       *body_ids)
      {
        SceneView v{};
        for (int a = 0; a < 3; ++a)
          {
            v.n[a]      = g.n[a];
            v.origin[a] = g.origin[a];
            v.inv_h[a]  = g.inv_h[a];
          }
        v.n_direct   = g.n_direct;
        v.cell_start = cell_start;
        v.body_ids   = body_ids;
        v.bodies     = bodies;
        for (int b = 0; b < g.n_direct; ++b)
          v.direct[b] = g.bodies[static_cast<std::size_t>(b)];
        return v;
      }
    } // namespace detail
  }   // namespace cuda
} // namespace particulate
