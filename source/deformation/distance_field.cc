#include <particulate/deformation/distance_field.h>

#include <limits>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    template <int dim>
    ShapeDistanceField<dim>::ShapeDistanceField(
      std::vector<geometry::PlacedShape> shapes_)
      : shapes(std::move(shapes_))
    {}



    template <int dim>
    double
    ShapeDistanceField<dim>::signed_distance(const Point<dim> &x,
                                             Tensor<1, dim>   *normal) const
    {
      Eigen::Vector3d world = Eigen::Vector3d::Zero();
      for (unsigned int d = 0; d < dim; ++d)
        world[d] = x[d];
      double          best        = std::numeric_limits<double>::infinity();
      Eigen::Vector3d best_normal = Eigen::Vector3d::Zero();
      for (const auto &placed : shapes)
        {
          Eigen::Vector3d n;
          const double    distance
            = placed.shape->signed_distance(placed.pose.to_body(world),
                                            normal ? &n : nullptr);
          if (distance < best)
            {
              best = distance;
              if (normal)
                best_normal = placed.pose.direction_to_world(n);
            }
        }
      if (normal)
        {
          for (unsigned int d = 0; d < dim; ++d)
            (*normal)[d] = best_normal[d];
          const double length = normal->norm();
          if (length > 0.)
            *normal /= length;
        }
      return best;
    }



    template <int dim>
    FunctionDistanceField<dim>::FunctionDistanceField(
      std::function<double(const Point<dim> &)> distance_,
      const double                              h_)
      : distance(std::move(distance_))
      , h(h_)
    {}



    template <int dim>
    double
    FunctionDistanceField<dim>::signed_distance(const Point<dim> &x,
                                                Tensor<1, dim>   *normal) const
    {
      if (normal)
        {
          for (unsigned int d = 0; d < dim; ++d)
            {
              Point<dim> plus = x, minus = x;
              plus[d] += h;
              minus[d] -= h;
              (*normal)[d] = (distance(plus) - distance(minus)) / (2. * h);
            }
          const double length = normal->norm();
          if (length > 0.)
            *normal /= length;
        }
      return distance(x);
    }

    template class ShapeDistanceField<2>;
    template class ShapeDistanceField<3>;
    template class FunctionDistanceField<2>;
    template class FunctionDistanceField<3>;
  } // namespace deformation
} // namespace particulate
