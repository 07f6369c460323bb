#ifndef particulate_core_function_expression_h
#define particulate_core_function_expression_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

namespace particulate {
  namespace core {
    /**
     * A user-given function of space and time, e.g. a parabolic inflow
     * profile. In the `.prm` it is one entry holding one muparser expression
     * per component separated by ';', in the variables x, y (z) and t, plus an
     * optional entry of constants:
     *
     *   set Inflow velocity = 4*Um*y*(H-y)/H^2; 0
     *   set Inflow velocity constants = Um=0.3, H=0.41
     *
     * The number of components is checked when the function is created, so a
     * missing component is reported with the entry's name.
     */
    struct FunctionExpression
    {
      std::string expression;
      std::string constants;

      /**
       * Declare the entries `<name>` and `<name> constants` in the current
       * subsection of @p prm.
       */
      static void
      declare(dealii::ParameterHandler &prm,
              const std::string        &name,
              const std::string        &default_expression,
              const std::string        &documentation);

      /** Read both entries back. */
      void
      parse(const dealii::ParameterHandler &prm, const std::string &name);

      /**
       * Build the function with @p n_components components in dimension
       * @p dim. Throws std::runtime_error naming @p entry_name if the
       * expression does not parse or has the wrong number of components.
       */
      template <int dim>
      std::unique_ptr<dealii::Function<dim>>
      create(const unsigned int n_components,
             const std::string &entry_name) const;
    };
  } // namespace core
} // namespace particulate

#endif
