#ifndef particulate_core_parameter_text_h
#define particulate_core_parameter_text_h

#include <string>
#include <vector>

namespace particulate {
  namespace core {
    /**
     * The text of a default value as a case file writes it. The parameter
     * declarations take their defaults from a default-constructed parameter
     * struct through these, so that the struct is the one place where a
     * default is set and a case built in code runs what an empty case file
     * runs.
     */

    /** A number in its shortest exact-enough form: 1e-3, 0.0075, 20. */
    std::string
    number_text(double value);

    /** "true" or "false". */
    std::string
    flag_text(bool value);

    /** A comma-separated list: "1, 3, 4" (empty for an empty list). */
    std::string
    list_text(const std::vector<unsigned int> &values);
  } // namespace core
} // namespace particulate

#endif
