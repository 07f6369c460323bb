#ifndef particulate_core_deal_ii_message_h
#define particulate_core_deal_ii_message_h

#include <deal.II/base/exceptions.h>

#include <string>

namespace particulate {
  namespace core {
    /**
     * What a deal.II exception says about the problem (its "additional
     * information", without the file, line and stack trace of the
     * library), on one line: for a message to a user.
     */
    std::string
    one_line_explanation(const dealii::ExceptionBase &exception);
  } // namespace core
} // namespace particulate

#endif
