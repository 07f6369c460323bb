#ifndef particulate_deformation_distance_field_h
#define particulate_deformation_distance_field_h

#include <particulate/geometry/point_containment.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <functional>
#include <vector>

namespace particulate {
  namespace deformation {
    /**
     * What every deformation method adapts the mesh to: the signed distance
     * to the nearest body surface (negative inside a body) and its gradient,
     * the outward normal of that surface (thesis §5.7, figure 5.5).
     */
    template <int dim>
    class DistanceField
    {
    public:
      virtual ~DistanceField() = default;

      /**
       * Signed distance from @p x to the nearest surface [m]; @p normal, if
       * not null, receives the outward unit normal there.
       */
      virtual double
      signed_distance(const dealii::Point<dim> &x,
                      dealii::Tensor<1, dim>   *normal = nullptr) const = 0;
    };

    /**
     * The distance to a set of placed geometry shapes (analytic shapes or
     * CGAL distance maps), the minimum over the shapes. In 2D a point (x, y)
     * is the point (x, y, 0) of the shapes' 3D frame, so a 2D disk is a
     * long cylinder along z, as in the fbm module.
     */
    template <int dim>
    class ShapeDistanceField : public DistanceField<dim>
    {
    public:
      /** The shapes are not owned and must outlive this object. */
      explicit ShapeDistanceField(std::vector<geometry::PlacedShape> shapes);

      double
      signed_distance(const dealii::Point<dim> &x,
                      dealii::Tensor<1, dim> *normal = nullptr) const override;

    private:
      std::vector<geometry::PlacedShape> shapes;
    };

    /**
     * A distance field given by a function, e.g. the distance to a circle of
     * the thesis's test problem (§5.6). Without a gradient function the
     * normal is taken by central differences of step @p h.
     */
    template <int dim>
    class FunctionDistanceField : public DistanceField<dim>
    {
    public:
      FunctionDistanceField(
        std::function<double(const dealii::Point<dim> &)> distance,
        const double                                      h = 1e-7);

      double
      signed_distance(const dealii::Point<dim> &x,
                      dealii::Tensor<1, dim> *normal = nullptr) const override;

    private:
      std::function<double(const dealii::Point<dim> &)> distance;
      double                                            h;
    };
  } // namespace deformation
} // namespace particulate

#endif
