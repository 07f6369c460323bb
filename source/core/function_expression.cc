#include <particulate/core/deal_ii_message.h>
#include <particulate/core/function_expression.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace core {
    namespace {
      /** Discards what is written to a stream while it lives. */
      class SilencedStream
      {
      public:
        explicit SilencedStream(std::ostream &stream)
          : stream(stream)
          , original(stream.rdbuf(sink.rdbuf()))
        {}
        ~SilencedStream()
        {
          stream.rdbuf(original);
        }
        SilencedStream(const SilencedStream &) = delete;
        SilencedStream &
        operator=(const SilencedStream &)
          = delete;

      private:
        std::ostringstream sink;
        std::ostream      &stream;
        std::streambuf    *original;
      };
    } // namespace

    void
    FunctionExpression::declare(dealii::ParameterHandler &prm,
                                const std::string        &name,
                                const std::string        &default_expression,
                                const std::string        &documentation)
    {
      prm.declare_entry(name,
                        default_expression,
                        dealii::Patterns::Anything(),
                        documentation
                          + " One muparser expression per component, separated "
                            "by ';', in the variables x, y, (z) and t. Empty: "
                            "zero.");
      prm.declare_entry(name + " constants",
                        "",
                        dealii::Patterns::Anything(),
                        "Constants used in '" + name
                          + "', as a comma-separated list 'name=value, ...'.");
    }



    void
    FunctionExpression::parse(const dealii::ParameterHandler &prm,
                              const std::string              &name)
    {
      expression = prm.get(name);
      constants  = prm.get(name + " constants");
    }



    template <int dim>
    std::unique_ptr<dealii::Function<dim>>
    FunctionExpression::create(const unsigned int n_components,
                               const std::string &entry_name) const
    {
      if (expression.find_first_not_of(" \t") == std::string::npos)
        return std::make_unique<dealii::Functions::ZeroFunction<dim>>(
          n_components);
      const auto components
        = dealii::Utilities::split_string_list(expression, ';');
      if (components.size() != n_components)
        throw std::runtime_error(
          "The entry '" + entry_name + "' has "
          + std::to_string(components.size()) + " component(s) ('" + expression
          + "') but needs " + std::to_string(n_components)
          + " separated by ';' (one per velocity component in "
          + std::to_string(dim) + "D).");

      // pi is always available, as users of muparser expressions expect
      std::map<std::string, double> constant_map{{"pi", M_PI}, {"Pi", M_PI}};
      for (const auto &item : dealii::Utilities::split_string_list(constants))
        {
          const auto pair = dealii::Utilities::split_string_list(item, '=');
          if (pair.size() != 2)
            throw std::runtime_error("The entry '" + entry_name
                                     + " constants' must look like 'a=1, b=2'; "
                                       "cannot read '"
                                     + item + "'.");
          try
            {
              constant_map[pair[0]] = std::stod(pair[1]);
            }
          catch (const std::exception &)
            {
              throw std::runtime_error(
                "The entry '" + entry_name + " constants' gives '" + pair[1]
                + "' for '" + pair[0] + "', which is not a number.");
            }
        }

      const std::string variables
        = dim == 2 ? "x,y,t" : (dim == 3 ? "x,y,z,t" : "x,t");
      for (const auto &[name, value] : constant_map)
        for (const std::string &variable :
             dealii::Utilities::split_string_list(variables, ','))
          if (name == variable)
            throw std::runtime_error(
              "The entry '" + entry_name + " constants' declares '" + name
              + "', which is one of the variables " + variables
              + "; give the constant another name.");
      auto function
        = std::make_unique<dealii::FunctionParser<dim>>(n_components);
      try
        {
          // deal.II's FunctionParser prints muparser's report of a bad
          // expression to std::cerr before it throws; the exception carries
          // the same facts, given below with the entry's name
          const SilencedStream quiet(std::cerr);
          function->initialize(variables,
                               components,
                               constant_map,
                               /*time_dependent=*/true);
          // evaluate once so that an unknown symbol is reported here, with
          // the entry's name, and not in the middle of the run
          dealii::Vector<double> value(n_components);
          function->vector_value(dealii::Point<dim>(), value);
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw std::runtime_error(
            "Cannot evaluate the entry '" + entry_name + "' = '" + expression
            + "': " + one_line_explanation(e) + " Use the variables "
            + variables + " and the constants you declare.");
        }
      catch (...)
        {
          // muparser's own errors (e.g. a constant's name it cannot define)
          // are not deal.II exceptions
          throw std::runtime_error(
            "Cannot evaluate the entry '" + entry_name + "' = '" + expression
            + "' with the constants of '" + entry_name
            + " constants'. Use the variables " + variables
            + " and constants named like C or U_0.");
        }
      return function;
    }

    template std::unique_ptr<dealii::Function<2>>
    FunctionExpression::create<2>(const unsigned int,
                                  const std::string &) const;
    template std::unique_ptr<dealii::Function<3>>
    FunctionExpression::create<3>(const unsigned int,
                                  const std::string &) const;
  } // namespace core
} // namespace particulate
