#ifndef particulate_deformation_carried_zone_realignment_h
#define particulate_deformation_carried_zone_realignment_h

#include <particulate/deformation/distance_field.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <functional>
#include <vector>

namespace particulate {
  namespace deformation {
    /**
     * One body's carried zone at a fresh start of `Moving bodies = carry
     * neighbourhood`: where its vertices are (@p centre, their mean
     * position on the carried mesh) and the displacement the fresh mesh
     * carries it by (@p residual).
     */
    template <int dim>
    struct RealignedZone
    {
      dealii::Point<dim>     centre;
      dealii::Tensor<1, dim> residual;
    };

    /**
     * A carried zone moves rigidly with its body, so each body keeps its
     * place among the vertices there. Starting afresh from the undeformed
     * mesh would put the body elsewhere among them: another set of covered
     * velocity nodes, another effective size, a jump of the drag. Where
     * the undeformed mesh repeats itself along the body's path (a uniform
     * column of cells), a fresh start can keep that place instead: the
     * zone carried by R (the displacement of its vertices from their
     * undeformed positions) is the zone around a translate u + S of the
     * undeformed mesh, S the lattice translation nearest to R, carried by
     * the residual R - S, less than half a cell.
     *
     * Returns one zone per distinct displacement of the vertices inside
     * the surfaces @p distance on the mesh at @p carried (undeformed
     * positions @p undeformed). With @p step (the displacement by which
     * the fresh mesh is about to be carried, as a function of the place)
     * S is the lattice translation nearest to R plus the step at the
     * zone's centre instead, so that the zone ends the step within half a
     * cell of the lattice: a fresh start carried over a step towards a
     * wall then presses the cells in between by at most half a cell more
     * than the step. A zone's residual is R - S when every
     * undeformed vertex within @p zone_width of the surface (counted as
     * carried by R) has a twin shifted by S, so that the fresh zone's
     * vertices lie where the carried ones were; 0 (an ordinary fresh
     * start) otherwise. Returns no zones, an ordinary fresh start
     * everywhere, when the vertices inside the surfaces do not move
     * rigidly (a body that turns, whose zone turns with it).
     */
    template <int dim>
    std::vector<RealignedZone<dim>>
    realigned_zones(
      const std::vector<dealii::Point<dim>> &carried,
      const std::vector<dealii::Point<dim>> &undeformed,
      const DistanceField<dim>              &distance,
      const double                           zone_width,
      const std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &)>
        &step
      = {});

    /** The residual of the zone whose centre is nearest to @p x; 0 when
     *  there are none. */
    template <int dim>
    dealii::Tensor<1, dim>
    residual_near(const std::vector<RealignedZone<dim>> &zones,
                  const dealii::Point<dim>              &x);
  } // namespace deformation
} // namespace particulate

#endif
